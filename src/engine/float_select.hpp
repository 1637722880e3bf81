// cond ? a : b for floats, without a jump where that is the point (issue 14, twelfth pass).
//
// A jump on a float comparison whose outcome the data flips at random (a bump's edge, a
// booking's sign) is mispredicted as often, and the processor discards what it had started
// after it. GCC turns `cond ? a : b` on floats into a jump as often as into a mask (cmpss,
// and, andn, or), depending on the code around it; the same selection on the floats' bits
// as 32-bit integers it keeps as bit operations or a cmov. The value is a or b, unchanged,
// so the same bits either way. A build for size (the Cortex-M4F firmware) keeps `?:`, which
// is shorter there (the flash is at its goal): the same value.
#pragma once

#include <bit>
#include <cstdint>

namespace feel::detail {

[[nodiscard]] inline float select_float(bool cond, float a, float b) noexcept {
#if defined(__OPTIMIZE_SIZE__)
    return cond ? a : b;
#else
    const uint32_t mask = 0u - static_cast<uint32_t>(cond);
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) | (std::bit_cast<uint32_t>(b) & ~mask));
#endif
}

}  // namespace feel::detail
