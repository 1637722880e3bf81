// Four floats in one SSE register, each lane worked out by the IEEE operation its scalar
// form uses (issue 14, x86 only).
//
// A periodic wave's value is one long chain of dependent operations (the cycle position, a
// division, the sine's reduction and series): the tick's periodics, each worked out alone,
// wait on it one after the other. Four of them in the lanes of one register go down the
// chain together. addps, subps, mulps and divps round each lane as addss, subss, mulss and
// divss round the scalar, cvtdq2ps and cvttps2dq convert each lane as cvtsi2ss and cvttss2si
// do, and nothing is contracted into a fused multiply-add (this build has no FMA): each
// lane is the scalar code's float to the bit.
#pragma once

#if !defined(__OPTIMIZE_SIZE__) && defined(__SSE2__)
#include <emmintrin.h>
#define FEEL_FLOAT_LANES 1

namespace feel::detail {

struct FloatLanes {
    __m128 v;
    FloatLanes(__m128 lanes) noexcept : v(lanes) {}                // NOLINT: a register is its lanes
    FloatLanes(float each) noexcept : v(_mm_set1_ps(each)) {}      // NOLINT: a constant in every lane
    friend FloatLanes operator+(FloatLanes a, FloatLanes b) noexcept { return _mm_add_ps(a.v, b.v); }
    friend FloatLanes operator-(FloatLanes a, FloatLanes b) noexcept { return _mm_sub_ps(a.v, b.v); }
    friend FloatLanes operator*(FloatLanes a, FloatLanes b) noexcept { return _mm_mul_ps(a.v, b.v); }
    friend FloatLanes operator/(FloatLanes a, FloatLanes b) noexcept { return _mm_div_ps(a.v, b.v); }
    // −a flips the sign bit, as the scalar negation does.
    friend FloatLanes operator-(FloatLanes a) noexcept { return _mm_xor_ps(a.v, _mm_set1_ps(-0.0f)); }
};

// Lane by lane, x > y ? if_true : if_false (a NaN compares false, as in C++).
[[nodiscard]] inline FloatLanes select_if_greater(FloatLanes x, FloatLanes y, FloatLanes if_true,
                                                  FloatLanes if_false) noexcept {
    const __m128 mask = _mm_cmpgt_ps(x.v, y.v);
    return _mm_or_ps(_mm_and_ps(mask, if_true.v), _mm_andnot_ps(mask, if_false.v));
}

// Lane by lane, x >= y ? if_true : if_false.
[[nodiscard]] inline FloatLanes select_if_at_least(FloatLanes x, FloatLanes y, FloatLanes if_true,
                                                   FloatLanes if_false) noexcept {
    const __m128 mask = _mm_cmpge_ps(x.v, y.v);
    return _mm_or_ps(_mm_and_ps(mask, if_true.v), _mm_andnot_ps(mask, if_false.v));
}

// Each lane truncated toward zero to an int32 and back (cvttss2si then cvtsi2ss, per lane).
[[nodiscard]] inline FloatLanes truncated_through_int32(FloatLanes x) noexcept {
    return _mm_cvtepi32_ps(_mm_cvttps_epi32(x.v));
}

}  // namespace feel::detail
#endif
