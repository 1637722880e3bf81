// int64 → float, correctly rounded, without a 64-bit conversion instruction.
//
// static_cast<float>(int64_t) rounds to the nearest float, ties to even, on every IEEE
// target; x86-64 does it in one instruction (cvtsi2ss), but a Cortex-M4F's FPU converts only
// 32-bit integers, so the cast there is libgcc's __aeabi_l2f, whose object also brings the
// soft-float add it uses (about 540 bytes of flash for the few call sites: the tick length,
// the estimator's times and sums, the passivity ledger).
//
// float_of_int64 gives the same bits from one 32-bit conversion. A value that fits int32 is
// converted directly. A larger magnitude m (2³¹ ≤ m ≤ 2⁶³) is converted as an unsigned
// 32-bit value (the FPU converts those too): m itself when it fits, else its top 32 bits,
// [2³¹, 2³²), with every bit shifted out ORed into the lowest kept bit (a sticky bit). A
// float keeps 24 of those 32 bits, so the rounding bit is bit 7 of the kept value and bits
// 0..6 only say "something below it is set": ORing the dropped bits into bit 0 keeps that
// answer, and the FPU's conversion (round to nearest even, the default mode) rounds the kept
// value exactly as it would round m. Multiplying by 2^s (1 ≤ s ≤ 32, the bits dropped) is
// exact, and so is the sign. Working on m's two 32-bit words, not shifting it as a 64-bit
// value, keeps it at about half the Thumb code (issue 14's flash).
// tests/engine/int64_to_float_test.cpp checks it against the cast at the boundaries and on
// random values.
#pragma once

#include <bit>
#include <cstdint>

namespace feel::detail {

// The conversion by one int32 → float; out of line, since the firmware calls it from several
// places and flash is what it saves. Public so the x86 test can check it against the cast.
[[gnu::noinline]] inline float float_of_int64_by_int32(int64_t v) noexcept {
    if (v >= INT32_MIN && v <= INT32_MAX) return static_cast<float>(static_cast<int32_t>(v));
    const bool negative = v < 0;
    const uint64_t m = negative ? uint64_t{0} - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
    const auto high = static_cast<uint32_t>(m >> 32);
    const auto low = static_cast<uint32_t>(m);
    float f = static_cast<float>(low);  // correctly rounded when m < 2³²
    if (high != 0) {
        const int z = std::countl_zero(high);  // 0..31: s = 32 − z bits of low are dropped
        const uint32_t kept = (high << z) | ((low >> 1) >> (31 - z)) | ((low << z) != 0 ? 1u : 0u);
        const float scale = std::bit_cast<float>(static_cast<uint32_t>(127 + 32 - z) << 23);  // 2^s
        f = static_cast<float>(kept) * scale;
    }
    return negative ? -f : f;
}

// What the engine calls: the plain cast where the target converts 64-bit integers itself.
[[nodiscard]] inline float float_of_int64(int64_t v) noexcept {
#if defined(__x86_64__) || defined(__aarch64__)
    return static_cast<float>(v);
#else
    return float_of_int64_by_int32(v);
#endif
}

}  // namespace feel::detail
