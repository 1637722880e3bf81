// summarize(): peak, time of peak, RMS and position range, against hand computations.
#include "feel/render/trace_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace feel::render {
namespace {

TraceRow row(int64_t t_us, float fx, float fy, float x, bool saturated = false) {
    TraceRow r;
    r.t_us = t_us;
    r.force[0] = fx;
    r.force[1] = fy;
    r.position[0] = x;
    r.saturated = saturated;
    return r;
}

TEST(TraceStats, PeakRmsAndRangeMatchTheirDefinitions) {
    Trace t;
    t.axis_count = 2;
    t.rate_hz = 1000;
    t.rows = {row(0, 3, 0, -10), row(1000, -4, 0, 25, true), row(2000, 4, 0, 5), row(3000, 0, 0, 0)};
    const TraceStats s = summarize(t);
    EXPECT_EQ(s.ticks, 4);
    EXPECT_DOUBLE_EQ(s.duration_s, 0.004);
    EXPECT_EQ(s.saturated_ticks, 1);
    EXPECT_DOUBLE_EQ(s.axes[0].peak_abs_force, 4);
    EXPECT_EQ(s.axes[0].peak_t_us, 1000);  // the first time |f| reaches the peak
    EXPECT_DOUBLE_EQ(s.axes[0].rms_force, std::sqrt((9.0 + 16 + 16 + 0) / 4));
    EXPECT_DOUBLE_EQ(s.axes[0].min_position, -10);
    EXPECT_DOUBLE_EQ(s.axes[0].max_position, 25);
    EXPECT_DOUBLE_EQ(s.axes[1].peak_abs_force, 0);
    EXPECT_DOUBLE_EQ(s.axes[1].rms_force, 0);
}

TEST(TraceStats, AnEmptyTraceGivesZeros) {
    Trace t;
    t.axis_count = 3;
    t.rate_hz = 1000;
    const TraceStats s = summarize(t);
    EXPECT_EQ(s.ticks, 0);
    EXPECT_EQ(s.duration_s, 0);
    EXPECT_EQ(s.axes[2].peak_abs_force, 0);
}

}  // namespace
}  // namespace feel::render
