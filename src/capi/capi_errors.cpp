// The thread's last error (feel_last_error, feel_last_error_message, feel_error_name).
#include <algorithm>
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"

namespace feel::capi {
namespace {

// Long enough for any message the host API builds (a sensation file's error names the
// file, the sensation, the field and the range).
constexpr std::size_t kMessageCapacity = 2048;

struct LastError {
    int code = FEEL_OK;
    char message[kMessageCapacity] = {};
};

thread_local LastError last_error;

// ErrorKind and the FEEL_ERROR_* codes are the same numbers.
static_assert(static_cast<int>(host::ErrorKind::ok) == FEEL_OK);
static_assert(static_cast<int>(host::ErrorKind::invalid_parameter) == FEEL_ERROR_INVALID_PARAMETER);
static_assert(static_cast<int>(host::ErrorKind::device_full) == FEEL_ERROR_DEVICE_FULL);
static_assert(static_cast<int>(host::ErrorKind::not_supported) == FEEL_ERROR_NOT_SUPPORTED);
static_assert(static_cast<int>(host::ErrorKind::invalid_handle) == FEEL_ERROR_INVALID_HANDLE);
static_assert(static_cast<int>(host::ErrorKind::disconnected) == FEEL_ERROR_DISCONNECTED);
static_assert(static_cast<int>(host::ErrorKind::timeout) == FEEL_ERROR_TIMEOUT);
static_assert(static_cast<int>(host::ErrorKind::protocol) == FEEL_ERROR_PROTOCOL);

std::size_t append(char* dst, std::size_t at, std::string_view s) noexcept {
    const std::size_t n = std::min(s.size(), kMessageCapacity - 1 - at);
    std::memcpy(dst + at, s.data(), n);
    return at + n;
}

}  // namespace

void set_error(int code, std::string_view message, std::string_view prefix) noexcept {
    LastError& e = last_error;
    e.code = code;
    std::size_t at = 0;
    if (!prefix.empty()) {
        at = append(e.message, at, prefix);
        at = append(e.message, at, ": ");
    }
    at = append(e.message, at, message);
    e.message[at] = '\0';
}

int fail(const host::Status& status) noexcept {
    const int code = static_cast<int>(status.kind);
    if (code == FEEL_OK) {
        // A Status that says ok is not an error; a caller asking to fail with it is a bug here.
        return fail(FEEL_ERROR_INTERNAL, "an error was reported without a cause");
    }
    set_error(code, status.message.empty() ? host::error_kind_name(status.kind) : std::string_view(status.message));
    return code;
}

int null_argument(const char* function, const char* what) noexcept {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s is NULL", what);
    set_error(FEEL_ERROR_INVALID_PARAMETER, buf, function);
    return FEEL_ERROR_INVALID_PARAMETER;
}

int out_of_range(const char* function, const char* name, int64_t value, int64_t min, int64_t max) noexcept {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s = %lld is out of range (allowed %lld..%lld)", name,
                  static_cast<long long>(value), static_cast<long long>(min), static_cast<long long>(max));
    set_error(FEEL_ERROR_INVALID_PARAMETER, buf, function);
    return FEEL_ERROR_INVALID_PARAMETER;
}

int bad_size(const char* function, const char* what, uint32_t size, uint32_t first, uint32_t known) noexcept {
    char buf[320];
    if (size < first) {
        std::snprintf(buf, sizeof buf,
                      "%s->size = %u is too small (allowed %u..: set it to sizeof the struct before the call)",
                      what, size, first);
        set_error(FEEL_ERROR_INVALID_PARAMETER, buf, function);
        return FEEL_ERROR_INVALID_PARAMETER;
    }
    std::snprintf(buf, sizeof buf,
                  "%s->size = %u: the struct sets fields that this libfeel (%s) does not know (it knows %u bytes)",
                  what, size, FEEL_VERSION_STRING, known);
    set_error(FEEL_ERROR_NOT_SUPPORTED, buf, function);
    return FEEL_ERROR_NOT_SUPPORTED;
}

}  // namespace feel::capi

extern "C" {

int feel_last_error(void) { return feel::capi::last_error.code; }

const char* feel_last_error_message(void) { return feel::capi::last_error.message; }

const char* feel_error_name(int code) {
    switch (code) {
        case FEEL_OK: return "ok";
        case FEEL_ERROR_INVALID_PARAMETER: return "invalid parameter";
        case FEEL_ERROR_DEVICE_FULL: return "device full";
        case FEEL_ERROR_NOT_SUPPORTED: return "not supported";
        case FEEL_ERROR_INVALID_HANDLE: return "invalid handle";
        case FEEL_ERROR_DISCONNECTED: return "disconnected";
        case FEEL_ERROR_TIMEOUT: return "timeout";
        case FEEL_ERROR_PROTOCOL: return "protocol error";
        case FEEL_ERROR_INTERNAL: return "internal error";
        default: return "unknown error";
    }
}

}  // extern "C"
