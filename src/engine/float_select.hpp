// Selections between two floats that x86 makes without a branch (issue 14).
//
// The tick chooses between two worked-out values on data that changes every tick (which eighth
// of a turn a wave's sine is in, which part of the cycle a wave is in, the sign of a wall's
// passivity booking as the handle wiggles across it). GCC often compiles a plain `c ? a : b` on
// floats into a conditional jump, which such data (the busy mix's periods: 5 to 15 ticks a
// cycle) makes unpredictable, and which resolves only at the end of the chain that computes its
// condition. On x86 these are a compare that makes a mask and three logical operations in the
// SSE registers; on another host the bits are masked in integers; either way the same float as
// the `?:` to the bit (a compare with a NaN is false in both). The board's build for size (a
// Cortex-M4F, whose branches cost a cycle or two and have nothing to mispredict) keeps the
// `?:`: the same result in fewer bytes.
#pragma once

#include <bit>
#include <cstdint>

#if !defined(__OPTIMIZE_SIZE__) && defined(__SSE2__)
#include <emmintrin.h>
#define FEEL_SELECT_SSE 1
#endif

namespace feel::detail {

// take ? if_true : if_false.
[[nodiscard]] inline float select_float(bool take, float if_true, float if_false) noexcept {
#if defined(__OPTIMIZE_SIZE__)
    return take ? if_true : if_false;
#else
    const uint32_t mask = 0u - static_cast<uint32_t>(take);
    return std::bit_cast<float>((std::bit_cast<uint32_t>(if_true) & mask) |
                                (std::bit_cast<uint32_t>(if_false) & ~mask));
#endif
}

#if defined(FEEL_SELECT_SSE)
// Lane 0 of mask all ones ? if_true : if_false. The operands are broadcast (one shuffle
// each): _mm_set_ss's zeroed upper lanes cost GCC a round trip through an integer register.
[[nodiscard]] inline float select_by_mask(__m128 mask, float if_true, float if_false) noexcept {
    return _mm_cvtss_f32(_mm_or_ps(_mm_and_ps(mask, _mm_set1_ps(if_true)), _mm_andnot_ps(mask, _mm_set1_ps(if_false))));
}
#endif

// x > y ? if_true : if_false.
[[nodiscard]] inline float select_if_greater(float x, float y, float if_true, float if_false) noexcept {
#if defined(FEEL_SELECT_SSE)
    return select_by_mask(_mm_cmpgt_ps(_mm_set1_ps(x), _mm_set1_ps(y)), if_true, if_false);
#else
    return select_float(x > y, if_true, if_false);
#endif
}

// x >= y ? if_true : if_false.
[[nodiscard]] inline float select_if_at_least(float x, float y, float if_true, float if_false) noexcept {
#if defined(FEEL_SELECT_SSE)
    return select_by_mask(_mm_cmpge_ps(_mm_set1_ps(x), _mm_set1_ps(y)), if_true, if_false);
#else
    return select_float(x >= y, if_true, if_false);
#endif
}

}  // namespace feel::detail
