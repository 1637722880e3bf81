// feel::studio — who may talk to the Studio's server.
//
// The server listens on loopback by default, but that alone does not stop a web page
// from another site, open in the same browser, from reaching it: the page can send
// requests to 127.0.0.1 (cross-site requests, WebSocket connections), and through DNS
// rebinding a hostile name can even come to resolve to 127.0.0.1 and count as "same
// origin". So every HTTP request and every WebSocket upgrade is checked:
//   * Host must be one of the server's own names with its port (127.0.0.1:P,
//     localhost:P, [::1]:P, and the --listen address): a rebound name fails here;
//   * Origin, when present, must be http:// plus one of those names: another site's page
//     fails here. Programs that are not browsers send no Origin, and may connect.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace feel::studio {

class RequestGuard {
public:
    // `listen_host`: the address the server listens on ("127.0.0.1" by default).
    RequestGuard(std::string_view listen_host, uint16_t port);

    // Why the request is refused, or nothing when it may pass. `origin` is nullopt when
    // the request has no Origin header.
    [[nodiscard]] std::optional<std::string> refusal(std::string_view host,
                                                     std::optional<std::string_view> origin) const;
    [[nodiscard]] const std::vector<std::string>& hosts() const noexcept { return hosts_; }

private:
    std::vector<std::string> hosts_;  // "127.0.0.1:8750", ...
};

}  // namespace feel::studio
