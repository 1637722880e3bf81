// Host and Origin checks (request_guard.hpp).
#include "request_guard.hpp"

#include <algorithm>
#include <cctype>

namespace feel::studio {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
    return out;
}

std::string shown(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 100)) out += (static_cast<unsigned char>(c) < 0x20 || c == '"') ? '?' : c;
    return "\"" + out + "\"";
}

}  // namespace

RequestGuard::RequestGuard(std::string_view listen_host, uint16_t port) {
    const std::string p = ":" + std::to_string(port);
    hosts_ = {"127.0.0.1" + p, "localhost" + p, "[::1]" + p};
    std::string h = lower(listen_host);
    if (h.find(':') != std::string::npos && h.front() != '[') h = "[" + h + "]";  // IPv6
    if (h != "0.0.0.0" && h != "[::]" && std::find(hosts_.begin(), hosts_.end(), h + p) == hosts_.end()) {
        hosts_.push_back(h + p);
    }
}

std::optional<std::string> RequestGuard::refusal(std::string_view host,
                                                 std::optional<std::string_view> origin) const {
    const std::string h = lower(host);
    if (std::find(hosts_.begin(), hosts_.end(), h) == hosts_.end()) {
        std::string allowed;
        for (const std::string& a : hosts_) allowed += (allowed.empty() ? "" : ", ") + a;
        return "Host " + shown(host) + " is not this server (allowed: " + allowed +
               "); refused to stop DNS rebinding";
    }
    if (origin) {
        const std::string o = lower(*origin);
        const bool ok = o.starts_with("http://") &&
                        std::find(hosts_.begin(), hosts_.end(), o.substr(7)) != hosts_.end();
        if (!ok) {
            return "Origin " + shown(*origin) + " is not this server's page (allowed: http:// and " +
                   hosts_.front() + " or another of its names); refused so other sites cannot drive the Studio";
        }
    }
    return std::nullopt;
}

}  // namespace feel::studio
