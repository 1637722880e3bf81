// The C ABI's handles and its error plumbing (include/feel/feel.h).
//
// Design. The opaque C handles are plain structs in the global namespace holding the C++
// host API's objects: a feel_device holds a feel::host::Device (a shared handle), a
// feel_effect a feel::host::Effect (RAII: destroying it unloads the effect), and so on.
// Every extern "C" function runs its body through guard(), which turns any exception into
// an error code and a message, so no exception can cross into C. The thread's last error
// lives in a fixed thread_local buffer: recording an error never allocates, so even
// std::bad_alloc is reported faithfully.
//
// Sized structs. Every struct but feel_trigger starts with `uint32_t size` (feel.h). The
// library fills (write_out) or reads (read_in) only the bytes both sides know: the
// caller's size or ours, whichever is smaller. A caller's struct may never be smaller than
// the struct's first published size (kFirstSize), and a caller's struct from newer headers
// than ours must leave the fields we do not know zero (their "as before" value), or the
// call is refused rather than silently ignoring them (docs/c-api.md, "ABI evolution").
#pragma once

#include <algorithm>
#include <cstring>
#include <map>
#include <span>
#include <vector>

#include <cstddef>
#include <cstdio>
#include <cstdint>
#include <exception>
#include <deque>
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

// An effect the caller owns (made by feel_create_effect or a wrapper), or a view of one a
// library owns (feel_library_effect): `effect` points at `owned` or into the library.
struct feel_effect {
    explicit feel_effect(feel::host::Effect e) : owned(std::move(e)), effect(&owned) {}
    explicit feel_effect(feel::host::Effect* borrowed_effect) : effect(borrowed_effect), borrowed(true) {}
    feel::host::Effect owned;
    feel::host::Effect* effect;
    bool borrowed = false;
};

struct feel_subscription {
    feel::host::Subscription subscription;
};

// A per-report input subscription, and the reports a call had no room for (the next call
// gives them first).
struct feel_input_subscription {
    feel::host::InputSubscription subscription;
    std::deque<feel::host::InputState> pending;
    uint64_t dropped = 0;  // lost to a full queue, not yet told
};

struct feel_library {
    feel::host::SensationLibrary library;
    std::unique_ptr<feel_device> device;  // borrowed view of library.device()
    bool owns_device = true;              // false after feel_library_load_on: the caller's
    std::vector<std::string> names;       // the sensations, for feel_library_sensation_name
    // Views of the library's effects handed out by feel_library_effect, made on first use.
    std::map<std::string, std::vector<std::unique_ptr<feel_effect>>, std::less<>> effect_views;
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

// Thrown by a body after it recorded its error (for bodies whose return value is not the
// code): guard() returns the recorded code unchanged.
struct RecordedError {};
[[noreturn]] inline void throw_last_error() { throw RecordedError{}; }

// Runs body() (returning int), mapping any exception to FEEL_ERROR_INVALID_PARAMETER
// (std::invalid_argument) or FEEL_ERROR_INTERNAL (anything else) with its message.
template <class Body>
int guard(const char* function, Body&& body) noexcept {
    try {
        return body();
    } catch (const RecordedError&) {
        return feel_last_error();
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

// feel_effect_params as EffectParams; the C enumerations' ranges checked (std::invalid_argument
// naming the field otherwise). The other ranges are the host's to check.
EffectParams to_cpp(const char* function, const feel_effect_params& params);
// The samples a caller passes: none, or sample_count (0..65535) of them; std::invalid_argument
// for a count out of range or NULL samples with a count.
std::span<const int16_t> samples_of(const char* function, const int16_t* samples, int32_t sample_count);

// Copies a string into a fixed C array, NUL-terminated, truncated to fit.
template <std::size_t N>
void copy_string(char (&dst)[N], const std::string& src) noexcept {
    std::snprintf(dst, N, "%s", src.c_str());
}

// The first published size of each sized struct; a struct that grows keeps its first
// size here (the oldest callers' size), and sizeof(T) is what this library knows.
template <class T>
inline constexpr uint32_t kFirstSize = sizeof(T);

// "<function>: <what>.size = N is too small (allowed >= first size; set it to sizeof(T))".
int bad_size(const char* function, const char* what, uint32_t size, uint32_t first, uint32_t known) noexcept;

// Checks the size of a struct the caller hands in for feel to fill.
template <class T>
int check_out(const char* function, const char* what, const T* out) noexcept {
    if (!out) return null_argument(function, what);
    if (out->size < kFirstSize<T>) return bad_size(function, what, out->size, kFirstSize<T>, sizeof(T));
    return FEEL_OK;
}

// Copies `full` (all the fields this library knows) into the caller's struct, as far as
// the caller's size goes; the caller's size stays.
template <class T>
void write_out(T full, T* out) noexcept {
    const uint32_t size = out->size;
    full.size = size;
    std::memcpy(static_cast<void*>(out), &full, std::min<std::size_t>(size, sizeof(T)));
}

// Reads the caller's struct into `full` (zero, i.e. default, where the caller's struct is
// shorter). Refuses a struct from newer headers that sets fields this library lacks.
template <class T>
int read_in(const char* function, const char* what, const T* in, T& full) noexcept {
    if (!in) return null_argument(function, what);
    if (in->size < kFirstSize<T>) return bad_size(function, what, in->size, kFirstSize<T>, sizeof(T));
    std::memset(static_cast<void*>(&full), 0, sizeof(T));
    std::memcpy(static_cast<void*>(&full), in, std::min<std::size_t>(in->size, sizeof(T)));
    if (in->size > sizeof(T)) {
        const auto* tail = reinterpret_cast<const unsigned char*>(in) + sizeof(T);
        if (std::any_of(tail, tail + (in->size - sizeof(T)), [](unsigned char b) { return b != 0; })) {
            return bad_size(function, what, in->size, kFirstSize<T>, sizeof(T));
        }
    }
    full.size = sizeof(T);
    return FEEL_OK;
}

}  // namespace feel::capi
