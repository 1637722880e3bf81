// A fixture that plays effects on an engine at a fixed tick and records the force, so that
// tests can compare every tick against the analytic formula of the effect.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "feel/engine.hpp"

namespace feel::test {

inline constexpr double kPi = std::numbers::pi;

// Force tolerance: forces are float, the formulas double. 1e-3 of full scale is far below
// anything a hand can feel and far above float rounding at ±10000.
inline constexpr double kForceTolerance = 1e-2;

class EngineFixture : public ::testing::Test {
protected:
    explicit EngineFixture(int axis_count = 2) { reset(axis_count); }

    void reset(int axis_count, int max_effects = 64, int max_samples = 4096) {
        EngineConfig c;
        c.axis_count = axis_count;
        c.max_effects = max_effects;
        c.max_samples = max_samples;
        engine_ = std::make_unique<Engine>(c);
        t_us_ = 0;
    }

    EffectId create(const EffectParams& p, std::span<const int16_t> samples = {}) {
        const CreateResult r = engine_->create(p, samples);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        return r.id;
    }

    EffectId play(const EffectParams& p, std::span<const int16_t> samples = {}) {
        const EffectId id = create(p, samples);
        EXPECT_TRUE(engine_->start(id).ok());
        return id;
    }

    // Ticks once at the current time and advances the clock by dt_us.
    TickOutput tick(int64_t dt_us = 1000) {
        TickInput in;
        in.t_us = t_us_;
        TickOutput out;
        engine_->tick(in, out);
        t_us_ += dt_us;
        return out;
    }

    // Steps from now for duration_us at dt_us and checks every axis of every tick against
    // expected(t_since_first_tick, axis); an expected NaN skips that point.
    void expect_forces(int64_t duration_us, int64_t dt_us,
                       const std::function<double(int64_t t_us, int axis)>& expected,
                       double tolerance = kForceTolerance) {
        const int64_t t0 = t_us_;
        while (t_us_ - t0 < duration_us) {
            const int64_t t = t_us_ - t0;
            const TickOutput out = tick(dt_us);
            for (int a = 0; a < engine_->config().axis_count; ++a) {
                const double want = expected(t, a);
                if (std::isnan(want)) continue;  // the formula declines this point
                ASSERT_NEAR(out.force[a], want, tolerance) << "t_us=" << t << " axis=" << a;
            }
        }
    }

    std::unique_ptr<Engine> engine_;
    int64_t t_us_ = 0;
};

// Builders for the effects the tests use.
inline EffectParams constant_on_x(int32_t magnitude, int64_t duration_us) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = duration_us;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.constant.magnitude = magnitude;
    return p;
}

inline EffectParams periodic_on_x(EffectType type, int32_t magnitude, int32_t offset, int64_t period_us,
                                  int32_t phase, int64_t duration_us) {
    EffectParams p;
    p.type = type;
    p.duration_us = duration_us;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.periodic.magnitude = magnitude;
    p.periodic.offset = offset;
    p.periodic.period_us = period_us;
    p.periodic.phase = phase;
    return p;
}

inline EffectParams on_xy_polar(EffectParams p, int32_t angle) {
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = angle;
    return p;
}

}  // namespace feel::test
