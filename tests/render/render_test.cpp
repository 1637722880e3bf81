// render(): the closed loop of engine and simulated device, checked against the
// definitions of the primer and the conventions of docs/conventions.md.
#include "feel/render/render.hpp"

#include <sstream>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sensation_builders.hpp"

namespace feel::render {
namespace {

using format::Sensation;
using testing::axis_constant;
using testing::constant_wave;
using testing::profile;
using testing::single;

RenderOptions kinematic_hold(const char* device, double duration_s, double rate_hz = 1000) {
    RenderOptions o;
    o.profile = &profile(device);
    o.grip = sim::Grip::kinematic;
    o.motion = "hold:0";
    o.duration_s = duration_s;
    o.rate_hz = rate_hz;
    return o;
}

// §6.6.c: a constant force of magnitude M and gain G pushes with M·G/10000. Polar 9000
// names a force coming FROM +x, so it pushes toward -x: fx = -M·G/10000, fy = 0.
TEST(Render, VectorForceFromEastPushesTowardMinusXWithMagnitudeTimesGain) {
    const int64_t duration_us = 300'000;
    const Sensation s = single("push_west", constant_wave(EffectType::vector_force, 6000, 5000,
                                                          9000, duration_us));
    const Trace trace = render(s, kinematic_hold("joystick", 0.5));

    ASSERT_EQ(trace.axis_count, 2);
    ASSERT_EQ(trace.rows.size(), 500u);  // 0.5 s × 1000 Hz
    const double expected = -6000.0 * 5000.0 / 10000.0;
    for (const TraceRow& row : trace.rows) {
        if (row.t_us < duration_us) {
            EXPECT_NEAR(row.force[0], expected, 0.5) << "t_us = " << row.t_us;
            EXPECT_NEAR(row.force[1], 0.0, 0.5) << "t_us = " << row.t_us;
        } else if (row.t_us > duration_us) {  // the effect has ended: no force at all
            EXPECT_EQ(row.force[0], 0.0f) << "t_us = " << row.t_us;
            EXPECT_EQ(row.force[1], 0.0f) << "t_us = " << row.t_us;
        }
        // A kinematic hand holds the handle exactly at the target.
        EXPECT_EQ(row.position[0], 0.0f);
        EXPECT_EQ(row.position[1], 0.0f);
    }
}

// Polar 18000 is a force from the south (-y): it pushes toward +y. 4500 comes from the
// north-east and pushes toward -x and -y with cos 45° on each.
TEST(Render, ConstantForceFollowsTheCompassConvention) {
    {
        const Sensation s = single("push_north", constant_wave(EffectType::constant, 8000,
                                                               10000, 18000, 200'000));
        const Trace trace = render(s, kinematic_hold("joystick", 0.1));
        for (const TraceRow& row : trace.rows) {
            EXPECT_NEAR(row.force[0], 0.0, 0.5);
            EXPECT_NEAR(row.force[1], 8000.0, 0.5);
        }
    }
    {
        const Sensation s = single("push_south_west", constant_wave(EffectType::constant, 10000,
                                                                    10000, 4500, 200'000));
        const Trace trace = render(s, kinematic_hold("3axis", 0.1));
        const double component = -10000.0 * std::sqrt(0.5);
        for (const TraceRow& row : trace.rows) {
            EXPECT_NEAR(row.force[0], component, 0.5);
            EXPECT_NEAR(row.force[1], component, 0.5);
            EXPECT_EQ(row.force[2], 0.0f);
        }
    }
}

// With no direction, a single-axis effect's magnitude carries the physical sign.
TEST(Render, AxisConstantOnAWheelKeepsItsSign) {
    const Sensation s = single("left", axis_constant(Axis::x, -2500, 100'000));
    const Trace trace = render(s, kinematic_hold("wheel", 0.05));
    ASSERT_EQ(trace.axis_count, 1);
    for (const TraceRow& row : trace.rows) EXPECT_NEAR(row.force[0], -2500.0, 0.5);
}

// Newton: a free handle pushed toward +x starts moving toward +x, and one pushed toward
// -x moves toward -x. This closes the loop: the force the engine computes moves the device.
TEST(Render, AFreeHandleMovesTheWayTheForcePushes) {
    for (int32_t magnitude : {6000, -6000}) {
        const Sensation s = single("shove", axis_constant(Axis::x, magnitude, kInfiniteUs));
        RenderOptions o;
        o.profile = &profile("wheel");
        o.grip = sim::Grip::none;
        o.duration_s = 0.1;
        const Trace trace = render(s, o);
        const TraceRow& last = trace.rows.back();
        const double sign = magnitude > 0 ? 1 : -1;
        EXPECT_GT(sign * last.position[0], 0.0f) << "magnitude " << magnitude;
        EXPECT_GT(sign * last.velocity[0], 0.0f) << "magnitude " << magnitude;
        EXPECT_EQ(trace.rows.front().position[0], 0.0f);  // it starts at rest at the center
    }
}

TEST(Render, RowCountIsDurationTimesRateAndTimesAreExact) {
    const Sensation s = single("hum", axis_constant(Axis::x, 1000, kInfiniteUs));
    const Trace trace = render(s, kinematic_hold("joystick", 0.3, 500));
    ASSERT_EQ(trace.rows.size(), 150u);
    EXPECT_EQ(trace.rate_hz, 500.0);
    for (size_t n = 0; n < trace.rows.size(); ++n) {
        ASSERT_EQ(trace.rows[n].t_us, static_cast<int64_t>(n) * 2000);
    }
    EXPECT_EQ(trace.rows.front().t_us, 0);
    EXPECT_EQ(trace.rows.back().t_us, 298'000);
}

// 300 Hz does not divide a second into whole µs: tick n is at round(n·1e6/300).
TEST(Render, ARateThatDoesNotDivideASecondRoundsEachTickToTheNearestMicrosecond) {
    const Sensation s = single("hum", axis_constant(Axis::x, 1000, kInfiniteUs));
    const Trace trace = render(s, kinematic_hold("joystick", 1.0, 300));
    ASSERT_EQ(trace.rows.size(), 300u);
    for (size_t n = 0; n < trace.rows.size(); ++n) {
        const auto expected = static_cast<int64_t>(std::llround(static_cast<double>(n) * 1e6 / 300));
        ASSERT_EQ(trace.rows[n].t_us, expected) << "tick " << n;
    }
    EXPECT_EQ(trace.rows.back().t_us, 996'667);
}

TEST(Render, DefaultDurationIsTheSensationPlusATail) {
    // 300 ms: the tail is at least 100 ms.
    const Sensation short_one = single("tap", axis_constant(Axis::x, 1000, 300'000));
    EXPECT_EQ(render(short_one, kinematic_hold("joystick", 0)).rows.size(), 400u);
    // 100 ms delay + 3 × 1 s: 3.1 s, and a 10% tail of 310 ms.
    EffectParams p = axis_constant(Axis::x, 1000, 1'000'000);
    p.start_delay_us = 100'000;
    p.iterations = 3;
    EXPECT_EQ(render(single("thrice", p), kinematic_hold("joystick", 0)).rows.size(), 3410u);
    // Endless: 2 s.
    const Sensation endless = single("forever", axis_constant(Axis::x, 1000, kInfiniteUs));
    EXPECT_EQ(render(endless, kinematic_hold("joystick", 0)).rows.size(), 2000u);
}

TEST(Render, ACompoundPlaysItsEffectsTogetherEachAfterItsDelay) {
    Sensation s;
    s.name = "two_pushes";
    s.compound = true;
    s.effects.push_back({axis_constant(Axis::x, 3000, 200'000), {}, {}});
    EffectParams later = axis_constant(Axis::y, -2000, 200'000);
    later.start_delay_us = 100'000;
    s.effects.push_back({later, {}, {}});
    const Trace trace = render(s, kinematic_hold("joystick", 0.4));
    for (const TraceRow& row : trace.rows) {
        const bool first_on = row.t_us < 200'000;
        const bool second_on = row.t_us >= 100'000 && row.t_us < 300'000;
        if (row.t_us == 200'000 || row.t_us == 100'000 || row.t_us == 300'000) continue;
        EXPECT_NEAR(row.force[0], first_on ? 3000.0 : 0.0, 0.5) << "t_us = " << row.t_us;
        EXPECT_NEAR(row.force[1], second_on ? -2000.0 : 0.0, 0.5) << "t_us = " << row.t_us;
    }
}

// An effect the engine refuses (here a recoil, which needs axes x and y, on the 1-axis
// wheel): the error must say which sensation, which effect and which type, whatever words
// the engine uses for the reason.
TEST(Render, AnEffectTheEngineRefusesNamesTheSensationEffectAndType) {
    EffectParams recoil;
    recoil.type = EffectType::dynamic_recoil;
    recoil.duration_us = 500'000;
    recoil.axis_count = 2;
    recoil.dynamic.blast_direction = 9000;
    recoil.dynamic.blast_intensity = 5000;
    Sensation s;
    s.name = "kick";
    s.compound = true;
    s.effects.push_back({axis_constant(Axis::x, 1000, 100'000), {}, {}});
    s.effects.push_back({recoil, {}, {}});
    try {
        (void)render(s, kinematic_hold("wheel", 0.1));
        FAIL() << "a two-axis recoil rendered on a one-axis wheel";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("kick"), std::string::npos) << message;
        EXPECT_NE(message.find("effect 1"), std::string::npos) << message;
        EXPECT_NE(message.find("dynamic_recoil"), std::string::npos) << message;
    }
}

// A sensation with a dynamic carries the simulated mass in the trace, and the CSV gets
// its columns: the mass relative to the handle and its velocity.
TEST(Render, ADynamicAddsTheMassColumns) {
    EffectParams recoil;
    recoil.type = EffectType::dynamic_recoil;
    recoil.duration_us = 300'000;
    recoil.axis_count = 2;
    recoil.dynamic.blast_direction = 9000;
    recoil.dynamic.blast_intensity = 5000;
    recoil.dynamic.dynamic_mass = 3000;
    recoil.dynamic.blast_resonance = 3000;
    recoil.dynamic.blast_decay = 1000;
    Sensation s;
    s.name = "kick";
    s.effects.push_back({recoil, {}, {}});
    const Trace trace = render(s, kinematic_hold("joystick", 0.2));
    EXPECT_TRUE(trace.has_dynamics);
    bool mass_moved = false;
    for (const TraceRow& row : trace.rows) {
        if (row.has_mass && (row.mass_relative[0] != 0.0f || row.mass_relative[1] != 0.0f)) mass_moved = true;
    }
    EXPECT_TRUE(mass_moved);
    std::ostringstream csv;
    write_csv(trace, csv);
    EXPECT_EQ(csv.str().substr(0, csv.str().find('\n')), "t_us,x,y,vx,vy,fx,fy,rx,ry,mx,my,mvx,mvy");
}

TEST(Render, AnAxisTheDeviceLacksIsRefusedWithTheEffectNamed) {
    Sensation s;
    s.name = "forward";
    s.compound = true;
    s.effects.push_back({axis_constant(Axis::x, 1000, 100'000), {}, {}});
    s.effects.push_back({axis_constant(Axis::y, 1000, 100'000), {}, {}});
    try {
        (void)render(s, kinematic_hold("wheel", 0.1));
        FAIL() << "a y-axis effect rendered on a 1-axis wheel";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("\"forward\""), std::string::npos) << message;
        EXPECT_NE(message.find("effect 1"), std::string::npos) << message;
        EXPECT_NE(message.find("constant"), std::string::npos) << message;
    }
}

void expect_invalid(const RenderOptions& o, const char* flag, const char* range_hint) {
    const Sensation s = single("hum", axis_constant(Axis::x, 1000, 100'000));
    try {
        (void)render(s, o);
        ADD_FAILURE() << "accepted options that should name " << flag;
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(flag), std::string::npos) << message;
        EXPECT_NE(message.find(range_hint), std::string::npos) << message;
    }
}

TEST(Render, BadOptionsNameTheFlagAndTheAllowedRange) {
    RenderOptions o = kinematic_hold("joystick", 0.1);

    RenderOptions no_profile = o;
    no_profile.profile = nullptr;
    expect_invalid(no_profile, "--device", "device");

    for (double rate : {50.0, 20000.0, 999.5, std::numeric_limits<double>::quiet_NaN()}) {
        RenderOptions r = o;
        r.rate_hz = rate;
        expect_invalid(r, "--rate", "100..10000");
    }
    for (double duration : {-1.0, 601.0, std::numeric_limits<double>::infinity()}) {
        RenderOptions d = o;
        d.duration_s = duration;
        expect_invalid(d, "--duration", "600");
    }
    RenderOptions too_many = o;
    too_many.duration_s = 500;
    too_many.rate_hz = 10000;
    expect_invalid(too_many, "--rate", "2000000");

    RenderOptions motion = o;
    motion.motion = "wobble:3";
    expect_invalid(motion, "--motion", "wobble");
}

TEST(Render, ASensationLongerThanTheLongestRenderAsksForADuration) {
    EffectParams p = axis_constant(Axis::x, 1000, 60'000'000);
    p.iterations = 20;  // 20 minutes
    try {
        (void)render(single("marathon", p), kinematic_hold("joystick", 0));
        FAIL() << "rendered 20 minutes by default";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--duration"), std::string::npos) << e.what();
    }
}

TEST(SensationLength, IsTheLatestEndOverEffectsOrEndless) {
    Sensation s;
    s.compound = true;
    EffectParams a = axis_constant(Axis::x, 1, 250'000);
    a.iterations = 2;
    EffectParams b = axis_constant(Axis::y, 1, 100'000);
    b.start_delay_us = 450'000;
    s.effects = {{a, {}, {}}, {b, {}, {}}};
    EXPECT_EQ(sensation_length_us(s), 550'000);

    s.effects[1].params.iterations = kInfiniteIterations;
    EXPECT_EQ(sensation_length_us(s), std::nullopt);
    EXPECT_EQ(default_duration_s(s), 2.0);

    s.effects[1].params.iterations = 1;
    s.effects[0].params.duration_us = kInfiniteUs;
    EXPECT_EQ(sensation_length_us(s), std::nullopt);
}

}  // namespace
}  // namespace feel::render

namespace feel::render {
namespace {

// The trace's walls for plots (docs/conditions.md, "Geometry"): an absolute wall at its
// offset; a relative one at offset + the handle's position along u where it began playing
// (§3.7's Offset-Flag), here an angle wall at compass 9000 (u = +x) with the hand holding
// the handle at x = 3000: its surface is at x = 4500, to within one sensor step.
TEST(RenderSurfaces, AWallIsMarkedAtItsOffsetARelativeOneFromWhereTheHandleWas) {
    EffectParams wall;
    wall.type = EffectType::angle_wall;
    wall.duration_us = 100'000;
    wall.axis_count = 2;
    wall.axes[0] = Axis::x;
    wall.axes[1] = Axis::y;
    wall.wall.hardness = 5000;
    wall.wall.angle = 9000;
    wall.wall.offset = 1500;
    wall.wall.offset_mode = OffsetMode::relative;
    EffectParams floor = wall;
    floor.type = EffectType::axis_barrier;
    floor.axis_count = 1;
    floor.axes[0] = Axis::y;
    floor.barrier.pos_hardness = floor.barrier.neg_hardness = 4000;
    floor.barrier.thickness = 300;
    floor.barrier.offset = -2500;
    format::Sensation s{"pair", std::nullopt, true, {{wall, {}, {}}, {floor, {}, {}}}};
    RenderOptions o;
    o.profile = &testing::profile("joystick");
    o.grip = sim::Grip::kinematic;
    o.motion = "hold:3000,0";
    o.duration_s = 0.05;
    const Trace trace = render(s, o);
    ASSERT_EQ(trace.surfaces.size(), 2u);
    const SurfaceMark& barrier = trace.surfaces[0];  // absolute: known before the first tick
    EXPECT_TRUE(barrier.barrier);
    EXPECT_EQ(barrier.axis, 1);
    EXPECT_EQ(barrier.at, -2500);
    EXPECT_EQ(barrier.thickness, 300);
    EXPECT_EQ(barrier.effect, "pair effect 1");
    const SurfaceMark& relative = trace.surfaces[1];
    EXPECT_FALSE(relative.barrier);
    EXPECT_TRUE(relative.relative);
    EXPECT_EQ(relative.axis, -1);
    EXPECT_EQ(relative.angle, 9000);
    const double step = 20000.0 / o.profile->axes[0].sensor_counts;
    EXPECT_NEAR(relative.at, 3000 + 1500, step);
    // The hand's target is the motion: held at (3000, 0) on every tick.
    EXPECT_TRUE(trace.has_hand);
    for (const TraceRow& row : trace.rows) {
        EXPECT_EQ(row.target[0], 3000.0f);
        EXPECT_EQ(row.target[1], 0.0f);
    }
}

}  // namespace
}  // namespace feel::render
