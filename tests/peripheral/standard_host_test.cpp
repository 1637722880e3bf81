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
    const protocol::CommandStatusReport s = rig.command(r);
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
        const protocol::CommandStatusReport s = rig.command(periodic(rig.next_sequence(), block, -2500, 100'000));
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

}  // namespace
}  // namespace feel::peripheral::test
