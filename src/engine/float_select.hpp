// A selection between two floats that x86 makes without a branch (issue 14).
//
// The tick's waves choose between two worked-out values on data that changes every tick
// (which eighth of a turn the sine is in, which half of a square's cycle). GCC compiles a
// plain `c ? a : b` on floats into a conditional jump, which the busy mix's periods (5 to
// 15 ticks a cycle) make unpredictable, and which resolves only at the end of the chain
// that computes its condition. Masking the bits leaves a compare and three logical
// operations, with the same float as the `?:` to the bit. The board's build for size (a
// Cortex-M4F, whose branches cost a cycle or two and have nothing to mispredict) keeps the
// `?:`: the same result in fewer bytes.
#pragma once

#include <bit>
#include <cstdint>

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

}  // namespace feel::detail
