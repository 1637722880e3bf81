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

#include "float_lanes.hpp"
#include "float_select.hpp"

namespace feel::detail {

// p truncated toward zero to an int32 and back (FloatLanes has its own, lane by lane).
[[nodiscard]] inline float truncated_through_int32(float p) noexcept {
    return static_cast<float>(static_cast<int32_t>(p));
}

namespace turn_trig_series {

constexpr float kTwoPi = 6.28318530717958647692f;

// sin 2πa for a in [0, ⅛] turn: the Taylor series to θ⁹.
// F is float, or FloatLanes (float_lanes.hpp: the same operations lane by lane).
template <class F>
[[nodiscard]] inline F sine_near_zero(F a) noexcept {
    const F t = a * kTwoPi;
    const F t2 = t * t;
    F s = 1.0f / 362880.0f;
    s = 1.0f / 5040.0f - t2 * s;
    s = 1.0f / 120.0f - t2 * s;
    s = 1.0f / 6.0f - t2 * s;
    return t - t * t2 * s;
}

// sin 2πa for a in [⅛, ¼] turn, as cos of the distance to the crest (to θ¹⁰): exactly 1 at
// a quarter turn.
template <class F>
[[nodiscard]] inline F sine_near_crest(F a) noexcept {
    const F t = (0.25f - a) * kTwoPi;
    const F t2 = t * t;
    F c = 1.0f / 3628800.0f;
    c = 1.0f / 40320.0f - t2 * c;
    c = 1.0f / 720.0f - t2 * c;
    c = 1.0f / 24.0f - t2 * c;
    c = 0.5f - t2 * c;
    return 1.0f - t2 * c;
}

}  // namespace turn_trig_series

// sin(2π·p), p in turns, |p| < 2^22 (the tick's arguments are within a few turns).
// kWithoutJumps: each step's choice a select_if_greater on x86, and the series of both eighths
// worked out, for an argument whose place in the turn changes from tick to tick (a
// periodic wave's sine: a mispredicted jump at the end of its chain costs more than the
// work it skips). Otherwise jumps, for arguments that move slowly (a direction, a sweep):
// well predicted, and fewer instructions. The same float either way; the board branches.
template <bool kWithoutJumps, class F = float>
[[nodiscard]] inline F sin_turns_by(F p) noexcept {
    using namespace turn_trig_series;
    // Each choice: x > y ? if_true : if_false.
    const auto choose = [](F x, F y, F if_true, F if_false) -> F {
        if constexpr (kWithoutJumps) {
            return select_if_greater(x, y, if_true, if_false);
        } else {
            return x > y ? if_true : if_false;
        }
    };
    // The nearest whole turn, by a conversion rather than floorf (a library call on both
    // targets): truncation toward zero, corrected below zero.
    const F shifted = p + 0.5f;
    const F truncated = truncated_through_int32(shifted);
    const F whole = choose(truncated, shifted, truncated - 1.0f, truncated);
    const F x = p - whole;  // [-0.5, 0.5]
    const F magnitude = choose(0.0f, x, -x, x);
    const F a = choose(magnitude, 0.25f, 0.5f - magnitude, magnitude);  // [0, 0.25]: sin(π - θ) = sin θ
    F v = 0.0f;
#if !defined(__OPTIMIZE_SIZE__)
    if constexpr (kWithoutJumps) {
        v = select_if_greater(a, F(0.125f), sine_near_crest(a), sine_near_zero(a));
    } else
#endif
    {
        v = a > 0.125f ? sine_near_crest(a) : sine_near_zero(a);
    }
    return choose(0.0f, x, -v, v);
}

[[nodiscard]] inline float sin_turns(float p) noexcept { return sin_turns_by<false>(p); }
// For an argument that changes its place in the turn every tick or so. On x86 the argument
// in every lane of an SSE register (float_lanes.hpp), so that each choice is a compare and
// three logical operations on the register as it is, with no shuffle to broadcast its
// operands first (select_if_greater's scalar form needs one for each): the same operations
// in each lane, so lane 0 is the scalar's float.
[[nodiscard]] inline float sin_turns_without_jumps(float p) noexcept {
#if defined(FEEL_FLOAT_LANES)
    return _mm_cvtss_f32(sin_turns_by<true>(FloatLanes(p)).v);
#else
    return sin_turns_by<true>(p);
#endif
}

// cos(2π·p) = sin(2π·(p + ¼)).
[[nodiscard]] inline float cos_turns(float p) noexcept { return sin_turns(p + 0.25f); }

}  // namespace feel::detail
