// Error values: building them without allocation, and formatting them for people.
#include "feel/status.hpp"

#include <algorithm>
#include <cstdio>

namespace feel {

std::string_view error_code_name(ErrorCode c) noexcept {
    switch (c) {
        case ErrorCode::ok: return "ok";
        case ErrorCode::invalid_parameter: return "invalid parameter";
        case ErrorCode::device_full: return "device full";
        case ErrorCode::not_supported: return "not supported";
        case ErrorCode::invalid_handle: return "invalid handle";
    }
    return "unknown error";
}

namespace {
void copy_field(char (&dst)[48], std::string_view src) noexcept {
    const size_t n = std::min(src.size(), sizeof(dst) - 1);
    std::copy_n(src.data(), n, dst);
    dst[n] = '\0';
}
}  // namespace

Error Error::out_of_range(std::string_view field, int64_t value, Range allowed) noexcept {
    Error e;
    e.code = ErrorCode::invalid_parameter;
    copy_field(e.field, field);
    e.value = value;
    e.allowed = allowed;
    e.has_range = true;
    e.rule = "is out of range";
    return e;
}

Error Error::invalid(std::string_view field, const char* rule) noexcept {
    return of(ErrorCode::invalid_parameter, field, rule);
}

Error Error::of(ErrorCode code, std::string_view field, const char* rule) noexcept {
    Error e;
    e.code = code;
    copy_field(e.field, field);
    e.rule = rule;
    return e;
}

std::string Error::message() const {
    if (ok()) return "ok";
    std::string out;
    if (field[0] != '\0') out += field;
    if (has_range) {
        char buf[128];
        std::snprintf(buf, sizeof buf, " = %lld is out of range (allowed %lld..%lld)",
                      static_cast<long long>(value), static_cast<long long>(allowed.min),
                      static_cast<long long>(allowed.max));
        out += buf;
    } else {
        if (!out.empty()) out += ": ";
        out += rule;
    }
    return out;
}

}  // namespace feel
