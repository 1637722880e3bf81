// What a standard PID host (Linux's hid-pidff) sends, and what a feel device must make of
// it (docs/protocol.md, "Standard hosts"): conditions that come with a direction and one
// Set Condition per axis, and periodic effects with a negative magnitude. The host here
// writes what hid-pidff writes: no vendor fields (axis_count 0), duration 0 = infinite,
// Direction Enable with a polar direction on every effect.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "session_rig.hpp"

namespace feel::peripheral::test {
namespace {

using protocol::EffectOperation;
using protocol::ReportId;

// Set Effect as hid-pidff writes it for evdev's `direction` (docs/protocol.md's table).
protocol::SetEffectReport pidff_set_effect(uint32_t sequence, uint16_t block, EffectType type, int32_t angle) {
    protocol::SetEffectReport r = set_effect(sequence, block, type, 0);
    r.duration_us = 0;  // evdev's replay.length 0: infinite
    r.iterations = 0;
    r.direction_kind = DirectionKind::polar;
    r.direction[0] = angle;
    return r;
}

// DirectInput's rule: a condition given one parameter block per axis ignores its direction.
// A spring of stiffness k on each axis, held at (5000, -3000), pushes back along each axis
// by -k·x/10000 (§3.3), whatever direction came with it.
TEST(StandardHost, ConditionWithABlockPerAxisIgnoresTheDirection) {
    SessionRig rig("iforce2", "hold:5000,-3000", sim::Grip::kinematic);
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    constexpr int16_t kx = 1000;
    constexpr int16_t ky = 4000;
    rig.ok(spring_axis(rig.next_sequence(), block, 0, kx));
    rig.ok(spring_axis(rig.next_sequence(), block, 1, ky));
    // hid-pidff's direction for evdev 0x4000 (feel 9000); before the rule, "take no direction".
    rig.ok(pidff_set_effect(rig.next_sequence(), block, EffectType::spring, 9000));
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 1));
    rig.run(20);

    const double x = rig.pipeline().last_input().position[0];
    const double y = rig.pipeline().last_input().position[1];
    EXPECT_NEAR(x, 5000, 20000.0 / 4096);
    EXPECT_NEAR(y, -3000, 20000.0 / 4096);
    EXPECT_NEAR(rig.pipeline().motor_force()[0], -kx * x / 10000.0, 1e-3);
    EXPECT_NEAR(rig.pipeline().motor_force()[1], -ky * y / 10000.0, 1e-3);
}

// The other form of DirectInput's rule: one block for several axes, with a direction, is
// the condition with a direction (§3.1), its block applied along it. A spring of stiffness
// k along compass 3000 (u = (sin 30°, cos 30°)), held at (5000, -3000): s = x·u, and the
// force is -k·s/10000 along u (§3.2), nothing across it.
TEST(StandardHost, ConditionWithOneBlockAndADirectionActsAlongTheDirection) {
    SessionRig rig("iforce2", "hold:5000,-3000", sim::Grip::kinematic);
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    constexpr int16_t k = 4000;
    rig.ok(spring_axis(rig.next_sequence(), block, 0, k));
    rig.ok(pidff_set_effect(rig.next_sequence(), block, EffectType::spring, 3000));
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 1));
    rig.run(20);

    const double x = rig.pipeline().last_input().position[0];
    const double y = rig.pipeline().last_input().position[1];
    const double ux = 0.5, uy = std::sqrt(3.0) / 2;
    const double f = -k * (x * ux + y * uy) / 10000.0;
    EXPECT_NEAR(rig.pipeline().motor_force()[0], f * ux, 1e-2);
    EXPECT_NEAR(rig.pipeline().motor_force()[1], f * uy, 1e-2);
}

// One block for two axes without a direction is neither form: refused, naming the block.
TEST(StandardHost, ConditionWithOneBlockForTwoAxesAndNoDirectionIsRefusedNamingTheMissingBlock) {
    SessionRig rig("iforce2");
    const uint16_t block = rig.create(EffectType::damper);
    ASSERT_NE(block, 0);
    rig.ok(spring_axis(rig.next_sequence(), block, 0, 1000));
    protocol::SetEffectReport r = pidff_set_effect(rig.next_sequence(), block, EffectType::damper, 9000);
    r.direction_kind = DirectionKind::none;
    r.direction[0] = 0;
    const protocol::CommandAnswer s = rig.command(r);
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "set_condition");
    EXPECT_NE(std::string(s.rule).find("axis 1"), std::string::npos) << s.rule;
}

// evdev's periodic force is offset + magnitude · w(t) (linux/input.h: the magnitude is
// signed), so a negative magnitude is the wave upside down. With w(1/4) = 1 and w(3/4) = -1
// for sine, square and triangle (the primer's waves, §6.6.b), magnitude M = -2500 and
// offset 1000 give 1000 - 2500 = -1500 a quarter period in and 1000 + 2500 = 3500 at three
// quarters. Direction 9000 comes from +x: force_x = -value (docs/conventions.md).
TEST(StandardHost, NegativePeriodicMagnitudeIsTheWaveUpsideDown) {
    for (const EffectType type : {EffectType::sine, EffectType::square, EffectType::triangle}) {
        SCOPED_TRACE(std::string(effect_type_name(type)));
        SessionRig rig("iforce2", "hold:0", sim::Grip::kinematic);
        const uint16_t block = rig.create(type);
        ASSERT_NE(block, 0);
        constexpr uint32_t kPeriodUs = 1'000'000;
        protocol::SetPeriodicReport w = periodic(rig.next_sequence(), block, -2500, kPeriodUs);
        w.offset = 1000;
        rig.ok(w);
        rig.ok(pidff_set_effect(rig.next_sequence(), block, type, 9000));
        rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 1));
        const int64_t tick_us = 1'000'000 / rig.pipeline().config().loop_rate_hz;
        const int quarter = static_cast<int>(kPeriodUs / 4 / tick_us);
        // The quarters are the wave's flat tops: a tick or two either side changes nothing
        // for square, < 1 for sine, 10 a tick for triangle (the start takes a few ticks).
        rig.run(quarter);
        EXPECT_NEAR(rig.pipeline().motor_force()[0], -(1000 - 2500), 40);
        EXPECT_NEAR(rig.pipeline().motor_force()[1], 0, 1);
        rig.run(2 * quarter);
        EXPECT_NEAR(rig.pipeline().motor_force()[0], -(1000 + 2500), 40);
    }
}

// A saw upside down is the other saw (-saw_up(p) = saw_down(p)), which no phase of the
// same saw gives, and an effect's type never changes: refused with the allowed range.
TEST(StandardHost, NegativeSawMagnitudeIsRefused) {
    for (const EffectType type : {EffectType::saw_up, EffectType::saw_down}) {
        SCOPED_TRACE(std::string(effect_type_name(type)));
        SessionRig rig("iforce2");
        const uint16_t block = rig.create(type);
        ASSERT_NE(block, 0);
        const protocol::CommandAnswer s = rig.command(periodic(rig.next_sequence(), block, -2500, 100'000));
        EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
        EXPECT_EQ(s.command, ReportId::set_periodic);
        EXPECT_STREQ(s.field, "set_periodic.magnitude");
        EXPECT_EQ(s.value, -2500);
        EXPECT_EQ(s.allowed_min, 0);
        EXPECT_EQ(s.allowed_max, 10000);
        // A positive magnitude still fits.
        rig.ok(periodic(rig.next_sequence(), block, 2500, 100'000));
    }
}


// hid-pidff sends Set Condition for axes 0 and 1 whatever the device has. On the one-axis
// wheel the axis-1 block is accepted and ignored (docs/protocol.md, "Standard hosts"): the
// spring holds axis 0 with axis 0's stiffness, -k·x/10000 (§3.3), and nothing is refused.
TEST(StandardHost, OneAxisDeviceAcceptsAndIgnoresTheSecondConditionBlock) {
    SessionRig rig("wheel", "hold:5000", sim::Grip::kinematic);
    ASSERT_EQ(rig.caps().axis_count, 1);
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    constexpr int16_t k0 = 1000;
    rig.ok(spring_axis(rig.next_sequence(), block, 0, k0));
    rig.ok(spring_axis(rig.next_sequence(), block, 1, 4000));  // the axis the wheel lacks
    rig.ok(pidff_set_effect(rig.next_sequence(), block, EffectType::spring, 9000));
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 1));
    rig.run(20);
    const double x = rig.pipeline().last_input().position[0];
    EXPECT_NEAR(x, 5000, 20000.0 / 4096);
    EXPECT_NEAR(rig.pipeline().motor_force()[0], -k0 * x / 10000.0, 1e-3);
}

// feel's own host names the effect's axes (Set Effect's axis_count) and sends one block per
// axis: a block for an axis the effect lacks is its mistake, refused at the commit.
TEST(StandardHost, OwnHostConditionBlockForAnAxisTheEffectLacksIsRefused) {
    SessionRig rig("wheel");
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    rig.ok(spring_axis(rig.next_sequence(), block, 0, 1000));
    rig.ok(spring_axis(rig.next_sequence(), block, 1, 4000));
    const protocol::CommandAnswer s = rig.command(set_effect(rig.next_sequence(), block, EffectType::spring, 1));
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "set_condition.axis_index");
    EXPECT_TRUE(s.has_range);
    EXPECT_EQ(s.value, 1);
    EXPECT_EQ(s.allowed_min, 0);
    EXPECT_EQ(s.allowed_max, 0);
}


// PID's Axes Enable names the axes an effect acts on (PID 1.0's Set Effect). A standard
// host's spring with only Y enabled and one Set Condition (Parameter Block Offset 0, the
// effect's first axis) holds y alone: -k·y/10000 (§3.3) on y, nothing on x.
TEST(StandardHost, AxesEnableChoosesTheEffectsAxes) {
    SessionRig rig("iforce2", "hold:5000,-3000", sim::Grip::kinematic);
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    constexpr int16_t k = 2000;
    rig.ok(spring_axis(rig.next_sequence(), block, 0, k));
    protocol::SetEffectReport e = pidff_set_effect(rig.next_sequence(), block, EffectType::spring, 0);
    e.direction_kind = DirectionKind::none;  // hid-pidff clears Direction Enable when it enables axes
    e.direction[0] = 0;
    e.axes_enable = 1u << static_cast<int>(Axis::y);
    rig.ok(e);
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 1));
    rig.run(20);
    const double y = rig.pipeline().last_input().position[1];
    EXPECT_NEAR(y, -3000, 20000.0 / 4096);
    EXPECT_NEAR(rig.pipeline().motor_force()[1], -k * y / 10000.0, 1e-3);
    EXPECT_NEAR(rig.pipeline().motor_force()[0], 0, 1e-6);
}

// hid-pidff enables the first axes it finds in Axes Enable's list (X and Y) whatever the
// device has: on the one-axis wheel Y is ignored and the effect plays on X.
TEST(StandardHost, AxesEnableNamingAnAxisTheDeviceLacksIsIgnored) {
    SessionRig rig("wheel", "hold:5000", sim::Grip::kinematic);
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    constexpr int16_t k = 1000;
    rig.ok(spring_axis(rig.next_sequence(), block, 0, k));
    rig.ok(spring_axis(rig.next_sequence(), block, 1, 3000));
    protocol::SetEffectReport e = pidff_set_effect(rig.next_sequence(), block, EffectType::spring, 0);
    e.direction_kind = DirectionKind::none;
    e.axes_enable = (1u << static_cast<int>(Axis::x)) | (1u << static_cast<int>(Axis::y));
    rig.ok(e);
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 1));
    rig.run(20);
    const double x = rig.pipeline().last_input().position[0];
    EXPECT_NEAR(rig.pipeline().motor_force()[0], -k * x / 10000.0, 1e-3);
}

TEST(StandardHost, AxesEnableNamingNoAxisOfTheDeviceIsRefused) {
    SessionRig rig("iforce2");
    const uint16_t block = rig.create(EffectType::constant);
    ASSERT_NE(block, 0);
    protocol::SetConstantForceReport c;
    c.sequence = rig.next_sequence();
    c.block = block;
    c.magnitude = 1000;
    rig.ok(c);
    protocol::SetEffectReport e = pidff_set_effect(rig.next_sequence(), block, EffectType::constant, 9000);
    e.axes_enable = 1u << static_cast<int>(Axis::rz);
    const protocol::CommandAnswer s = rig.command(e);
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "set_effect.axes_enable");
    EXPECT_EQ(s.value, 1 << static_cast<int>(Axis::rz));
}

// feel's own host names the axes in its vendor fields; an Axes Enable that disagrees is refused.
TEST(StandardHost, OwnHostAxesEnableMustMatchItsAxes) {
    SessionRig rig("iforce2");
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_NE(block, 0);
    rig.ok(spring_axis(rig.next_sequence(), block, 0, 1000));
    protocol::SetEffectReport e = set_effect(rig.next_sequence(), block, EffectType::spring, 1);  // axes[0] = x
    e.axes_enable = 1u << static_cast<int>(Axis::y);
    const protocol::CommandAnswer s = rig.command(e);
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "set_effect.axes_enable");
    // The refused first commit rolled the block back: its Set Condition comes again.
    rig.ok(spring_axis(rig.next_sequence(), block, 0, 1000));
    e.sequence = rig.next_sequence();
    e.axes_enable = 1u << static_cast<int>(Axis::x);
    rig.ok(e);
}

}  // namespace
}  // namespace feel::peripheral::test
