// Tick arithmetic for plots: steps of 1, 2, 2.5 or 5 times a power of ten.
#include "plot_scale.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace feel::render::detail {
namespace {

TEST(PlotScale, NiceStepsAreOneTwoTwoAndAHalfOrFiveTimesAPowerOfTen) {
    EXPECT_DOUBLE_EQ(nice_step(10000, 5), 2000);  // raw 2000
    EXPECT_DOUBLE_EQ(nice_step(1, 4), 0.25);      // raw 0.25
    EXPECT_DOUBLE_EQ(nice_step(7, 5), 2);         // raw 1.4 -> 2
    EXPECT_DOUBLE_EQ(nice_step(30, 10), 5);       // raw 3 -> 5
    EXPECT_DOUBLE_EQ(nice_step(600, 10), 100);    // raw 60 -> 100
    EXPECT_DOUBLE_EQ(nice_step(0.003, 3), 0.001);
}

TEST(PlotScale, ANiceScaleCoversTheDataWithWholeSteps) {
    const Scale s = nice_scale(-3000, 7000, 5);
    EXPECT_DOUBLE_EQ(s.step, 2000);
    EXPECT_DOUBLE_EQ(s.lo, -4000);
    EXPECT_DOUBLE_EQ(s.hi, 8000);
    EXPECT_EQ(s.ticks(), (std::vector<double>{-4000, -2000, 0, 2000, 4000, 6000, 8000}));
}

TEST(PlotScale, TheTightestScaleWastesTheLeastRoom) {
    // Target 4..5 give step 500 and [-1000, 1000]; target 7 gives 250 and [-750, 1000].
    const Scale s = nice_scale(-657, 877, 4, 7);
    EXPECT_DOUBLE_EQ(s.step, 250);
    EXPECT_DOUBLE_EQ(s.lo, -750);
    EXPECT_DOUBLE_EQ(s.hi, 1000);
    // Already tight at the first target: keep the fewest intervals.
    const Scale full = nice_scale(-10000, 10000, 4, 7);
    EXPECT_DOUBLE_EQ(full.lo, -10000);
    EXPECT_DOUBLE_EQ(full.hi, 10000);
    EXPECT_DOUBLE_EQ(full.step, 5000);
}

TEST(PlotScale, ADegenerateRangeIsWidenedAroundItsValue) {
    const Scale zero = nice_scale(0, 0, 4);
    EXPECT_LT(zero.lo, 0);
    EXPECT_GT(zero.hi, 0);
    const Scale flat = nice_scale(500, 500, 4);
    EXPECT_LE(flat.lo, 250);
    EXPECT_GE(flat.hi, 750);
}

TEST(PlotScale, AnExactScaleKeepsItsEndsAndTicksInside) {
    const Scale s = exact_scale(0, 1099, 10);
    EXPECT_EQ(s.lo, 0);
    EXPECT_EQ(s.hi, 1099);
    EXPECT_DOUBLE_EQ(s.step, 200);  // raw 109.9 -> 200
    EXPECT_EQ(s.ticks(), (std::vector<double>{0, 200, 400, 600, 800, 1000}));
}

TEST(PlotScale, TickLabelsUseTheDecimalsTheStepNeedsAndARealMinus) {
    EXPECT_EQ(tick_label(-2000, 2000), "\u22122000");
    EXPECT_EQ(tick_label(0.25, 0.25), "0.25");
    EXPECT_EQ(tick_label(2.5, 2.5), "2.5");
    EXPECT_EQ(tick_label(1, 0.5), "1.0");
    EXPECT_EQ(tick_label(0, 0.5), "0.0");
    EXPECT_EQ(tick_label(-1e-12, 0.5), "0.0");  // no "-0.0" from rounding
}

}  // namespace
}  // namespace feel::render::detail
