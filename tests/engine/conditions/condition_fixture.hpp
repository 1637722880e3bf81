// Kinematic tests of Spatial Conditions: the engine is fed prescribed positions through
// TickInput at a fixed tick, and each tick's force is compared with the condition's
// analytic formula, written out independently in each test.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <memory>
#include <numbers>

#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::test {

inline constexpr double kPi = std::numbers::pi;

// The joystick profile's velocity reference (units/s): the speed that reads as full scale.
inline constexpr double kVelocityRef = 1e5;

// The joystick profile's sensor step: 20000 units over 4096 counts.
inline constexpr double kJoystickStep = 20000.0 / 4096.0;

// Rounds a position to the sensor's step, as SimDevice::sense() does.
inline double quantize(double x, double step) { return step * std::round(x / step); }

// A Condition Struct block.
inline ConditionBlock block(int32_t pos_coefficient, int32_t neg_coefficient, int32_t offset = 0,
                            int32_t pos_saturation = 10000, int32_t neg_saturation = 10000,
                            int32_t deadband = 0, OffsetMode mode = OffsetMode::absolute) {
    ConditionBlock b;
    b.pos_coefficient = pos_coefficient;
    b.neg_coefficient = neg_coefficient;
    b.offset = offset;
    b.pos_saturation = pos_saturation;
    b.neg_saturation = neg_saturation;
    b.deadband = deadband;
    b.offset_mode = mode;
    return b;
}

// A spring, damper, inertia or friction effect on the given axes, one block per axis.
inline EffectParams condition(EffectType type, std::initializer_list<Axis> axes,
                              std::initializer_list<ConditionBlock> blocks) {
    EffectParams p;
    p.type = type;
    p.duration_us = kInfiniteUs;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) p.axes[i++] = a;
    i = 0;
    for (const ConditionBlock& b : blocks) p.conditions[i++] = b;
    return p;
}

// An angle_spring on x, y at compass angle `angle` (hundredths of a degree).
inline EffectParams angle_spring(int32_t angle, const ConditionBlock& b) {
    EffectParams p = condition(EffectType::angle_spring, {Axis::x, Axis::y}, {b});
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = angle;
    return p;
}

inline EffectParams texture(std::initializer_list<Axis> axes, int32_t pos_roughness, int32_t neg_roughness,
                            int32_t spacing, int32_t density) {
    EffectParams p = condition(EffectType::texture, axes, {});
    p.texture.pos_roughness = pos_roughness;
    p.texture.neg_roughness = neg_roughness;
    p.texture.spacing = spacing;
    p.texture.density = density;
    return p;
}

// The joystick profile's engine configuration (velocity_ref 1e5 units/s, acceleration_ref
// 2e6 units/s², sensor step 20000/4096, its mechanical damping).
inline EngineConfig joystick_config() {
    return sim::engine_config_for(*sim::find_device_profile("joystick"));
}

class ConditionFixture : public ::testing::Test {
protected:
    ConditionFixture() { reset(joystick_config()); }

    void reset(const EngineConfig& config) {
        config_ = config;
        engine_ = std::make_unique<Engine>(config_);
        t_us_ = 0;
    }

    EffectId play(const EffectParams& p) {
        const CreateResult r = engine_->create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(engine_->start(r.id).ok());
        return r.id;
    }

    // One tick at the current time with the handle at (x, y, z); advances the clock.
    TickOutput tick_at(double x, double y = 0, double z = 0) {
        TickInput in;
        in.t_us = t_us_;
        in.position[0] = static_cast<float>(x);
        in.position[1] = static_cast<float>(y);
        in.position[2] = static_cast<float>(z);
        TickOutput out;
        engine_->tick(in, out);
        t_us_ += dt_us_;
        return out;
    }

    // Ticks `ticks` times along the path position(k) (k = 0, 1, ...; x and y), and checks
    // every axis of every tick against expected(k, axis, out); a NaN expectation skips
    // that point.
    struct Point {
        double x = 0, y = 0;
    };
    void expect_along(int ticks, const std::function<Point(int k)>& path,
                      const std::function<double(int k, int axis, const TickOutput& out)>& expected,
                      double tolerance = 1e-2) {
        for (int k = 0; k < ticks; ++k) {
            const Point p = path(k);
            const TickOutput out = tick_at(p.x, p.y);
            for (int a = 0; a < 2; ++a) {
                const double want = expected(k, a, out);
                if (std::isnan(want)) continue;
                ASSERT_NEAR(out.force[a], want, tolerance)
                    << "tick " << k << " axis " << a << " at (" << p.x << ", " << p.y << ")";
            }
        }
    }

    double dt_s() const { return static_cast<double>(dt_us_) * 1e-6; }

    EngineConfig config_;
    std::unique_ptr<Engine> engine_;
    int64_t t_us_ = 0;
    int64_t dt_us_ = 1000;
};

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace feel::test
