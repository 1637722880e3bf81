// e^x, e^x − 1 and tanh x in single precision, of + − × ÷ and conversions only (issue 14).
//
// The engine's friction, stop guard, contact surface and control laws need these three.
// libm's expf, expm1f and tanhf are different code on each platform (glibc on x86, newlib
// on the Cortex-M4F) and need not round alike, and newlib's, with their errno handling,
// took 1.3 KB of the board's flash (docs/firmware.md). These are one short piece of code
// both builds run, so x86 and the M4 compute the same bits.
//
// Method: x = k·ln 2 + r with k the nearest whole number to x/ln 2 (adding 1.5·2^23 rounds
// it; |r| ≤ ln 2/2 + a rounding), ln 2 split in two (Cody and Waite: ln2_hi has 15
// significant bits, so k·ln2_hi is exact for |k| < 512 and x − k·ln2_hi exact by Sterbenz's
// lemma); e^r − 1 from its Taylor series to r⁷ (truncation below 5.6e-9 at |r| = 0.35, a
// twentieth of an ulp of e^r − 1 there), r + r²·(…) so that the leading term is exact; then
// e^x = 2^k·(1 + p), k added to the exponent's bits, and e^x − 1 = 2^k·p + (2^k − 1), both
// parts exact for −25 ≤ k ≤ 24, so the sum rounds once (beyond, e^x − 1 is e^x or −1 to
// the last bit). tanh |x| = −(e^(−2|x|) − 1) over 2 + (e^(−2|x|) − 1), its sign x's.
//
// Error bounds for results that are normal floats, against long double: the worst found on
// every 7th float of ±[2^-6, 89] and on 20000 random arguments in every other binade of the
// domain (a throwaway program) was 1.004, 1.735 and 2.493 ulps;
// tests/engine/float_exp_test.cpp checks the bounds below on every binade and at random:
//   float_exp    within 1.1 ulps (glibc's expf: 0.502)
//   float_expm1  within 2 ulps (the control laws' exact step needs 1 − e^(−γh) to its own
//                relative precision for small γh: docs/dynamics.md; there k = 0 and
//                p = r + r²·(…) with r = x exact)
//   float_tanh   within 3 ulps
// Special values: NaN gives NaN; e^x is +inf from 88.7228394 (the largest float is
// e^88.7228391) and 0 below −87.33, where it would be subnormal (libm gives the subnormal;
// no caller needs one); e^x − 1 is −1 below −17.4, e^±0 − 1 = ±0, tanh ±0 = ±0 and
// tanh ±inf = ±1.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace feel::detail {

// e^x, or e^x − 1 when minus_one. Inline, so that x86 specializes it at each call (a call
// costs its caller the spill of every live float register, which made friction's tick
// slower than with glibc's expf); the board calls one out-of-line copy (float_exp.cpp).
// The same operations either way, so the same bits.
[[nodiscard, gnu::always_inline]] inline float exp_or_expm1_inline(float x, bool minus_one) noexcept {
    constexpr float kLog2e = 1.44269504088896340736f;
    constexpr float kLn2Hi = 0x1.62e4p-1f;                // 0.693145751953125: 15 significant bits
    constexpr float kLn2Lo = 1.42860682030941723212e-6f;  // ln 2 − kLn2Hi
    constexpr float kLargest = 0x1.62e42ep+6f;            // 88.72283: the largest x with e^x below FLT_MAX
    constexpr float kSmallest = -87.33f;                  // e^x > FLT_MIN (2^-126 = e^-87.3365) above it
    constexpr float kMinusOne = -17.4f;                   // below: e^x < 2^-25, e^x − 1 rounds to −1
    constexpr float kRound = 0x1.8p23f;                   // adding it rounds a float below 2^22 to a whole number
    if (x != x) return x;
    if (x > kLargest) return std::numeric_limits<float>::infinity();
    if (minus_one) {
        if (x == 0.0f) return x;  // ±0, its sign kept
        if (x < kMinusOne) return -1.0f;
    } else if (x < kSmallest) {
        return 0.0f;  // no subnormal results
    }
    // x = k·ln 2 + r, k the nearest whole number to x/ln 2 (ties to even): |k| ≤ 128.
    const float fk = (x * kLog2e + kRound) - kRound;
    const int k = static_cast<int>(fk);
    const float r = (x - fk * kLn2Hi) - fk * kLn2Lo;
    // e^r − 1 for |r| ≤ 0.35: the Taylor series to r⁷, its leading term r exact.
    const float q = 0.5f + r * (1.0f / 6 + r * (1.0f / 24 + r * (1.0f / 120 + r * (1.0f / 720 + r * (1.0f / 5040)))));
    const float p = r + (r * r) * q;
    if (minus_one && k <= 24) {
        if (k == 0) return p;
        // 2^k·(1 + p) − 1 = 2^k·p + (2^k − 1): both parts exact for −25 ≤ k ≤ 24, so the sum
        // rounds once. (Beyond 2^24 the −1 is below half an ulp of e^x: below.)
        const float two_k = std::bit_cast<float>(static_cast<uint32_t>(k + 127) << 23);
        return two_k * p + (two_k - 1.0f);
    }
    // 2^k·(1 + p): 1 + p is in [0.7, 1.42] and the result a normal float (the guards), so
    // adding k to the exponent's bits is the exact multiplication.
    return std::bit_cast<float>(std::bit_cast<uint32_t>(1.0f + p) + (static_cast<uint32_t>(k) << 23));
}

#if defined(__x86_64__) || defined(__aarch64__)
[[nodiscard]] inline float float_exp(float x) noexcept { return exp_or_expm1_inline(x, false); }
[[nodiscard]] inline float float_expm1(float x) noexcept { return exp_or_expm1_inline(x, true); }
#else
[[nodiscard]] float float_exp(float x) noexcept;
[[nodiscard]] float float_expm1(float x) noexcept;
#endif
[[nodiscard]] float float_tanh(float x) noexcept;

// float_tanh's body, for a caller on x86 that would otherwise spill its floats around the
// call (the walls' rubbing, contact_surface.cpp); float_tanh is this, out of line.
[[nodiscard, gnu::always_inline]] inline float float_tanh_inline(float x) noexcept {
    constexpr float kTanhOne = 9.1f;  // above: 1 − tanh x < 2^-25, tanh rounds to 1
    if (x == 0.0f) return x;
    const float a = x < 0 ? -x : x;
    if (a > kTanhOne) return x < 0 ? -1.0f : 1.0f;
    const float t = float_expm1(-2.0f * a);  // NaN stays NaN
    const float magnitude = -t / (2.0f + t);
    return x < 0 ? -magnitude : magnitude;
}

}  // namespace feel::detail
