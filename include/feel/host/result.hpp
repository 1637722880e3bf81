// feel::host — error values of the host API.
//
// Every call that talks to a device returns a Status or a Result<T>; none throws for a
// device-side problem (SDL and DirectInput return codes too). The error says what went
// wrong in words a game developer can log, and for a refused parameter it names the field,
// the value and the allowed range exactly as the device or the host's own check refused it.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "feel/status.hpp"

namespace feel::host {

enum class ErrorKind : uint8_t {
    ok,
    invalid_parameter,  // a field out of range or inconsistent (detail names it)
    device_full,        // no free effect block, parameter memory or sample memory
    not_supported,      // the device cannot play it and the host cannot emulate it
    invalid_handle,     // the effect was unloaded or belongs to a closed device
    disconnected,       // the device went away (cable, process, socket)
    timeout,            // the device did not answer in time (OpenOptions::timeout)
    protocol,           // the device answered something that is not the protocol
};
[[nodiscard]] std::string_view error_kind_name(ErrorKind kind) noexcept;

struct Status {
    ErrorKind kind = ErrorKind::ok;
    Error detail{};       // the engine's error (field, value, range) when there is one
    std::string message;  // the whole sentence, e.g.
                          // "create spring: conditions[0].deadband = 12000 is out of range (allowed 0..10000)"

    [[nodiscard]] bool ok() const noexcept { return kind == ErrorKind::ok; }
    [[nodiscard]] static Status success() { return {}; }
    [[nodiscard]] static Status failure(ErrorKind kind, std::string message, Error detail = {}) {
        Status s;
        s.kind = kind;
        s.message = std::move(message);
        s.detail = detail;
        return s;
    }
};

// A value or the Status that explains why there is none.
template <class T>
class Result {
public:
    Result(T value) : v_(std::move(value)) {}                 // NOLINT: implicit by design
    Result(Status error) : v_(std::move(error)) {             // NOLINT
        if (std::get<Status>(v_).ok()) throw std::logic_error("feel::host::Result: an ok Status is not an error");
    }

    [[nodiscard]] bool ok() const noexcept { return std::holds_alternative<T>(v_); }
    explicit operator bool() const noexcept { return ok(); }
    // The value. Throws std::logic_error with the error's message if there is none.
    [[nodiscard]] T& value() & { check(); return std::get<T>(v_); }
    [[nodiscard]] const T& value() const& { check(); return std::get<T>(v_); }
    [[nodiscard]] T&& value() && { check(); return std::get<T>(std::move(v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    // The error; an ok Status when there is a value.
    [[nodiscard]] Status status() const { return ok() ? Status{} : std::get<Status>(v_); }

private:
    void check() const {
        if (!ok()) throw std::logic_error("feel::host::Result has no value: " + std::get<Status>(v_).message);
    }
    std::variant<T, Status> v_;
};

}  // namespace feel::host
