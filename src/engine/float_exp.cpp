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

float float_tanh(float x) noexcept { return float_tanh_inline(x); }

}  // namespace feel::detail
