// A damper in closed loop: a hand drags the joystick slowly, at 2% of its reference speed,
// and meets a steady resistance on every tick. With the raw difference of sensor readings
// the same damper would read zero velocity on most ticks (0.4 count per tick) and push
// in bursts.
#include "friction_loop.hpp"

namespace feel::test {
namespace {

TEST(DamperClosedLoop, ASlowDragMeetsASteadyResistance) {
    EffectParams damper;
    damper.type = EffectType::damper;
    damper.duration_us = kInfiniteUs;
    damper.axis_count = 1;
    damper.axes[0] = Axis::x;
    damper.conditions[0].pos_coefficient = 10000;
    damper.conditions[0].neg_coefficient = 10000;
    // ramp over the 2 s render: 4000 units in 2 s = 2000 units/s = 2% of velocity_ref 1e5
    const auto rows = run_loop("joystick", sim::Grip::firm, "ramp:x:-2000:2000", {damper}, 2.0);

    int ticks = 0, raw_zero = 0, off = 0;
    double force_sum = 0, velocity_sum = 0;
    for (size_t i = 300; i < 1900; ++i) {  // past the start-up, before the end
        const LoopRow& r = rows[i];
        ++ticks;
        force_sum += r.force[0];
        velocity_sum += r.v[0];
        // b = 10000: force = -v·10000/velocity_ref = -v/10
        if (std::fabs(r.force[0] - (-r.v[0] / 10)) > 0.1 * 200) ++off;
        if (r.sensed[0] == rows[i - 1].sensed[0]) ++raw_zero;
    }
    const double mean_velocity = velocity_sum / ticks;
    EXPECT_NEAR(mean_velocity, 2000, 100);  // the hand does drag at 2% of velocity_ref
    EXPECT_NEAR(force_sum / ticks, -mean_velocity / 10, 0.05 * 200);
    EXPECT_EQ(off, 0);                  // every tick within 10% of -b·v
    EXPECT_GT(raw_zero, ticks / 2);     // a backward difference would read 0 on most ticks
}

}  // namespace
}  // namespace feel::test
