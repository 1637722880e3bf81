// Friction (§3.5, §6.6.a): a constant resistance against the motion with a smooth turn-
// around, checked against the closed form of the Dahl bristle the engine renders it with
// (docs/conditions.md). Along a monotone stretch of travel X from a deflection z0 the
// bristle obeys dz/dx = 1 - z·sign(dx), whose solution is
//
//     z = ±1 + (z0 ∓ 1)·exp(-X/Z)        (+ while moving toward +, - toward -)
//
// and the force is -f·z, f the coefficient of the side z is on. The presliding distance Z
// follows the documented rule: Z = f/K with K = 2b/T (the device's passivity bound),
// at least f/1000 and at most 200/(2·sensor_step). A small LuGre microdamping acts while
// the bristle deflects at low speed (bristle_model.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include "bristle_model.hpp"
#include "condition_fixture.hpp"
#include "conditions/friction_model.hpp"

namespace feel::test {
namespace {

using Friction = ConditionFixture;

double presliding(double f, double damping = kJoystickDamping, double dt_s = 1e-3) {
    return feel::test::presliding(f, damping, dt_s, kJoystickStep);
}

// The friction force at deflection z with the handle moving at v relative to the surface:
// -f·z (f of the side z is on) plus microdamping, capped by that side's saturation.
double friction_force(double z, double v, double f_pos, double f_neg, double sat_pos, double sat_neg) {
    const double magnitude = std::max(std::fabs(f_pos), std::fabs(f_neg));
    const double Z = presliding(magnitude);
    const double f = -(z >= 0 ? f_pos : f_neg) * z + microdamping(magnitude / Z, z, v);
    const double cap = z >= 0 ? sat_pos : sat_neg;
    return std::min(std::max(f, -cap), cap);
}

TEST_F(Friction, ThePresslidingDistanceOnTheJoystickIsItsPassiveStiffness) {
    // 2b/T = 11.24 force units per position unit at 1 kHz: f = 6000 builds up over 534 units.
    EXPECT_NEAR(presliding(6000), 534.0, 0.5);
    // After sliding exactly one presliding distance from rest: 1 - 1/e of the force.
    play(condition(EffectType::friction, {Axis::x}, {block(6000, 6000)}));
    const double Z = presliding(6000);
    tick_at(-2000);
    const TickOutput out = tick_at(-2000 + Z);
    EXPECT_NEAR(out.force[0], -6000 * (1 - std::exp(-1.0)), 1.0);
}

TEST_F(Friction, SlidingBothWaysWithAsymmetricCoefficients) {
    // f+ 6000 (moving toward +), f- 3000. Slide + for 600 ticks at 20 units/tick, then back.
    play(condition(EffectType::friction, {Axis::x}, {block(6000, 3000)}));
    const double Z = presliding(6000);
    const double x0 = -6000, turn = x0 + 20.0 * 600;
    const double z_turn = bristle(0, turn - x0, Z);
    auto x_at = [&](int k) { return k <= 600 ? x0 + 20.0 * k : turn - 20.0 * (k - 600); };
    expect_along(
        1200, [&](int k) { return Point{x_at(k), 0}; },
        [&](int k, int axis, const TickOutput& out) {
            if (axis != 0) return 0.0;
            const double z = k <= 600 ? bristle(0, x_at(k) - x0, Z) : bristle(z_turn, x_at(k) - turn, Z);
            return friction_force(z, out.velocity[0], 6000, 3000, 10000, 10000);
        },
        0.5);
    // Sliding on, the force is the coefficient of the direction of motion (Figure 3-9).
    EXPECT_NEAR(tick_at(x_at(1200) - 20).force[0], 3000, 1.0);
}

TEST_F(Friction, TurningAroundHasNoStep) {
    // A 3 Hz back-and-forth of ±1500, quantized: the ideal Coulomb law would step by
    // 2f = 16000 at each reversal. The bristle's force changes per tick by at most
    // 2·f·|dx|/Z = 300 here (0.4 count per tick at the fastest), the microdamping a little more.
    play(condition(EffectType::friction, {Axis::x}, {block(8000, 8000)}));
    const double Z = presliding(8000);
    double previous_f = 0, largest_step = 0;
    int sign_changes = 0;
    for (int k = 0; k < 1000; ++k) {
        const double x = quantize(1500 * std::sin(2 * kPi * 3 * k * 1e-3), kJoystickStep);
        const double f = tick_at(x).force[0];
        if (k > 0) {
            largest_step = std::max(largest_step, std::fabs(f - previous_f));
            if (f * previous_f < 0) ++sign_changes;
        }
        previous_f = f;
    }
    EXPECT_LT(largest_step, 0.05 * 16000);
    EXPECT_LT(largest_step, 1.2 * 2 * 8000 * 1500 * 2 * kPi * 3 * 1e-3 / Z);
    EXPECT_EQ(sign_changes, 6);  // once per reversal: 3 periods
}

TEST_F(Friction, AtRestTheForceHoldsExactly) {
    play(condition(EffectType::friction, {Axis::x, Axis::y}, {block(5000, 5000), block(5000, 5000)}));
    for (int k = 0; k < 200; ++k) tick_at(-3000 + 7.0 * k, 2000 - 3.0 * k);
    const double x = -3000 + 7.0 * 200, y = 2000 - 3.0 * 200;
    // While the velocity estimate's window still holds the motion, the microdamping fades
    // (a few force units: the bristle is nearly slid through, ż is small).
    TickOutput out = tick_at(x, y);
    for (int k = 0; k < 110; ++k) {
        const TickOutput next = tick_at(x, y);
        ASSERT_NEAR(next.force[0], out.force[0], 5) << k;
        ASSERT_NEAR(next.force[1], out.force[1], 5) << k;
        out = next;
    }
    // Then not a bit changes.
    for (int k = 0; k < 500; ++k) {
        const TickOutput next = tick_at(x, y);
        ASSERT_EQ(next.force[0], out.force[0]) << k;
        ASSERT_EQ(next.force[1], out.force[1]) << k;
    }
    const double Z = presliding(5000);
    EXPECT_NEAR(out.force[0], -5000 * bristle(0, 7.0 * 200, Z), 0.5);  // it was sliding toward +x
    EXPECT_NEAR(out.force[1], 5000 * bristle(0, 3.0 * 200, Z), 0.5);   // and toward -y
}

TEST_F(Friction, SaturationsCapEachSideAndNegativeCoefficientsPushAlong) {
    play(condition(EffectType::friction, {Axis::x, Axis::y},
                   {block(8000, 5000, 0, 3000, 10000, 0), block(-4000, -4000, 0, 10000, 2500, 0)}));
    const double Zx = presliding(8000), Zy = presliding(4000);
    expect_along(
        800, [](int k) { return Point{-8000 + 20.0 * k, 8000 - 20.0 * k}; },
        [&](int k, int axis, const TickOutput& out) {
            if (axis == 0) return friction_force(bristle(0, 20.0 * k, Zx), out.velocity[0], 8000, 5000, 3000, 10000);
            return friction_force(bristle(0, -20.0 * k, Zy), out.velocity[1], -4000, -4000, 10000, 2500);
        },
        0.5);
    const TickOutput out = tick_at(-8000 + 20.0 * 800, 8000 - 20.0 * 800);
    EXPECT_NEAR(out.force[0], -3000, 1e-2);  // 8000 capped at the + side's 3000
    EXPECT_NEAR(out.force[1], -2500, 1e-2);  // pushed along its motion toward -y, capped
}

TEST_F(Friction, AnOffsetIsASurfaceMovingAtThatSpeed) {
    // offset 2000 = 20000 units/s. A handle at rest is dragged toward + with the
    // coefficient of the side its motion relative to the surface is on (-: f- = 3000).
    play(condition(EffectType::friction, {Axis::x}, {block(6000, 3000, 2000)}));
    const double Z = presliding(6000);
    expect_along(
        300, [](int) { return Point{1000, 0}; },
        [&](int k, int axis, const TickOutput& out) {
            if (axis != 0) return 0.0;
            if (k == 0) return 0.0;  // the first tick only anchors the bristle
            return friction_force(bristle(0, -20000.0 * 1e-3 * k, Z), out.velocity[0] - 20000, 6000, 3000, 10000,
                                  10000);
        },
        0.5);
    EXPECT_NEAR(tick_at(1000).force[0], 3000, 1.0);
    // Moving with the surface, nothing rubs: the bristle stays where it was (only the
    // microdamping follows the velocity estimate as it catches up with the new motion).
    const double z = bristle(0, -20000.0 * 1e-3 * 301, Z);
    for (int k = 1; k <= 100; ++k) {
        const TickOutput out = tick_at(1000 + 20.0 * k);
        ASSERT_NEAR(out.force[0], friction_force(z, out.velocity[0] - 20000, 6000, 3000, 10000, 10000), 0.5) << k;
        if (k > 10) {
            ASSERT_NEAR(out.force[0], -3000 * z, 0.5) << k;
        }
    }
}

TEST_F(Friction, TheDeadbandIsAFreeBandOfSpeed) {
    // deadband 1000 = 10000 units/s: no force below it, the full force beyond twice it, a
    // smoothstep between.
    for (double v : {5000.0, 15000.0, 30000.0}) {
        SCOPED_TRACE(v);
        reset(joystick_config());
        play(condition(EffectType::friction, {Axis::x}, {block(6000, 6000, 0, 10000, 10000, 1000)}));
        const double Z = presliding(6000);
        const double t = std::clamp((v / 10 - 1000) / 1000, 0.0, 1.0);
        const double gate = t * t * (3 - 2 * t);
        expect_along(
            400, [&](int k) { return Point{-9000 + v * 1e-3 * k, 0}; },
            [&](int k, int axis, const TickOutput& out) {
                if (axis != 0) return 0.0;
                if (k < 2) return kNaN;  // the velocity estimate needs two samples
                EXPECT_NEAR(out.velocity[0], v, 2e-6 * v);  // the estimator is single precision
                return gate * friction_force(bristle(0, v * 1e-3 * k, Z), v, 6000, 6000, 10000, 10000);
            },
            0.5);
    }
}

TEST_F(Friction, ThePresslidingDistanceFollowsTheTickAndTheDevice) {
    // 10 kHz: 2b/T = 112 exceeds the resolution cap 200/(2·4.88) = 20.5, which wins.
    dt_us_ = 100;
    play(condition(EffectType::friction, {Axis::x}, {block(5000, 5000)}));
    const double Z = presliding(5000, kJoystickDamping, 1e-4);
    EXPECT_NEAR(Z, 5000 / 20.48, 0.1);
    tick_at(0);
    EXPECT_NEAR(tick_at(Z).force[0], -5000 * (1 - std::exp(-1.0)), 1.0);

    // A device that reports no damping: the force builds up over 1000 units.
    EngineConfig undamped = joystick_config();
    undamped.device_damping = 0;
    reset(undamped);
    dt_us_ = 1000;
    play(condition(EffectType::friction, {Axis::x}, {block(5000, 5000)}));
    tick_at(0);
    EXPECT_NEAR(tick_at(1000).force[0], -5000 * (1 - std::exp(-1.0)), 1.0);
}

// An effect of `type` on x alone, running for `duration_us`.
EffectParams on_x(EffectType type, int64_t duration_us = kInfiniteUs) {
    EffectParams p;
    p.type = type;
    p.duration_us = duration_us;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    return p;
}

TEST_F(Friction, StictionBalancesThePushItHolds) {
    // Coulomb's static friction is whatever balances the push on a handle at rest, within ±f
    // (§3.5: friction "always resists the direction of motion"; it does not move a handle
    // that nothing moves). At the first tick the handle has not moved, so the friction holds
    // the constant push at once: the engine's total force is 0. A hand then drags the handle
    // 300 units into the bristle and holds it; when the push ends, the friction's force
    // changes by exactly the push at that very tick, so the hand feels no step (the friction
    // holds the hand's share alone). (device_mass 0: the stop guard is off, this needs no
    // mass.)
    EngineConfig config = joystick_config();
    config.device_mass = 0;
    const double Z = presliding(6000);
    for (int32_t push : {2000, 3000, -2000}) {
        SCOPED_TRACE(push);
        reset(config);
        play(condition(EffectType::friction, {Axis::x}, {block(6000, 6000)}));
        EffectParams constant = on_x(EffectType::constant);
        constant.constant.magnitude = push;
        const EffectId pushing = play(constant);
        EXPECT_NEAR(tick_at(0).force[0], 0.0, 1.0);
        const double held = -6000 * bristle(push / 6000.0, 300, Z);  // dragged from z = push/f
        tick_at(300);
        for (int k = 0; k < 5; ++k) EXPECT_NEAR(tick_at(300).force[0], push + held, 1.0);
        ASSERT_TRUE(engine_->stop(pushing).ok());
        for (int k = 0; k < 5; ++k) EXPECT_NEAR(tick_at(300).force[0], push + held, 1.0) << k;
    }
}

TEST_F(Friction, ASlowlySlidingHandleKeepsItsKineticFriction) {
    // §3.5: friction "always resists the direction of motion". A handle dragged toward +x
    // under a count a tick (the sensed position repeats for 5 ticks, then moves a count)
    // while a ramp pushes along +x with a growing force: on the ticks where the sensor shows
    // no motion the stiction rule must not take the ramp's growth for a push to balance, so
    // the friction stays -f throughout (the bristle is fully slid, z = 1).
    EngineConfig config = joystick_config();
    config.device_mass = 0;
    reset(config);
    play(condition(EffectType::friction, {Axis::x}, {block(6000, 6000)}));
    tick_at(-5000);
    tick_at(5000);  // slid 10000 units: z = 1 to the float
    EffectParams ramp = on_x(EffectType::ramp, 100'000);
    ramp.ramp.start = 0;
    ramp.ramp.end = 3000;
    play(ramp);
    const double count = config.sensor_step;
    for (int k = 0; k < 80; ++k) {
        const TickOutput out = tick_at(5000 + count * (k / 5));
        // The ramp's level at this tick plus the friction's -6000.
        const double ramp_level = 3000.0 * (static_cast<double>(k) * 1e-3) / 0.1;
        ASSERT_NEAR(out.force[0], ramp_level - 6000, 31.0) << k;  // the ramp moves 30 a tick
    }
}

TEST_F(Friction, StictionDoesNotHoldAPushLargerThanTheFriction) {
    // A push above f is not held (§3.5: the handle slides): at the first tick the friction
    // adds nothing yet, and the push moves the handle into the bristle as before.
    reset(joystick_config());
    play(condition(EffectType::friction, {Axis::x}, {block(6000, 6000)}));
    EffectParams constant = on_x(EffectType::constant);
    constant.constant.magnitude = 7000;
    play(constant);
    EXPECT_NEAR(tick_at(0).force[0], 7000.0, 1.0);
}

TEST_F(Friction, AnUpdateWhilePlayingSlidesWithTheNewBlock) {
    // Without a restart the effect keeps its bristle and slides on with the new coefficients
    // and saturations at once (Engine::update; Figure 3-9: sliding, the force is the
    // coefficient of the direction of motion, capped by that side's saturation). A travel of
    // 12000 is over 22 presliding distances: the bristle is fully slid (z = ±1).
    const EffectId id = play(condition(EffectType::friction, {Axis::x}, {block(6000, 6000)}));
    double x = -9000;
    TickOutput out{};
    for (int k = 0; k < 600; ++k) out = tick_at(x += 20);
    EXPECT_NEAR(out.force[0], -6000, 1.0);
    EffectParams changed = condition(EffectType::friction, {Axis::x}, {block(8000, 3000, 0, 7000, 10000)});
    ASSERT_TRUE(engine_->update(id, changed, effect_field::kTypeSpecific, false).ok());
    EXPECT_NEAR(tick_at(x += 20).force[0], -7000, 1.0);  // 8000, capped at 7000
    for (int k = 0; k < 600; ++k) out = tick_at(x -= 20);
    EXPECT_NEAR(out.force[0], 3000, 1.0);
    changed = condition(EffectType::friction, {Axis::x}, {block(2000, 2000)});
    ASSERT_TRUE(engine_->update(id, changed, effect_field::kTypeSpecific, false).ok());
    EXPECT_NEAR(tick_at(x -= 20).force[0], 2000, 1.0);
}

TEST_F(Friction, ANonFiniteSensorReadingMovesNoBristle) {
    // A reading that is not a position (NaN, inf) is no travel: Dahl's z moves only with the
    // handle, so once the handle reads where it was and the velocity estimate is at rest
    // again, the force is the one it held before, to the bit, and never NaN meanwhile. (The
    // common friction's lean way, friction_condition.cpp, leaves such a tick to the general
    // one.)
    play(condition(EffectType::friction, {Axis::x, Axis::y}, {block(5000, 5000), block(4000, 4000)}));
    for (int k = 0; k < 200; ++k) tick_at(-3000 + 7.0 * k, 2000 - 3.0 * k);
    const double x = -3000 + 7.0 * 200, y = 2000 - 3.0 * 200;
    for (int k = 0; k < 700; ++k) tick_at(x, y);
    const TickOutput before = tick_at(x, y);
    const double inf = std::numeric_limits<double>::infinity();
    for (const double bad : {kNaN, inf, -inf}) {
        const TickOutput out = tick_at(bad, bad);
        EXPECT_TRUE(std::isfinite(out.force[0]) && std::isfinite(out.force[1]));
    }
    TickOutput after{};
    for (int k = 0; k < 700; ++k) {
        after = tick_at(x, y);
        ASSERT_TRUE(std::isfinite(after.force[0]) && std::isfinite(after.force[1])) << k;
    }
    EXPECT_EQ(after.force[0], before.force[0]);
    EXPECT_EQ(after.force[1], before.force[1]);
    const double Z = presliding(5000);
    const double z0 = bristle(0, 7.0 * 200, Z);
    EXPECT_NEAR(after.force[0], -5000 * z0, 0.5);
    // And the bristle still moves with the handle from where it was: back by 700 units it
    // has turned (the microdamping adds about 40 at this speed).
    TickOutput back{};
    for (int k = 1; k <= 100; ++k) back = tick_at(x - 7.0 * k, y);
    EXPECT_NEAR(back.force[0], -5000 * bristle(z0, -700, Z), 100);
}

TEST(BristleExponential, IsWithinTwoFloatUlpsOfTheExponentialOverItsPolynomial) {
    // The bristle's e^-u (friction_model.hpp, exp_of_travel) is a polynomial below u = 1/4
    // and std::exp beyond. Against the exponential in double: within 1.3e-7 (2 float ulps
    // near 1) on floats spread over every binade of [0, 1/4) (every 1021st float and the
    // last 4096 below 1/4), and continuous where it hands over to std::exp.
    double worst = 0;
    auto check = [&worst](float u) {
        worst = std::max(worst, std::fabs(static_cast<double>(feel::detail::exp_of_travel(u)) -
                                          std::exp(-static_cast<double>(u))));
    };
    const float end = 0.25f;
    uint32_t end_bits = 0;
    std::memcpy(&end_bits, &end, sizeof end);
    for (uint32_t bits = 0; bits < end_bits; bits += 1021) {
        float u = 0;
        std::memcpy(&u, &bits, sizeof u);
        check(u);
    }
    float u = end;
    for (int k = 0; k < 4096; ++k) check(u = std::nextafter(u, 0.0f));
    EXPECT_LE(worst, 1.3e-7);
    EXPECT_EQ(feel::detail::exp_of_travel(0.0f), 1.0f);
    EXPECT_NEAR(feel::detail::exp_of_travel(std::nextafter(end, 0.0f)), feel::detail::exp_of_travel(end), 2e-7);
    for (const float far : {0.25f, 0.5f, 1.0f, 4.0f, 30.0f}) {
        EXPECT_NEAR(feel::detail::exp_of_travel(far), std::exp(-static_cast<double>(far)), 1e-7) << far;
    }
    EXPECT_EQ(feel::detail::exp_of_travel(std::numeric_limits<float>::infinity()), 0.0f);
}

TEST(TextureBump, IsTheRaisedCosineWithinFloatPrecision) {
    // The texture's bump (friction_model.hpp, texture_bump: cos² of the half angle, cos by
    // its Taylor polynomial, in float) against the raised cosine (1 + cos(2π·r/w))/2 in
    // double, r the distance to the nearest multiple of the spacing: within 5e-7 (a few
    // float ulps of 1: the angle's rounding moves it by at most |sin 2θ|·1.2e-7·θ) over two
    // spacings either side of 0, for spacings and densities from the smallest to the largest.
    double worst = 0;
    for (const int32_t spacing : {1, 7, 100, 3001, 10000}) {
        for (const int32_t density : {1, 2500, 5000, 9999, 10000}) {
            const float width = static_cast<float>(spacing) * static_cast<float>(density) / 10000.0f;
            for (int k = -4000; k <= 4000; ++k) {
                const float s = static_cast<float>(spacing) * static_cast<float>(k) / 2000.0f;
                const double r = s - spacing * std::round(static_cast<double>(s) / spacing);
                const double expected = std::fabs(r) <= width / 2.0 ? 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * r / width)) : 0.0;
                const double bump = feel::detail::texture_bump(s, spacing, width);
                worst = std::max(worst, std::fabs(bump - expected));
                ASSERT_GE(bump, 0.0) << s;
                ASSERT_LE(bump, 1.0) << s;
            }
        }
    }
    EXPECT_LE(worst, 5e-7);
    EXPECT_EQ(feel::detail::texture_bump(0.0f, 100, 30.0f), 1.0f);  // a bump's top
    EXPECT_EQ(feel::detail::texture_bump(50.0f, 100, 30.0f), 0.0f);  // between bumps
    EXPECT_EQ(feel::detail::texture_bump(3.0f, 0, 30.0f), 0.0f);     // no spacing, no bump
}

}  // namespace
}  // namespace feel::test
