// Mapping device answers and host checks onto Status: one place, so that every error of
// the host API reads the same way whether the host or the device refused.
#include "host_errors.hpp"

#include <cstring>
#include <mutex>
#include <string>
#include <unordered_set>

namespace feel::host {

std::string_view error_kind_name(ErrorKind kind) noexcept {
    switch (kind) {
        case ErrorKind::ok: return "ok";
        case ErrorKind::invalid_parameter: return "invalid parameter";
        case ErrorKind::device_full: return "device full";
        case ErrorKind::not_supported: return "not supported";
        case ErrorKind::invalid_handle: return "invalid handle";
        case ErrorKind::disconnected: return "disconnected";
        case ErrorKind::timeout: return "timeout";
        case ErrorKind::protocol: return "protocol error";
    }
    return "unknown error";
}

const char* intern_rule(std::string_view rule) {
    // Bounded: a hostile device could send a new sentence with every answer.
    constexpr std::size_t kMaxRules = 1024;
    static std::mutex mu;
    static std::unordered_set<std::string> rules;
    if (rule.empty()) return "";
    std::lock_guard lock(mu);
    auto it = rules.find(std::string(rule));
    if (it != rules.end()) return it->c_str();
    if (rules.size() >= kMaxRules) return "refused by the device";
    return rules.emplace(rule).first->c_str();
}

ErrorKind kind_of(ErrorCode code) noexcept {
    switch (code) {
        case ErrorCode::ok: return ErrorKind::ok;
        case ErrorCode::invalid_parameter: return ErrorKind::invalid_parameter;
        case ErrorCode::device_full: return ErrorKind::device_full;
        case ErrorCode::not_supported: return ErrorKind::not_supported;
        case ErrorCode::invalid_handle: return ErrorKind::invalid_handle;
    }
    return ErrorKind::protocol;
}

Error error_from_status(const protocol::CommandAnswer& status) {
    Error e;
    e.code = status.code;
    const std::size_t n = strnlen(status.field, sizeof status.field);
    const std::size_t m = std::min(n, sizeof e.field - 1);
    std::memcpy(e.field, status.field, m);
    e.field[m] = '\0';
    e.has_range = status.has_range;
    e.value = status.value;
    e.allowed = Range{status.allowed_min, status.allowed_max};
    e.rule = status.has_range ? "is out of range"
                              : intern_rule(std::string_view(status.rule, strnlen(status.rule, sizeof status.rule)));
    if (!status.has_range && e.rule[0] == '\0') e.rule = "refused by the device";
    return e;
}

Status status_from_error(const Error& error, std::string_view what) {
    if (error.ok()) return Status::success();
    return Status::failure(kind_of(error.code), std::string(what) + ": " + error.message(), error);
}

Status status_from_command(const protocol::CommandAnswer& status, std::string_view what) {
    if (status.code == ErrorCode::ok) return Status::success();
    return status_from_error(error_from_status(status), what);
}

}  // namespace feel::host
