// Sine and cosine of a fraction of a turn, in single precision, without libm (issue 14).
//
// The tick's periodic waves, smart pops and sweeps need sin(2π·p) every tick. libm's sin
// is double precision (a software routine on a Cortex-M4F, whose FPU is single precision),
// and glibc's and newlib's sinf, though both accurate to about an ulp, are different code
// and need not round alike: the M4 build's forces would then drift from the x86 build's by
// an ulp now and then. This is a short polynomial of + and * only, which IEEE 754 rounds
// the same on every platform (the builds do not contract a·b + c into a fused
// multiply-add), so x86 and the M4 compute the same bits.
//
// Method: reduce p to x in [-½, ½] turn (sin(2πp) = sin(2πx)), fold |x| into [0, ¼] with
// sin(π - θ) = sin θ (both steps exact in float by Sterbenz's lemma), then a Taylor series
// on an eighth of a turn: sin θ to θ⁹ below ⅛ turn, cos of the distance to the crest to
// θ¹⁰ above (truncation errors below 1e-8). Measured against double-precision sin on a
// dense grid (tests/engine/turn_trig_test.cpp): within about 1.2e-7, and exactly 0 at
// whole and half turns and exactly ±1 at the crests.
#pragma once

#include <cstdint>

namespace feel::detail {

// sin(2π·p), p in turns, |p| < 2^22 (the tick's arguments are within a few turns).
[[nodiscard]] inline float sin_turns(float p) noexcept {
    // The nearest whole turn, by a conversion rather than floorf (a library call on both
    // targets): truncation toward zero, corrected below zero.
    const float shifted = p + 0.5f;
    float whole = static_cast<float>(static_cast<int32_t>(shifted));
    if (whole > shifted) whole -= 1.0f;
    const float x = p - whole;  // [-0.5, 0.5]
    float a = x < 0.0f ? -x : x;
    if (a > 0.25f) a = 0.5f - a;  // [0, 0.25]: sin(π - θ) = sin θ
    constexpr float kTwoPi = 6.28318530717958647692f;
    float v = 0.0f;
    if (a > 0.125f) {
        // Near the crest, cos of the distance to it: exactly 1 at a quarter turn.
        const float t = (0.25f - a) * kTwoPi;
        const float t2 = t * t;
        float c = 1.0f / 3628800.0f;
        c = 1.0f / 40320.0f - t2 * c;
        c = 1.0f / 720.0f - t2 * c;
        c = 1.0f / 24.0f - t2 * c;
        c = 0.5f - t2 * c;
        v = 1.0f - t2 * c;
    } else {
        const float t = a * kTwoPi;
        const float t2 = t * t;
        float s = 1.0f / 362880.0f;
        s = 1.0f / 5040.0f - t2 * s;
        s = 1.0f / 120.0f - t2 * s;
        s = 1.0f / 6.0f - t2 * s;
        v = t - t * t2 * s;
    }
    return x < 0.0f ? -v : v;
}

// cos(2π·p) = sin(2π·(p + ¼)).
[[nodiscard]] inline float cos_turns(float p) noexcept { return sin_turns(p + 0.25f); }

}  // namespace feel::detail
