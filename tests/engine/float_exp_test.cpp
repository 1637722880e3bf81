// The engine's own e^x, e^x − 1 and tanh x (src/engine/float_exp.hpp) against long double
// libm, in ulps of the float result, over every binade of their domains; and the special
// values. A result below the smallest normal float is judged in units of the smallest
// normal's ulp (2^-126 · 2^-23); e^x gives none (0 below −87.33).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "float_exp.hpp"

namespace feel::detail {
namespace {

// |f − truth| in ulps of the float nearest the truth.
double exp_ulps_off(float f, long double truth) {
    int e = truth == 0 ? -126 : std::ilogb(truth);
    if (e < -126) e = -126;
    return static_cast<double>(std::fabs(static_cast<long double>(f) - truth) / std::ldexp(1.0L, e - 23));
}

struct ExpWorst {
    double exp = 0, expm1 = 0, tanh = 0;
};

// Every result's error, over [lo, hi] (exp only where e^x is a normal float).
void measure_exp_family(float x, ExpWorst& w) {
    const long double lx = x;
    if (x > -87.33f && x < 88.72f) w.exp = std::max(w.exp, exp_ulps_off(float_exp(x), std::exp(lx)));
    if (x < 88.72f) w.expm1 = std::max(w.expm1, exp_ulps_off(float_expm1(x), std::expm1(lx)));
    w.tanh = std::max(w.tanh, exp_ulps_off(float_tanh(x), std::tanh(lx)));
}

// 1000 random floats in each binade [2^e, 2^(e+1)) of either sign, from the smallest
// subnormal's up to the overflow of e^x (|x| < 128).
TEST(FloatExp, WithinTheirBoundsOnEveryBinade) {
    std::mt19937 rng(14);
    ExpWorst w;
    for (int sign : {1, -1}) {
        for (int e = -149; e <= 6; ++e) {
            for (int i = 0; i < 1000; ++i) {
                const uint32_t m = rng() & 0x7fffffu;
                const float x = e < -126 ? std::ldexp(static_cast<float>(m | 1u), -149)
                                         : std::ldexp(1.0f + static_cast<float>(m) * 0x1p-23f, e);
                measure_exp_family(static_cast<float>(sign) * x, w);
            }
        }
    }
    EXPECT_LE(w.exp, 1.1);
    EXPECT_LE(w.expm1, 2.0);
    EXPECT_LE(w.tanh, 3.0);
}

// Where the reduction changes k (x near (k + ½)·ln 2) and at the thresholds, every float
// within 64 ulps either side.
TEST(FloatExp, WithinTheirBoundsWhereTheReductionChangesItsMultiple) {
    ExpWorst w;
    for (int k = -40; k <= 40; ++k) {
        float x = static_cast<float>((k + 0.5L) * 0.693147180559945309417L);
        for (int i = 0; i < 64; ++i) x = std::nextafter(x, -std::numeric_limits<float>::infinity());
        for (int i = 0; i < 128; ++i, x = std::nextafter(x, std::numeric_limits<float>::infinity())) measure_exp_family(x, w);
    }
    for (float edge : {-17.4f, -9.1f, 9.1f, 16.6f, 17.4f, 88.7f}) {
        float x = edge;
        for (int i = 0; i < 64; ++i) x = std::nextafter(x, -std::numeric_limits<float>::infinity());
        for (int i = 0; i < 128; ++i, x = std::nextafter(x, std::numeric_limits<float>::infinity())) measure_exp_family(x, w);
    }
    EXPECT_LE(w.exp, 1.1);
    EXPECT_LE(w.expm1, 2.0);
    EXPECT_LE(w.tanh, 3.0);
}

RC_GTEST_PROP(FloatExp, AnyFloatWithinItsBounds, (uint32_t bits)) {
    const float x = std::bit_cast<float>(bits);
    RC_PRE(std::isfinite(x) && std::fabs(x) < 88.0f);
    ExpWorst w;
    measure_exp_family(x, w);
    RC_ASSERT(w.exp <= 1.1);
    RC_ASSERT(w.expm1 <= 2.0);
    RC_ASSERT(w.tanh <= 3.0);
}

TEST(FloatExp, SpecialValues) {
    EXPECT_EQ(float_exp(0.0f), 1.0f);
    EXPECT_EQ(float_exp(-0.0f), 1.0f);
    EXPECT_EQ(float_exp(89.0f), std::numeric_limits<float>::infinity());
    EXPECT_EQ(float_exp(std::numeric_limits<float>::infinity()), std::numeric_limits<float>::infinity());
    EXPECT_EQ(float_exp(-std::numeric_limits<float>::infinity()), 0.0f);
    EXPECT_EQ(float_exp(-104.5f), 0.0f);
    EXPECT_EQ(float_exp(-87.34f), 0.0f);  // no subnormal results
    EXPECT_GE(float_exp(-87.33f), std::numeric_limits<float>::min());
    EXPECT_TRUE(std::isnan(float_exp(std::nanf(""))));
    // the largest float's neighbourhood: finite below ln(FLT_MAX), inf above
    EXPECT_EQ(float_exp(0x1.62e42ep+6f), 0x1.ffff08p+127f);  // e^88.7228317 within an ulp
    EXPECT_EQ(float_exp(0x1.62e430p+6f), std::numeric_limits<float>::infinity());                // e^88.7228394 > the largest float

    EXPECT_EQ(std::bit_cast<uint32_t>(float_expm1(0.0f)), std::bit_cast<uint32_t>(0.0f));
    EXPECT_EQ(std::bit_cast<uint32_t>(float_expm1(-0.0f)), std::bit_cast<uint32_t>(-0.0f));
    EXPECT_EQ(float_expm1(-18.0f), -1.0f);
    EXPECT_EQ(float_expm1(-std::numeric_limits<float>::infinity()), -1.0f);
    EXPECT_EQ(float_expm1(std::numeric_limits<float>::infinity()), std::numeric_limits<float>::infinity());
    EXPECT_TRUE(std::isnan(float_expm1(std::nanf(""))));
    const float tiny = std::numeric_limits<float>::denorm_min();
    EXPECT_EQ(float_expm1(tiny), tiny);  // e^x − 1 = x to far below an ulp
    EXPECT_EQ(float_expm1(-1e-30f), -1e-30f);

    EXPECT_EQ(std::bit_cast<uint32_t>(float_tanh(-0.0f)), std::bit_cast<uint32_t>(-0.0f));
    EXPECT_EQ(float_tanh(std::numeric_limits<float>::infinity()), 1.0f);
    EXPECT_EQ(float_tanh(-std::numeric_limits<float>::infinity()), -1.0f);
    EXPECT_EQ(float_tanh(10.0f), 1.0f);
    EXPECT_EQ(float_tanh(1e-30f), 1e-30f);
    EXPECT_TRUE(std::isnan(float_tanh(std::nanf(""))));
}

// Never out of range: e^x ≥ 0, e^x − 1 ≥ −1, |tanh x| ≤ 1, and each monotone on a grid.
TEST(FloatExp, InRangeAndMonotone) {
    float last_exp = 0, last_expm1 = -1, last_tanh = -1;
    for (int i = -200000; i <= 200000; ++i) {
        const float x = static_cast<float>(i) * 4e-4f;
        const float e = float_exp(x), m = float_expm1(x), t = float_tanh(x);
        ASSERT_GE(e, last_exp) << x;
        ASSERT_GE(m, last_expm1) << x;
        ASSERT_GE(t, last_tanh) << x;
        ASSERT_LE(std::fabs(t), 1.0f);
        last_exp = e;
        last_expm1 = m;
        last_tanh = t;
    }
}

}  // namespace
}  // namespace feel::detail
