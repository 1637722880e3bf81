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
#include "float_select.hpp"
#include "turn_trig.hpp"

namespace feel::detail {

// The square, the triangle and the saws are straight pieces over the quarters of the cycle:
// at_zero + slope·p, the same float as the switch's expressions (a + (−b) is a − b to the
// bit, and 0 + 4p is 4p for p ≥ 0).
struct LinearPiece {
    float at_zero;
    float slope;
};
// By waveform (sine's row unused) and quarter of the cycle.
inline constexpr LinearPiece kWaveformPieces[5][4] = {
    {{0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}},        // sine: sin_turns
    {{1.0f, 0.0f}, {1.0f, 0.0f}, {-1.0f, 0.0f}, {-1.0f, 0.0f}},      // square
    {{0.0f, 4.0f}, {2.0f, -4.0f}, {2.0f, -4.0f}, {-4.0f, 4.0f}},     // triangle
    {{-1.0f, 2.0f}, {-1.0f, 2.0f}, {-1.0f, 2.0f}, {-1.0f, 2.0f}},    // saw_up
    {{1.0f, -2.0f}, {1.0f, -2.0f}, {1.0f, -2.0f}, {1.0f, -2.0f}},    // saw_down
};

// Single precision (issue 14); the sine is turn_trig.hpp's, the same bits on every platform.
// Inline, as the rest of this header: every periodic wave calls them every tick.
// On x86 without a branch on p (which changes every tick) nor on the waveform: the piece
// is a table's row, and the sine is worked out for every waveform and selected.
[[nodiscard]] inline float waveform_value(Waveform w, float p) noexcept {
#if defined(__OPTIMIZE_SIZE__)
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
#else
    if (w == Waveform::sine) return sin_turns_without_jumps(p);
    const int quarter = static_cast<int>(p >= 0.25f) + static_cast<int>(p >= 0.5f) + static_cast<int>(p >= 0.75f);
    const LinearPiece& piece = kWaveformPieces[static_cast<int>(w)][quarter];
    return piece.at_zero + piece.slope * p;
#endif
}

// The cycle fraction at wave time tau_us (≥ 0), in [0, 1): the time into the cycle is
// taken in integers first, so that long times keep full precision. A wave of finite
// duration has τ below it (at most 65e6 µs), so the remainder is a 32-bit one (a Cortex-M4
// divides 32 bits in hardware, 64 in a library call) and the same integer as the 64-bit
// remainder; only an endless wave past 2^31 µs (36 minutes) takes the 64-bit one (time_division.hpp).
// phase_turns is the phase / 36000, kept with the block (SlotPeriodicBlock).
// The time into the cycle (τ mod period) at wave time tau_us ≥ 0.
[[nodiscard]] inline int32_t time_into_cycle(int64_t tau_us, int32_t period_us) noexcept {
    return tau_us <= INT32_MAX ? static_cast<int32_t>(tau_us) % period_us
                               : static_cast<int32_t>(tau_us - time_quotient(tau_us, period_us) * period_us);
}

// The cycle fraction of a time into the cycle (in [0, period)), in [0, 1).
[[nodiscard]] inline float fraction_of_cycle(int32_t into_cycle, int32_t period_us, float phase_turns) noexcept {
    // On x86 in every lane of an SSE register (float_lanes.hpp): the choices below without a
    // shuffle to broadcast each operand, the same float in lane 0.
#if defined(FEEL_FLOAT_LANES)
    FloatLanes p = FloatLanes(static_cast<float>(into_cycle)) / static_cast<float>(period_us) + phase_turns;
#else
    float p = static_cast<float>(into_cycle) / static_cast<float>(period_us) + phase_turns;
#endif
    // Rounding may land a hair's breadth below the period on 1 itself: that is the cycle's start.
    p = select_if_at_least(p, 1.0f, p - 1.0f, p);
    p = select_if_at_least(p, 1.0f, 0.0f, p);
#if defined(FEEL_FLOAT_LANES)
    return _mm_cvtss_f32(p.v);
#else
    return p;
#endif
}

[[nodiscard]] inline float cycle_fraction(int64_t tau_us, int32_t period_us, float phase_turns) noexcept {
    return fraction_of_cycle(time_into_cycle(tau_us, period_us), period_us, phase_turns);
}

}  // namespace feel::detail
