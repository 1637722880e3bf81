// The board's double sin, cos, exp and expm1 (firmware/board_math.c) against glibc's, an
// independent implementation within 1 unit in the last place of the true value: within 2
// units of it over the engine's arguments and well beyond, and IEEE's special values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "board_math.h"

namespace {

// Distance in units in the last place (adjacent doubles are 1 apart, across zero too).
int64_t ulps_between(double a, double b) {
    auto key = [](double d) {
        int64_t i;
        std::memcpy(&i, &d, sizeof i);
        return i < 0 ? std::numeric_limits<int64_t>::min() - i : i;
    };
    const int64_t d = key(a) - key(b);
    return d < 0 ? -d : d;
}

struct Xorshift {
    uint64_t s = 88172645463325252ULL;
    double uniform() {  // [0, 1)
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        return static_cast<double>(s >> 11) * 0x1p-53;
    }
};

using Fn = double (*)(double);

// The worst distance from glibc over n arguments: a quarter uniform in [lo, hi], a quarter
// in [-10, 10], a quarter in [-1, 1], a quarter tiny (down to 2^-60).
int64_t worst_ulps(Fn board, Fn glibc, double lo, double hi, int n) {
    Xorshift r;
    int64_t worst = 0;
    for (int i = 0; i < n; ++i) {
        double x = 0;
        switch (i % 4) {
            case 0: x = lo + (hi - lo) * r.uniform(); break;
            case 1: x = (r.uniform() - 0.5) * 20; break;
            case 2: x = (r.uniform() - 0.5) * 2; break;
            default: x = std::ldexp(r.uniform() - 0.5, -static_cast<int>(r.uniform() * 60)); break;
        }
        worst = std::max(worst, ulps_between(board(x), glibc(x)));
    }
    return worst;
}

constexpr int kSamples = 400000;
constexpr double kInf = std::numeric_limits<double>::infinity();

double glibc_sin(double x) { return std::sin(x); }
double glibc_cos(double x) { return std::cos(x); }
double glibc_exp(double x) { return std::exp(x); }
double glibc_expm1(double x) { return std::expm1(x); }

TEST(BoardMath, SinAndCosWithinTwoUnitsOfGlibcUpToAMillion) {
    EXPECT_LE(worst_ulps(feel_board_sin, glibc_sin, -1e6, 1e6, kSamples), 2);
    EXPECT_LE(worst_ulps(feel_board_cos, glibc_cos, -1e6, 1e6, kSamples), 2);
}

TEST(BoardMath, ExpAndExpm1WithinTwoUnitsOfGlibcOverTheirWholeRange) {
    EXPECT_LE(worst_ulps(feel_board_exp, glibc_exp, -745.1, 709.78, kSamples), 2);
    EXPECT_LE(worst_ulps(feel_board_expm1, glibc_expm1, -45, 709.78, kSamples), 2);
}

TEST(BoardMath, ExactAtTheCardinalPointsWhereGlibcIs) {
    EXPECT_EQ(feel_board_sin(0.0), 0.0);
    EXPECT_TRUE(std::signbit(feel_board_sin(-0.0)));
    EXPECT_EQ(feel_board_cos(0.0), 1.0);
    EXPECT_EQ(feel_board_exp(0.0), 1.0);
    EXPECT_EQ(feel_board_expm1(0.0), 0.0);
    EXPECT_TRUE(std::signbit(feel_board_expm1(-0.0)));
    EXPECT_EQ(feel_board_sin(M_PI / 2), 1.0);
    EXPECT_EQ(feel_board_cos(M_PI), -1.0);
}

TEST(BoardMath, SpecialValuesAsIeeeSays) {
    EXPECT_TRUE(std::isnan(feel_board_sin(kInf)));
    EXPECT_TRUE(std::isnan(feel_board_cos(-kInf)));
    EXPECT_TRUE(std::isnan(feel_board_sin(std::nan(""))));
    EXPECT_TRUE(std::isnan(feel_board_exp(std::nan(""))));
    EXPECT_TRUE(std::isnan(feel_board_expm1(std::nan(""))));
    EXPECT_EQ(feel_board_exp(kInf), kInf);
    EXPECT_EQ(feel_board_exp(-kInf), 0.0);
    EXPECT_EQ(feel_board_exp(710.0), kInf);
    EXPECT_EQ(feel_board_exp(-746.0), 0.0);
    EXPECT_EQ(feel_board_expm1(kInf), kInf);
    EXPECT_EQ(feel_board_expm1(-kInf), -1.0);
    EXPECT_EQ(feel_board_expm1(-50.0), -1.0);
    // The largest finite result, and the smallest subnormal's neighbourhood.
    EXPECT_LE(ulps_between(feel_board_exp(709.78), std::exp(709.78)), 2);
    EXPECT_LE(ulps_between(feel_board_exp(-740.0), std::exp(-740.0)), 2);
}

TEST(BoardMath, HugeArgumentsGiveAFiniteSineAndCosine) {
    // Far beyond the engine's arguments the reduction is not to the last place, but the
    // result is a sine: finite, within [-1, 1], and sin^2 + cos^2 = 1.
    for (double x : {1e7, 1e15, 1e22, 1e300, -1e300, std::numeric_limits<double>::max()}) {
        const double s = feel_board_sin(x);
        const double c = feel_board_cos(x);
        EXPECT_TRUE(std::isfinite(s) && std::abs(s) <= 1.0) << x;
        EXPECT_NEAR(s * s + c * c, 1.0, 1e-15) << x;
    }
}

}  // namespace
