// The C ABI's handles and its error plumbing (include/feel/feel.h).
//
// Design. The opaque C handles are plain structs in the global namespace holding the C++
// host API's objects: a feel_device holds a feel::host::Device (a shared handle), a
// feel_effect a feel::host::Effect (RAII: destroying it unloads the effect), and so on.
// Every extern "C" function runs its body through guard(), which turns any exception into
// an error code and a message, so no exception can cross into C. The thread's last error
// lives in a fixed thread_local buffer: recording an error never allocates, so even
// std::bad_alloc is reported faithfully.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

#include "feel/feel.h"
#include "feel/host/device.hpp"
#include "feel/host/result.hpp"
#include "feel/host/sensation_library.hpp"

struct feel_device {
    feel::host::Device device;
    bool borrowed = false;  // a library's device: feel_library_free closes it, not feel_close
};

struct feel_effect {
    feel::host::Effect effect;
};

struct feel_subscription {
    feel::host::Subscription subscription;
};

struct feel_library {
    feel::host::SensationLibrary library;
    std::unique_ptr<feel_device> device;  // borrowed view of library.device()
};

namespace feel::capi {

// Sets the thread's last error to `code` and "prefix: message" (just message when prefix
// is empty; NUL-terminated, truncated to fit the buffer). Never allocates.
void set_error(int code, std::string_view message, std::string_view prefix = {}) noexcept;
inline int succeed() noexcept {
    set_error(FEEL_OK, "");
    return FEEL_OK;
}
// Records a host Status (its kind is the code: ErrorKind mirrors FEEL_ERROR_*) and returns
// its code.
int fail(const host::Status& status) noexcept;
inline int fail(int code, std::string_view message) noexcept {
    set_error(code, message);
    return code;
}
inline int from_status(const host::Status& status) noexcept { return status.ok() ? succeed() : fail(status); }

// "<function>: <what> is NULL".
int null_argument(const char* function, const char* what) noexcept;
// For the functions that return a handle: `return no_handle(null_argument(...));`.
inline std::nullptr_t no_handle(int /*recorded error*/) noexcept { return nullptr; }
// "<function>: <name> = <value> is out of range (allowed <min>..<max>)".
int out_of_range(const char* function, const char* name, int64_t value, int64_t min, int64_t max) noexcept;

// Runs body() (returning int), mapping any exception to FEEL_ERROR_INVALID_PARAMETER
// (std::invalid_argument) or FEEL_ERROR_INTERNAL (anything else) with its message.
template <class Body>
int guard(const char* function, Body&& body) noexcept {
    try {
        return body();
    } catch (const std::invalid_argument& e) {
        return fail(FEEL_ERROR_INVALID_PARAMETER, e.what());
    } catch (const std::bad_alloc&) {
        set_error(FEEL_ERROR_INTERNAL, "out of memory", function);
        return FEEL_ERROR_INTERNAL;
    } catch (const std::exception& e) {
        set_error(FEEL_ERROR_INTERNAL, e.what(), function);
        return FEEL_ERROR_INTERNAL;
    } catch (...) {
        set_error(FEEL_ERROR_INTERNAL, "an unknown exception inside feel", function);
        return FEEL_ERROR_INTERNAL;
    }
}

// guard() for the functions that return a handle: body() returns the pointer (nullptr
// after recording an error).
template <class T, class Body>
T* guard_ptr(const char* function, Body&& body) noexcept {
    T* out = nullptr;
    (void)guard(function, [&] {
        out = body();
        return out ? succeed() : feel_last_error();
    });
    return out;
}

}  // namespace feel::capi
