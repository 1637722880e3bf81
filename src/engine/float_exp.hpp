// e^x, e^x − 1 and tanh x in single precision, of + − × ÷ and conversions only (issue 14).
//
// The engine's friction, stop guard, contact surface and control laws need these three.
// libm's expf, expm1f and tanhf are different code on each platform (glibc on x86, newlib
// on the Cortex-M4F) and need not round alike, and newlib's, with their errno handling,
// took 1.3 KB of the board's flash (docs/firmware.md). These are one short piece of code
// both builds run, so x86 and the M4 compute the same bits.
//
// Method: x = k·ln 2 + r with k the nearest whole number to x/ln 2 (|r| ≤ ln 2/2 + a
// rounding), ln 2 split in two (Cody and Waite: ln2_hi has 15 significant bits, so k·ln2_hi
// is exact for |k| < 512 and x − k·ln2_hi exact by Sterbenz's lemma); e^r − 1 from its
// Taylor series to r⁷ (truncation below 5.6e-9 at |r| = 0.35, a twentieth of an ulp of
// e^r − 1 there), r + r²·(…) so that the leading term is exact; then e^x = 2^k·(1 + p), k
// added to the exponent's bits, and e^x − 1 = 2^k·p + (2^k − 1), both parts exact for
// −25 ≤ k ≤ 24, so the sum rounds once (beyond, e^x − 1 is e^x or −1 to the last bit).
// One body computes both (on the board: one copy of the reduction and the guards).
// tanh |x| = −e^(−2|x|) − 1 over 2 + (e^(−2|x|) − 1), its sign x's.
//
// Error bounds for results that are normal floats, against long double: the worst found on
// every float of [−20, −2^-10] and [2^-10, 20] and on 20000 random arguments in every other
// binade of the domain (a throwaway program) was 1.02, 1.77 and 2.50 ulps;
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

namespace feel::detail {

[[nodiscard]] float float_exp(float x) noexcept;
[[nodiscard]] float float_expm1(float x) noexcept;
[[nodiscard]] float float_tanh(float x) noexcept;

}  // namespace feel::detail
