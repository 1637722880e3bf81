// e^x, e^x − 1 and tanh x in single precision (float_exp.hpp has the method and the bounds).
#include "float_exp.hpp"

#include <bit>
#include <cstdint>
#include <limits>

namespace feel::detail {
namespace {

constexpr float kExpLog2e = 1.44269504088896340736f;
constexpr float kExpLn2Hi = 0x1.62e4p-1f;                // 0.693145751953125: 15 significant bits
constexpr float kExpLn2Lo = 1.42860682030941723212e-6f;  // ln 2 − kExpLn2Hi
constexpr float kExpLargest = 0x1.62e42ep+6f;         // 88.72283: the largest x with e^x below FLT_MAX
constexpr float kExpSmallest = -87.33f;               // e^x > FLT_MIN (2^-126 = e^-87.3365) above it
constexpr float kExpm1MinusOne = -17.4f;              // below: e^x < 2^-25, e^x − 1 rounds to −1
constexpr float kTanhOne = 9.1f;                      // above: 1 − tanh x < 2^-25, tanh rounds to 1

// e^r − 1 for |r| ≤ 0.35: the Taylor series to r⁷, its leading term r exact.
float exp_series_near_zero(float r) noexcept {
    const float q = 0.5f + r * (1.0f / 6 + r * (1.0f / 24 + r * (1.0f / 120 + r * (1.0f / 720 + r * (1.0f / 5040)))));
    return r + (r * r) * q;
}

// e^x, or e^x − 1 when minus_one: one body for both, so that the board carries one copy of
// the reduction and the guards.
[[gnu::noinline]] float exp_or_expm1(float x, bool minus_one) noexcept {
    if (x != x) return x;
    if (x > kExpLargest) return std::numeric_limits<float>::infinity();
    if (minus_one) {
        if (x == 0.0f) return x;  // ±0, its sign kept
        if (x < kExpm1MinusOne) return -1.0f;
    } else if (x < kExpSmallest) {
        return 0.0f;  // no subnormal results
    }
    // x = k·ln 2 + r, k the nearest whole number to x/ln 2 (ties either way): |k| ≤ 128.
    const float kf = x * kExpLog2e;
    const int k = static_cast<int>(kf + (kf < 0 ? -0.5f : 0.5f));  // conversion truncates
    const float fk = static_cast<float>(k);
    const float p = exp_series_near_zero((x - fk * kExpLn2Hi) - fk * kExpLn2Lo);
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

}  // namespace

float float_exp(float x) noexcept { return exp_or_expm1(x, false); }

float float_expm1(float x) noexcept { return exp_or_expm1(x, true); }

float float_tanh(float x) noexcept {
    if (x == 0.0f) return x;
    const float a = x < 0 ? -x : x;
    if (a > kTanhOne) return x < 0 ? -1.0f : 1.0f;
    const float t = float_expm1(-2.0f * a);  // NaN stays NaN
    const float magnitude = -t / (2.0f + t);
    return x < 0 ? -magnitude : magnitude;
}

}  // namespace feel::detail
