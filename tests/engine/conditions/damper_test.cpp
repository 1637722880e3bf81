// Damper (§3.3, §6.6.a) against F = -b·v with DirectInput's offset, deadband and
// saturation rules, on prescribed motion; and the damper on a slow quantized drag.
#include <vector>

#include "condition_fixture.hpp"

namespace feel::test {
namespace {

using Damper = ConditionFixture;

// §3.3 Figure 3-7: the generalized damping profile over the scaled velocity v (10000 =
// velocity_ref). Zero within deadband of the offset velocity, then b × (distance past the
// band's edge) against the motion, capped by the saturation of that side.
double damper_force(double v, double offset, double b_pos, double b_neg, double sat_pos, double sat_neg,
                    double deadband) {
    const double d = v - offset;
    if (d > deadband) return -std::min(std::max(b_pos * (d - deadband) / 10000, -sat_pos), sat_pos);
    if (d < -deadband) return std::min(std::max(b_neg * (-d - deadband) / 10000, -sat_neg), sat_neg);
    return 0;
}

TEST_F(Damper, HandComputedPoint) {
    // 20000 units/s = 2000 on the ±10000 scale; b = 5000 resists with 1000.
    play(condition(EffectType::damper, {Axis::x}, {block(5000, 5000)}));
    TickOutput out;
    for (int k = 0; k < 20; ++k) out = tick_at(-5000 + 20.0 * k);
    EXPECT_NEAR(out.force[0], -1000, 1e-2);
}

TEST_F(Damper, RampsAtSpeedsOnBothSidesOfTheOffset) {
    // b+ 7000, b- 4000, offset +500 (5000 units/s), deadband 300, saturations 6000 and 2500.
    const ConditionBlock b = block(7000, 4000, 500, 6000, 2500, 300);
    for (double v : {-95000.0, -40000.0, -8000.0, -1000.0, 0.0, 2500.0, 5000.0, 8000.0, 9000.0, 30000.0, 95000.0}) {
        SCOPED_TRACE(v);
        reset(joystick_config());
        play(condition(EffectType::damper, {Axis::x}, {b}));
        const double x0 = v > 0 ? -9500.0 : 9500.0;
        expect_along(
            150, [&](int k) { return Point{x0 + v * k * 1e-3, 0}; },
            [&](int k, int axis, const TickOutput&) {
                if (axis != 0) return 0.0;
                if (k == 0) return kNaN;  // one sample: no velocity yet
                return damper_force(v * 10000 / kVelocityRef, 500, 7000, 4000, 6000, 2500, 300);
            });
    }
}

TEST_F(Damper, TwoAxesEachWithItsBlock) {
    play(condition(EffectType::damper, {Axis::x, Axis::y}, {block(10000, 10000), block(-3000, 6000, -1000, 10000, 10000, 0)}));
    const double vx = 35000, vy = -22000;
    expect_along(
        120, [&](int k) { return Point{-8000 + vx * k * 1e-3, 6000 + vy * k * 1e-3}; },
        [&](int k, int axis, const TickOutput&) {
            if (k == 0) return kNaN;
            return axis == 0 ? damper_force(vx / 10, 0, 10000, 10000, 10000, 10000, 0)
                             : damper_force(vy / 10, -1000, -3000, 6000, 10000, 10000, 0);
        });
}

TEST_F(Damper, AlongASineTheForceFollowsTheEstimatedVelocity) {
    // The force is the profile of the engine's velocity estimate on every tick, and that
    // estimate follows the true velocity of the sine to within 7% of its peak (the FOAW
    // window lags by half its length, motion_estimator.cpp).
    const ConditionBlock b = block(8000, 5000, 0, 7000, 4000, 150);
    play(condition(EffectType::damper, {Axis::x}, {b}));
    const double amplitude = 6000, hz = 1.0, w = 2 * kPi * hz;
    for (int k = 0; k < 2000; ++k) {
        const double t = k * 1e-3;
        const TickOutput out = tick_at(quantize(amplitude * std::sin(w * t), kJoystickStep));
        const double v_est = out.velocity[0];
        ASSERT_NEAR(out.force[0], damper_force(v_est / 10, 0, 8000, 5000, 7000, 4000, 150), 1e-2) << k;
        if (k >= 150) {
            ASSERT_NEAR(v_est, amplitude * w * std::cos(w * t), 0.07 * amplitude * w) << k;
        }
    }
}

TEST_F(Damper, ASlowQuantizedDragMeetsASteadyResistance) {
    // 2% of velocity_ref (2000 units/s, 10 mm/s on the joystick): 0.41 sensor
    // count per tick. b = 10000 must resist with 200 on every tick. A backward difference
    // of the same sensor readings is 0 on most ticks (and 4.9 times too big on the rest).
    play(condition(EffectType::damper, {Axis::x}, {block(10000, 10000)}));
    const double v = 2000;
    int zero_differences = 0, ticks = 0;
    double previous = 0;
    for (int k = 0; k < 1500; ++k) {
        const double x = quantize(-3000 + v * k * 1e-3, kJoystickStep);
        const TickOutput out = tick_at(x);
        if (k >= 110) {  // the estimator's window has filled (100 ms)
            ASSERT_NEAR(out.force[0], -200, 0.05 * 200) << "tick " << k;
            ++ticks;
            if (x == previous) ++zero_differences;
        }
        previous = x;
    }
    EXPECT_GT(zero_differences, ticks / 2);  // the raw difference would collapse the damper
}

}  // namespace
}  // namespace feel::test
