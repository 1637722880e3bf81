// Barrier pop-through in closed loop (§3.8, Figure 3-13): a firm hand pushes the handle
// slowly into a barrier; it resists until the handle is in by half the thickness, then
// flips and pops the handle through to the other side; and back again from that side.
//
// Independent truths: the primer's definition (the pop comes at half the thickness, the
// force flips direction there), and statics: moving slowly, the hand must push with the
// barrier's force K·t/2 to get the handle that deep, which the simulator measures at the
// hand without asking the engine.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact_loop.hpp"

namespace feel::test::loop {
namespace {

constexpr int32_t kThickness = 200;  // faces at ±100 around the center at 0
constexpr double kRampUnitsPerS = 2000;

struct Crossing {
    int pop_tick = -1;               // first tick whose sensed position is past the center
    double force_before = 0;         // engine force on the tick before the pop
    double force_after = 0;          // engine force on the pop tick
    double hand_before = 0;          // the hand's push on the tick before the pop, normalized
    double deepest_before = 0;       // deepest sensed penetration past the near face before the pop
    int ticks_to_far_face = -1;      // from the pop until the true position is past the far face
};

// The target ramps from `from` to `to` (x) at 2000 units/s (10 mm/s on the joystick).
Crossing cross(double from, double to) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const EngineConfig config = sim::engine_config_for(joystick);
    ClosedLoop loop(config);
    EffectParams barrier;
    barrier.type = EffectType::axis_barrier;
    barrier.axis_count = 1;
    barrier.axes[0] = Axis::x;
    barrier.barrier.pos_hardness = 10000;
    barrier.barrier.neg_hardness = 10000;
    barrier.barrier.thickness = kThickness;
    loop.play(barrier);

    const double seconds = std::fabs(to - from) / kRampUnitsPerS;
    const std::string spec =
        "ramp:x:" + std::to_string(static_cast<int>(from)) + ":" + std::to_string(static_cast<int>(to));
    sim::SimDevice device(joystick, sim::Grip::firm, sim::TargetMotion::parse(spec, seconds, 2));
    const double direction = to > from ? 1.0 : -1.0;
    const double near_face = -direction * kThickness / 2.0;
    const double far_face = direction * kThickness / 2.0;
    const double to_normalized = 10000.0 / joystick.axes[0].max_force;

    Crossing c;
    double previous_force = 0, previous_hand = 0;
    const int ticks = static_cast<int>(seconds * 1000) + 200;
    for (int n = 0; n < ticks; ++n) {
        TickInput sensed;
        device.sense(sensed);
        const TickOutput out = loop.tick(device);
        const double s = sensed.position[0];
        if (c.pop_tick < 0) {
            c.deepest_before = std::max(c.deepest_before, direction * (s - near_face));
            if (direction * s > 0) {
                c.pop_tick = n;
                c.force_before = previous_force;
                c.force_after = out.force[0];
                c.hand_before = previous_hand;
            }
        } else if (c.ticks_to_far_face < 0 && direction * (device.position(0) - far_face) > 0) {
            c.ticks_to_far_face = n - c.pop_tick;
        }
        previous_force = out.force[0];
        previous_hand = device.hand_force(0) * to_normalized;
    }
    return c;
}

void expect_pop(const Crossing& c, double direction) {
    const EngineConfig config = sim::engine_config_for(*sim::find_device_profile("joystick"));
    const double pop_force = config.wall_stiffness * kThickness / 2.0;  // K·t/2 at hardness 10000
    const double count = config.sensor_step;
    ASSERT_GE(c.pop_tick, 0) << "never popped";
    // It got in to half the thickness before popping, not sooner.
    EXPECT_GE(c.deepest_before, kThickness / 2.0 - count);
    // Just before the pop the barrier resisted with K·t/2 (within the force of a count and
    // a tick of motion); on the pop tick it pushed the other way, on through.
    EXPECT_NEAR(-direction * c.force_before, pop_force, 3 * config.wall_stiffness * count);
    EXPECT_GT(direction * c.force_after, 0.0);
    // The hand had to push that hard to get there (slow motion: statics, less the
    // mechanism's own 0.15 N = 337 units of friction, which helps hold the handle).
    EXPECT_NEAR(direction * c.hand_before, pop_force, 400 + 3 * config.wall_stiffness * count);
    // Popped: past the far face within 30 ms (the barrier and the hand both push it on).
    ASSERT_GE(c.ticks_to_far_face, 0);
    EXPECT_LE(c.ticks_to_far_face, 30);
}

TEST(BarrierPop, FromTheNegativeSide) { expect_pop(cross(-2500, 2500), 1.0); }

TEST(BarrierPop, FromThePositiveSide) { expect_pop(cross(2500, -2500), -1.0); }

TEST(BarrierPop, ThereAndBackAgain) {
    // One run: through to the positive side and back. The barrier remembers the side the
    // handle is on, so on the way back it is the positive face that resists.
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    ClosedLoop loop(sim::engine_config_for(joystick));
    EffectParams barrier;
    barrier.type = EffectType::axis_barrier;
    barrier.axis_count = 1;
    barrier.axes[0] = Axis::x;
    barrier.barrier.pos_hardness = 10000;
    barrier.barrier.neg_hardness = 10000;
    barrier.barrier.thickness = kThickness;
    loop.play(barrier);
    sim::SimDevice device(joystick, sim::Grip::firm, sim::TargetMotion::parse("sine:x:2500:0.25", 10.0, 2));
    int crossings = 0;
    double previous = 0;
    for (int n = 0; n < 10000; ++n) {
        const TickOutput out = loop.tick(device);
        const double x = device.position(0);
        // Inside the slab the force always points away from the center: the near face
        // holds the handle back until it passes the center, then the far face pushes it
        // on through.
        if (n > 0 && (previous < 0) != (x < 0)) ++crossings;
        if (std::fabs(x) < kThickness / 2.0 - 20 && std::fabs(x) > 20) {
            EXPECT_GT(out.force[0] * x, 0.0) << "tick " << n << " x=" << x << ": must point away from the center";
        }
        previous = x;
    }
    EXPECT_GE(crossings, 4) << "two full back-and-forth passes";
}

}  // namespace
}  // namespace feel::test::loop
