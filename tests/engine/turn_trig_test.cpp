// The tick's own sine (src/engine/turn_trig.hpp) against libm's double-precision sin.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "turn_trig.hpp"

namespace feel::detail {
namespace {

// The largest difference of sine(p) from double-precision sin(2πp) over ±3 turns.
double worst_error_over_several_turns(float (*sine)(float)) {
    double worst = 0;
    for (int i = -3'000'000; i <= 3'000'000; ++i) {
        const float p = static_cast<float>(i) * 1e-6f;
        const double truth = std::sin(2.0 * std::numbers::pi * static_cast<double>(p));
        worst = std::max(worst, std::fabs(static_cast<double>(sine(p)) - truth));
    }
    return worst;
}

void expect_exact_at_the_crests_and_zeros(float (*sine)(float)) {
    for (float whole : {-2.0f, -1.0f, 0.0f, 1.0f, 3.0f}) {
        EXPECT_EQ(sine(whole), 0.0f);
        EXPECT_EQ(sine(whole + 0.5f), 0.0f);
        EXPECT_EQ(sine(whole + 0.25f), 1.0f);
        EXPECT_EQ(sine(whole + 0.75f), -1.0f);
    }
}

TEST(TurnTrig, SineWithinTwoTenMillionthsOfDoubleSinOverSeveralTurns) {
    EXPECT_LT(worst_error_over_several_turns(sin_turns), 2e-7);
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
    expect_exact_at_the_crests_and_zeros(sin_turns);
    for (float whole : {-2.0f, -1.0f, 0.0f, 1.0f, 3.0f}) EXPECT_EQ(cos_turns(whole), 1.0f);
}

TEST(TurnTrig, NeverBeyondOne) {
    for (int i = 0; i <= 1'000'000; ++i) {
        const float v = sin_turns(static_cast<float>(i) * 1e-6f);
        EXPECT_LE(std::fabs(v), 1.0f);
    }
}

// The periodic waves' form, without jumps on x86: the same bounds against the same truth.
TEST(TurnTrig, SineWithoutJumpsWithinTwoTenMillionthsOfDoubleSinOverSeveralTurns) {
    EXPECT_LT(worst_error_over_several_turns(sin_turns_without_jumps), 2e-7);
}

TEST(TurnTrig, SineWithoutJumpsExactAtTheCrestsAndZeros) {
    expect_exact_at_the_crests_and_zeros(sin_turns_without_jumps);
}

// The periodic's form (on x86 in the lanes of an SSE register, float_lanes.hpp) and the jumps'
// form (the board's, and every other caller's) are to be the same float for every argument
// the tick passes (|p| < 2^22 turns): the forces of x86 and the board agree bit for bit only
// so. Every 4093rd float of each sign below 2^22 (0.6 million, every binade), and the steps
// of the reduction: the half turns, the quarter and the eighth turns and their neighbours.
TEST(TurnTrig, SineWithoutJumpsIsTheSineWithJumpsToTheBit) {
    const auto expect_same = [](float p) {
        ASSERT_EQ(std::bit_cast<uint32_t>(sin_turns_without_jumps(p)), std::bit_cast<uint32_t>(sin_turns(p))) << p;
    };
    const uint32_t below = std::bit_cast<uint32_t>(4194304.0f);
    for (uint32_t bits = 0; bits < below; bits += 4093) {
        expect_same(std::bit_cast<float>(bits));
        expect_same(-std::bit_cast<float>(bits));
    }
    for (int eighth = -64; eighth <= 64; ++eighth) {
        const float p = static_cast<float>(eighth) * 0.125f;
        expect_same(p);
        expect_same(std::nextafter(p, 1e9f));
        expect_same(std::nextafter(p, -1e9f));
    }
}

}  // namespace
}  // namespace feel::detail
