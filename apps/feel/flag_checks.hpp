// Range checks for command-line numbers, with the message every command uses:
//
//   --rate = 0 Hz is out of range (allowed a whole number of Hz, 1..1000)
//
// CLI11 converts the text (a word where a number belongs is its error); these check the
// value, including NaN and infinities, which CLI11 accepts as doubles. Each throws
// UsageError (exit 2) naming the flag, the value and the allowed range.
#pragma once

#include <cstdint>
#include <string>

#include "feel/sim/device_profile.hpp"

namespace feel::cli {

// 0.35 -> "0.35", 1e-7 -> "1e-07": the shortest %g form.
[[nodiscard]] std::string number(double v);

// A whole number in min..max. `unit` follows the value in the message ("Hz"; may be empty).
[[nodiscard]] int32_t checked_whole(const char* flag, double value, int32_t min, int32_t max,
                                    const char* unit = "");
// A finite number in min..max (min itself allowed only if min_inclusive).
[[nodiscard]] double checked_range(const char* flag, double value, double min, double max, const char* unit,
                                   bool min_inclusive = true);

// The built-in profile named by --profile; a UsageError listing them when none is.
[[nodiscard]] const sim::DeviceProfile& checked_profile(const std::string& name);

}  // namespace feel::cli
