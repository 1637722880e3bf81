// The five periodic sources (§4.2), as functions of the cycle fraction p in [0, 1).
//
//   sine      sin(2πp)                 starts at 0, rising
//   square    +1 for p < ½, -1 after   starts high
//   triangle  0 → +1 (p=¼) → -1 (p=¾) → 0, starts at 0 rising like the sine
//   saw_up    -1 → +1 linearly, then drops back
//   saw_down  +1 → -1 linearly, then jumps back
//
// The phase (hundredths of a degree) shifts where in the cycle the wave starts:
// p = frac(τ / period + phase / 36000).
#pragma once

#include <cstdint>

#include "feel/effect_type.hpp"

namespace feel::detail {

// Single precision (issue 14); the sine is turn_trig.hpp's, the same bits on every platform.
[[nodiscard]] float waveform_value(Waveform w, float p) noexcept;

// The cycle fraction at wave time tau_us, in [0, 1): the time into the cycle is taken in
// integers first, so that long times keep full precision.
[[nodiscard]] float cycle_fraction(int64_t tau_us, int64_t period_us, int32_t phase) noexcept;

}  // namespace feel::detail
