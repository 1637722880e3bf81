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
#include "time_division.hpp"
#include "turn_trig.hpp"

namespace feel::detail {

// Single precision (issue 14); the sine is turn_trig.hpp's, the same bits on every platform.
// Inline, as the rest of this header: every periodic wave calls them every tick.
[[nodiscard]] inline float waveform_value(Waveform w, float p) noexcept {
    switch (w) {
        case Waveform::sine: return sin_turns(p);
        case Waveform::square: return p < 0.5f ? 1.0f : -1.0f;
        case Waveform::triangle:
            if (p < 0.25f) return 4.0f * p;
            if (p < 0.75f) return 2.0f - 4.0f * p;
            return 4.0f * p - 4.0f;
        case Waveform::saw_up: return 2.0f * p - 1.0f;
        case Waveform::saw_down: return 1.0f - 2.0f * p;
    }
    return 0.0f;
}

// The cycle fraction at wave time tau_us (≥ 0), in [0, 1): the time into the cycle is
// taken in integers first, so that long times keep full precision. A wave of finite
// duration has τ below it (at most 65e6 µs), so the remainder is a 32-bit one (a Cortex-M4
// divides 32 bits in hardware, 64 in a library call) and the same integer as the 64-bit
// remainder; only an endless wave past 2^31 µs (36 minutes) takes the 64-bit one (time_division.hpp).
// phase_turns is the phase / 36000, kept with the block (SlotPeriodicBlock).
[[nodiscard]] inline float cycle_fraction(int64_t tau_us, int32_t period_us, float phase_turns) noexcept {
    const int32_t into_cycle = tau_us <= INT32_MAX ? static_cast<int32_t>(tau_us) % period_us
                                                   : static_cast<int32_t>(tau_us - time_quotient(tau_us, period_us) * period_us);
    float p = static_cast<float>(into_cycle) / static_cast<float>(period_us) + phase_turns;
    // Rounding may land a hair's breadth below the period on 1 itself: that is the cycle's start.
    if (p >= 1.0f) p -= 1.0f;
    if (p >= 1.0f) p = 0.0f;
    return p;
}

}  // namespace feel::detail
