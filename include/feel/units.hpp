// feel — the primer's integer API units (§6) and their allowed ranges.
//
// Every range used to validate input lives here, once. The file reader, the engine's
// own validator and (later) the protocol decoder all name these constants, so an error
// message always quotes the same range the engine enforces.
#pragma once

#include <cstdint>

#include "feel/axis.hpp"

namespace feel {

// Magnitudes, coefficients, saturations and positions are in ±10000 of device capability.
inline constexpr int32_t kFullScale = 10000;

// Durations and other times are microseconds; kInfiniteUs marks an endless effect (§6.3).
inline constexpr int64_t kInfiniteUs = -1;
inline constexpr int64_t kMaxTimeUs = 65'000'000;  // "0 to 65 million" (§6.3)

// An inclusive integer range, [min, max].
struct Range {
    int64_t min;
    int64_t max;
    [[nodiscard]] constexpr bool contains(int64_t v) const noexcept { return v >= min && v <= max; }
};

namespace range {
inline constexpr Range kSignedLevel{-kFullScale, kFullScale};  // magnitudes, offsets, coefficients
inline constexpr Range kLevel{0, kFullScale};                  // saturations, envelope levels, deadband
inline constexpr Range kPositiveLevel{1, kFullScale};          // texture roughness, spacing, density
inline constexpr Range kAngle{0, 35999};                       // hundredths of a degree
inline constexpr Range kDurationUs{1, kMaxTimeUs};             // or kInfiniteUs
inline constexpr Range kDelayUs{0, kMaxTimeUs};                // start delay, settle/fade time
inline constexpr Range kPeriodUs{1, kMaxTimeUs};               // a zero period has no frequency
inline constexpr Range kGain{0, kFullScale};
inline constexpr Range kIterations{1, 255};                    // or infinite (HID PID loop count)
inline constexpr Range kTriggerButton{1, 32};
inline constexpr Range kTriggerHat{1, 4};
inline constexpr Range kChannels{1, 6};
inline constexpr Range kSampleCount{1, 65535};
inline constexpr Range kCartesianComponent{-kFullScale, kFullScale};
inline constexpr Range kDynamicMass{1, kFullScale};            // §6.6.f, §8.4
inline constexpr Range kHalfCycles{0, kFullScale};
inline constexpr Range kAxisCount{1, kMaxAxes};                // x, y, z, rx, ry, rz (axis.hpp)
inline constexpr Range kElevation{0, 18000};                   // spherical: angle away from +z (§6.5.c)
inline constexpr Range kRepeatIntervalUs{0, kMaxTimeUs};       // 0 = no repeat (§6.3)
inline constexpr Range kDynamicStiffness{1, kFullScale};       // KPos/KNeg and what maps to them (§8.4)
inline constexpr Range kSample{-kFullScale, kFullScale};       // one force-profile sample (§6.6.d)
}  // namespace range

}  // namespace feel
