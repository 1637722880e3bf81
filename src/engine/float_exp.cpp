// e^x, e^x − 1 and tanh x in single precision (float_exp.hpp has the method and the bounds).
#include "float_exp.hpp"

namespace feel::detail {

#if !(defined(__x86_64__) || defined(__aarch64__))
namespace {
// One copy of the body for both (the board's flash).
[[gnu::noinline]] float exp_or_expm1(float x, bool minus_one) noexcept { return exp_or_expm1_inline(x, minus_one); }
}  // namespace

float float_exp(float x) noexcept { return exp_or_expm1(x, false); }

float float_expm1(float x) noexcept { return exp_or_expm1(x, true); }
#endif

float float_tanh(float x) noexcept {
    constexpr float kTanhOne = 9.1f;  // above: 1 − tanh x < 2^-25, tanh rounds to 1
    if (x == 0.0f) return x;
    const float a = x < 0 ? -x : x;
    if (a > kTanhOne) return x < 0 ? -1.0f : 1.0f;
    const float t = float_expm1(-2.0f * a);  // NaN stays NaN
    const float magnitude = -t / (2.0f + t);
    return x < 0 ? -magnitude : magnitude;
}

}  // namespace feel::detail
