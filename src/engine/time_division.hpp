// A time in µs divided by a 32-bit length, without a 64-bit division.
//
// The engine divides times by lengths: the time since an effect started by its duration
// (the iteration), by a period (the time into a cycle), by a sample period (the frame), and
// 10⁶ · 2^k by a frequency's significand (the period). Each time is a non-negative int64 and
// each length a positive int32 (the validator's ranges: durations, periods and sample
// periods are int32 fields; a frequency's significand is 24 bits). x86-64 divides 64 bits in
// one instruction; a Cortex-M4 divides only 32 bits in hardware, and the 64-bit quotient is
// libgcc's __aeabi_ldivmod with __udivmoddi4 behind it (about 870 bytes of flash).
//
// time_quotient gives the same quotient as the plain division; the callers take the
// remainder as t - q·d, exact in int64 (the quotient alone comes back in registers; a
// struct with the remainder would come back through memory on the M4, AAPCS). A time under
// 2³² µs (71 minutes) is divided in 32 bits. A longer one is divided as long division by
// hand: the high 32 bits by the length in hardware, then its remainder r (< d < 2³¹)
// followed by the low 32 bits one bit at a time: each step doubles r and brings in the next
// bit (2r + 1 < 2³² fits 32 bits) and subtracts d when it can, setting that bit of the
// quotient. 32 steps of a few instructions: slower than the library, but only an effect
// playing for over an hour takes them. tests/engine/time_division_test.cpp checks it
// against the plain division.
#pragma once

#include <cstdint>

namespace feel::detail {

// t ≥ 0, d > 0. Out of line: the firmware calls it from several places, and flash is what
// it saves. Public so the x86 test can check it against the plain division.
[[gnu::noinline]] inline int64_t time_quotient_in_32_bits(int64_t t, int32_t d) noexcept {
    const auto n = static_cast<uint64_t>(t);
    const auto divisor = static_cast<uint32_t>(d);
    const auto low = static_cast<uint32_t>(n);
    const auto high = static_cast<uint32_t>(n >> 32);
    if (high == 0) return low / divisor;
    uint32_t r = high % divisor;
    uint32_t q_low = 0;
    for (int bit = 31; bit >= 0; --bit) {
        r = (r << 1) | ((low >> bit) & 1u);  // r < divisor < 2³¹ before: no overflow
        q_low <<= 1;
        if (r >= divisor) {
            r -= divisor;
            q_low |= 1u;
        }
    }
    return static_cast<int64_t>((static_cast<uint64_t>(high / divisor) << 32) | q_low);
}

// What the engine calls: the plain division where the target divides 64 bits itself.
[[nodiscard]] inline int64_t time_quotient(int64_t t, int32_t d) noexcept {
#if defined(__x86_64__) || defined(__aarch64__)
    return t / d;
#else
    return time_quotient_in_32_bits(t, d);
#endif
}

}  // namespace feel::detail
