// feel — error values shared by the engine, the file reader and (later) the host API.
//
// The engine is built without exceptions, so failures are values. An Error names the
// field that is wrong, the value found and the range allowed, with no heap allocation.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "feel/units.hpp"

namespace feel {

enum class ErrorCode : uint8_t {
    ok,
    invalid_parameter,  // a field is out of range or inconsistent with another field
    device_full,        // no free effect slot or not enough sample memory (§2.2)
    not_supported,      // the device or this version of feel cannot render the type
    invalid_handle,     // the effect id is stale or was never created
};

[[nodiscard]] std::string_view error_code_name(ErrorCode c) noexcept;

struct Error {
    ErrorCode code = ErrorCode::ok;
    char field[48] = {};       // field path, e.g. "periodic.phase" or "conditions[1].deadband"
    int64_t value = 0;         // the offending value, when has_range
    Range allowed{0, 0};       // the allowed range, when has_range
    bool has_range = false;
    const char* rule = "";     // a static sentence for errors that are not a range

    [[nodiscard]] bool ok() const noexcept { return code == ErrorCode::ok; }
    explicit operator bool() const noexcept { return !ok(); }  // true when there is an error

    // Builders; they never allocate.
    static Error out_of_range(std::string_view field, int64_t value, Range allowed) noexcept;
    static Error invalid(std::string_view field, const char* rule) noexcept;
    static Error of(ErrorCode code, std::string_view field, const char* rule) noexcept;

    // "periodic.phase = 36000 is out of range (allowed 0..35999)". Not for the real-time path.
    [[nodiscard]] std::string message() const;
};

}  // namespace feel
