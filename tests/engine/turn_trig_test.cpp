// The tick's own sine (src/engine/turn_trig.hpp) against libm's double-precision sin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>

#include "turn_trig.hpp"

namespace feel::detail {
namespace {

TEST(TurnTrig, SineWithinTwoTenMillionthsOfDoubleSinOverSeveralTurns) {
    double worst = 0;
    for (int i = -3'000'000; i <= 3'000'000; ++i) {
        const float p = static_cast<float>(i) * 1e-6f;
        const double truth = std::sin(2.0 * std::numbers::pi * static_cast<double>(p));
        worst = std::max(worst, std::fabs(static_cast<double>(sin_turns(p)) - truth));
    }
    EXPECT_LT(worst, 2e-7);
}

// Adding the quarter turn rounds p + ¼ to float's spacing there (up to 6e-8 turn below 1.25
// turns), which moves the result by up to 2π·6e-8 = 3.7e-7 more.
TEST(TurnTrig, CosineIsTheSineAQuarterTurnLater) {
    for (int i = 0; i <= 100'000; ++i) {
        const float p = static_cast<float>(i) * 1e-5f;
        EXPECT_NEAR(cos_turns(p), std::cos(2.0 * std::numbers::pi * static_cast<double>(p)), 6e-7) << p;
    }
}

TEST(TurnTrig, ExactAtTheCrestsAndZeros) {
    for (float whole : {-2.0f, -1.0f, 0.0f, 1.0f, 3.0f}) {
        EXPECT_EQ(sin_turns(whole), 0.0f);
        EXPECT_EQ(sin_turns(whole + 0.5f), 0.0f);
        EXPECT_EQ(sin_turns(whole + 0.25f), 1.0f);
        EXPECT_EQ(sin_turns(whole + 0.75f), -1.0f);
        EXPECT_EQ(cos_turns(whole), 1.0f);
    }
}

TEST(TurnTrig, NeverBeyondOne) {
    for (int i = 0; i <= 1'000'000; ++i) {
        const float v = sin_turns(static_cast<float>(i) * 1e-6f);
        EXPECT_LE(std::fabs(v), 1.0f);
    }
}

// libm's roundf is the judge: every 1021st float (4.2 million, both signs, every exponent: the
// ties, the zeros, 2^23 and up, the infinities and NaN among them), and the halfway cases
// on either side of every whole number below 2^12. (All 2^32 floats agreed once, in 26 s.)
bool same_float(float a, float b) {
    uint32_t x = 0, y = 0;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    return x == y || (std::isnan(a) && std::isnan(b));
}

TEST(TurnTrig, RoundsAsRoundf) {
    int64_t mismatches = 0;
    for (uint64_t bits = 0; bits <= 0xffffffffu; bits += 1021) {
        const uint32_t b = static_cast<uint32_t>(bits);
        float x = 0;
        std::memcpy(&x, &b, sizeof x);
        mismatches += same_float(round_half_away(x), std::round(x)) ? 0 : 1;
    }
    for (int n = -4096; n <= 4096; ++n) {
        const float half = static_cast<float>(n) + 0.5f;
        for (float x : {half, std::nextafter(half, -1e9f), std::nextafter(half, 1e9f), -0.0f, 8388608.0f,
                        std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
            mismatches += same_float(round_half_away(x), std::round(x)) ? 0 : 1;
        }
    }
    EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace feel::detail
