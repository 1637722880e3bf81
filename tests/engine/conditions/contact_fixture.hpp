// Kinematic tests of walls and barriers: the engine is fed prescribed positions at a fixed
// 1 ms tick and every force is compared with the element's formula, written out in the
// tests from the primer's definitions (§3.7, §3.8), never taken from the engine.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "conditions/condition_fixture.hpp"
#include "feel/engine.hpp"

namespace feel::test::contact {

// The stiffness of hardness 10000 in these tests, force units per position unit: a round
// number so the expected forces are easy to read (full force at 200 units of depth).
inline constexpr double kWallK = 50.0;
// Float forces against double formulas.
inline constexpr double kContactTolerance = 1e-2;

// A two-axis device like the joystick, with a round wall stiffness and (unless a test says
// otherwise) the passivity controller off, so the force is the element's formula exactly.
inline EngineConfig contact_config(int axis_count = 2, bool passivity = false) {
    EngineConfig c;
    c.axis_count = axis_count;
    c.velocity_ref = 1e5f;
    c.sensor_step = 20000.0f / 4096.0f;
    c.device_damping = 0.0056f;
    c.wall_stiffness = static_cast<float>(kWallK);
    c.passivity_control = passivity;
    return c;
}

inline EffectParams axis_wall(Axis axis, int32_t hardness, WallSense sense, int32_t offset,
                              OffsetMode mode = OffsetMode::absolute) {
    EffectParams p;
    p.type = EffectType::axis_wall;
    p.axis_count = 1;
    p.axes[0] = axis;
    p.wall.hardness = hardness;
    p.wall.sense = sense;
    p.wall.offset = offset;
    p.wall.offset_mode = mode;
    return p;
}

inline EffectParams angle_wall(int32_t angle, int32_t hardness, WallSense sense, int32_t offset) {
    EffectParams p;
    p.type = EffectType::angle_wall;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.wall.angle = angle;
    p.wall.hardness = hardness;
    p.wall.sense = sense;
    p.wall.offset = offset;
    return p;
}

inline EffectParams axis_barrier(Axis axis, int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                                 int32_t offset) {
    EffectParams p;
    p.type = EffectType::axis_barrier;
    p.axis_count = 1;
    p.axes[0] = axis;
    p.barrier.pos_hardness = pos_hardness;
    p.barrier.neg_hardness = neg_hardness;
    p.barrier.thickness = thickness;
    p.barrier.offset = offset;
    return p;
}

inline EffectParams angle_barrier(int32_t angle, int32_t pos_hardness, int32_t neg_hardness,
                                  int32_t thickness, int32_t offset) {
    EffectParams p = axis_barrier(Axis::x, pos_hardness, neg_hardness, thickness, offset);
    p.type = EffectType::angle_barrier;
    p.axis_count = 2;
    p.axes[1] = Axis::y;
    p.barrier.angle = angle;
    return p;
}

// The primer's compass: angle a (hundredths of a degree, clockwise from +y) points along
// (sin a, cos a) in (x, y).
inline double compass_x(int32_t angle) { return std::sin(angle * std::numbers::pi / 18000.0); }
inline double compass_y(int32_t angle) { return std::cos(angle * std::numbers::pi / 18000.0); }

// A spring pushing back by k·depth, capped at the motor's full scale; 0 out of contact.
inline double push_back(double k, double depth) {
    return depth > 0 ? std::clamp(k * depth, -10000.0, 10000.0) : 0.0;
}

// The condition fixture, configured for contacts, with a shorter name for a tick.
class ContactFixture : public ConditionFixture {
protected:
    ContactFixture() { reset(contact_config()); }

    // One tick with the handle at (x, y, z); advances the clock by one tick.
    TickOutput at(double x, double y = 0, double z = 0) { return tick_at(x, y, z); }

    static constexpr int64_t kTickUs = 1000;  // ConditionFixture's default tick
};

}  // namespace feel::test::contact
