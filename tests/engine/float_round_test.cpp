// round_half_away and next_float (src/engine/float_round.hpp) against std::round and
// std::nextafter, bit for bit: every float of several binades, the edges, and any float;
// nearest_multiple_index against std::round of the quotient.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "float_round.hpp"

namespace feel::detail {
namespace {

uint32_t round_test_bits(float x) { return std::bit_cast<uint32_t>(x); }

void expect_rounding_like_libm(float x) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    ASSERT_EQ(round_test_bits(round_half_away(x)), round_test_bits(std::round(x))) << x;
    ASSERT_EQ(round_test_bits(next_float(x, true)), round_test_bits(std::nextafter(x, kInf))) << x;
    ASSERT_EQ(round_test_bits(next_float(x, false)), round_test_bits(std::nextafter(x, -kInf))) << x;
}

// Every 13th float whose magnitude is in [2^-1, 4) (the halves and the fractions around
// them) or in [2^22, 2^23) (the last fractions), both signs; and every 997th half k + ½
// below 2^22 with the floats either side of it.
TEST(FloatRound, EqualsLibmOnTheBinadesWhereItMatters) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    int64_t differ = 0;
    const auto compare = [&](float x) {
        differ += round_test_bits(round_half_away(x)) != round_test_bits(std::round(x));
        differ += round_test_bits(next_float(x, true)) != round_test_bits(std::nextafter(x, kInf));
        differ += round_test_bits(next_float(x, false)) != round_test_bits(std::nextafter(x, -kInf));
    };
    for (const auto& [lo, hi] : {std::pair{0x1p-1f, 0x1p2f}, std::pair{0x1p22f, 0x1p23f}}) {
        for (uint32_t b = round_test_bits(lo); b < round_test_bits(hi); b += 13) {
            compare(std::bit_cast<float>(b));
            compare(-std::bit_cast<float>(b));
        }
    }
    for (int32_t k = 0; k < (1 << 22); k += 997) {
        const float half = static_cast<float>(k) + 0.5f;
        for (const float x : {half, std::nextafter(half, 0.0f), std::nextafter(half, kInf)}) {
            compare(x);
            compare(-x);
        }
    }
    EXPECT_EQ(differ, 0);
}

// Every 1021st float of the whole range, both signs and every binade (the check over all
// 2^32 was run once, docs/tick-cost.md); with the halves k + ½ below 4096 and their
// neighbours.
TEST(FloatRound, RoundsAsLibmAcrossEveryBinade) {
    int64_t differ = 0;
    for (uint64_t bits = 0; bits <= 0xffffffffu; bits += 1021) {
        const float x = std::bit_cast<float>(static_cast<uint32_t>(bits));
        differ += x == x && round_test_bits(round_half_away(x)) != round_test_bits(std::round(x));
    }
    for (int n = -4096; n <= 4096; ++n) {
        const float half = static_cast<float>(n) + 0.5f;
        for (const float x : {half, std::nextafter(half, -1e9f), std::nextafter(half, 1e9f)}) {
            differ += round_test_bits(round_half_away(x)) != round_test_bits(std::round(x));
        }
    }
    EXPECT_EQ(differ, 0);
}

TEST(FloatRound, EqualsLibmAtTheEdges) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (float x : {0.0f, -0.0f, 0.5f, -0.5f, 0.49999997f, -0.49999997f, 1.5f, -2.5f, 8388607.5f, 8388608.0f,
                    std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::denorm_min(),
                    std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
                    -std::numeric_limits<float>::max(), kInf, -kInf}) {
        expect_rounding_like_libm(x);
    }
    EXPECT_TRUE(std::isnan(round_half_away(std::nanf(""))));
    EXPECT_TRUE(std::isnan(next_float(std::nanf(""), true)));
}

// nearest_multiple_index(x, step, 1/step) is std::round(x / step) but for the sign of a zero:
// every 1021st float, and the floats at and either side of x = (n + ½)·step, where the
// product x·(1/step) may round across the half (the case its fast way must give up), for
// the bumps' spacings (the walls' 200, the busy mix's texture 400) and some others.
TEST(FloatRound, NearestMultipleIndexIsTheRoundedQuotient) {
    int64_t differ = 0;
    const auto compare = [&](float x, float step) {
        const float index = nearest_multiple_index(x, step, 1.0f / step);
        const float quotient = std::round(x / step);
        differ += x == x && !(index == quotient);  // (+0 == −0: the sign of a zero is not compared)
    };
    for (const float step : {200.0f, 400.0f, 1.0f, 3.0f, 7.0f, 1000.0f, 32767.0f}) {
        for (uint64_t bits = 0; bits <= 0xffffffffu; bits += 1021) {
            compare(std::bit_cast<float>(static_cast<uint32_t>(bits)), step);
        }
        for (int n = -3000; n <= 3000; ++n) {
            float x = (static_cast<float>(n) + 0.5f) * step;
            for (int k = 0; k < 4; ++k) x = std::nextafter(x, -1e30f);
            for (int k = 0; k < 9; ++k, x = std::nextafter(x, 1e30f)) compare(x, step);
        }
    }
    EXPECT_EQ(differ, 0);
    EXPECT_TRUE(std::isnan(nearest_multiple_index(std::nanf(""), 200.0f, 1.0f / 200.0f)));
    EXPECT_EQ(nearest_multiple_index(std::numeric_limits<float>::infinity(), 200.0f, 1.0f / 200.0f),
              std::numeric_limits<float>::infinity());
}

RC_GTEST_PROP(FloatRound, AnyFloatLikeLibm, (uint32_t b)) {
    const float x = std::bit_cast<float>(b);
    RC_PRE(x == x);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    RC_ASSERT(round_test_bits(round_half_away(x)) == round_test_bits(std::round(x)));
    RC_ASSERT(round_test_bits(next_float(x, true)) == round_test_bits(std::nextafter(x, kInf)));
    RC_ASSERT(round_test_bits(next_float(x, false)) == round_test_bits(std::nextafter(x, -kInf)));
}

}  // namespace
}  // namespace feel::detail
