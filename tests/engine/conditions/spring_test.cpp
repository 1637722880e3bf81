// Spring and Angle Spring (§3.2, §6.6.a, §8.2) against Hooke's law with the DirectInput
// deadband and saturation rules, on prescribed motion.
#include "condition_fixture.hpp"

namespace feel::test {
namespace {

using Spring = ConditionFixture;

// The generalized spring profile of §3.2 (Figure 3-2) as DirectInput defines it: no force
// within deadband of the offset; beyond, coefficient × (distance past the band's edge),
// restoring (the force points back toward the offset for positive coefficients), its
// magnitude capped by the saturation of that side.
double spring_force(double x, double offset, double k_pos, double k_neg, double sat_pos, double sat_neg,
                    double deadband) {
    const double d = x - offset;
    if (d > deadband) return -std::min(std::max(k_pos * (d - deadband) / 10000, -sat_pos), sat_pos);
    if (d < -deadband) return std::min(std::max(k_neg * (-d - deadband) / 10000, -sat_neg), sat_neg);
    return 0;
}

TEST_F(Spring, HandComputedPoints) {
    // k+ 5000, k- 2000, offset 1000, deadband 500, saturations 10000.
    play(condition(EffectType::spring, {Axis::x}, {block(5000, 2000, 1000, 10000, 10000, 500)}));
    EXPECT_NEAR(tick_at(4000).force[0], -1250, 1e-2);   // 5000 · (4000 - 1000 - 500) / 10000
    EXPECT_NEAR(tick_at(1400).force[0], 0, 1e-9);       // inside the deadband
    EXPECT_NEAR(tick_at(600).force[0], 0, 1e-9);        // its other edge, still inside
    EXPECT_NEAR(tick_at(-3500).force[0], 800, 1e-2);    // 2000 · (1000 - 500 - (-3500)) / 10000
    EXPECT_NEAR(tick_at(10000).force[0], -4250, 1e-2);  // 5000 · 8500 / 10000
}

TEST_F(Spring, AlongARampWithAsymmetricCoefficientsOffsetDeadbandAndSaturations) {
    play(condition(EffectType::spring, {Axis::x}, {block(6000, 3000, 1500, 4000, 2500, 800)}));
    expect_along(
        4001, [](int k) { return Point{-10000.0 + 5.0 * k, 0}; },
        [](int k, int axis, const TickOutput&) {
            if (axis != 0) return 0.0;
            return spring_force(-10000.0 + 5.0 * k, 1500, 6000, 3000, 4000, 2500, 800);
        });
}

TEST_F(Spring, AlongASineWithNegativeCoefficientsItPushesAway) {
    play(condition(EffectType::spring, {Axis::y}, {block(-4000, -7000, -500, 3000, 6000, 200)}));
    expect_along(
        2000, [](int k) { return Point{0, 9000.0 * std::sin(2 * kPi * k / 1000.0)}; },
        [](int k, int axis, const TickOutput&) {
            if (axis != 1) return 0.0;
            return spring_force(9000.0 * std::sin(2 * kPi * k / 1000.0), -500, -4000, -7000, 3000, 6000, 200);
        });
    // Spot check of the sign: past the offset on the + side, a negative coefficient pushes
    // further toward +.
    EXPECT_GT(tick_at(0, 2000).force[1], 0);
}

TEST_F(Spring, EachAxisFollowsItsOwnBlockInTheOrderOfTheAxes) {
    // axes [y, x]: block 0 acts on y, block 1 on x.
    play(condition(EffectType::spring, {Axis::y, Axis::x},
                   {block(2000, 2000, 0, 10000, 10000, 0), block(8000, 1000, 3000, 5000, 5000, 100)}));
    expect_along(
        3000, [](int k) { return Point{7000 * std::cos(2 * kPi * k / 1500.0), 7000 * std::sin(2 * kPi * k / 1500.0)}; },
        [](int k, int axis, const TickOutput&) {
            const double x = 7000 * std::cos(2 * kPi * k / 1500.0);
            const double y = 7000 * std::sin(2 * kPi * k / 1500.0);
            return axis == 0 ? spring_force(x, 3000, 8000, 1000, 5000, 5000, 100)
                             : spring_force(y, 0, 2000, 2000, 10000, 10000, 0);
        });
}

TEST_F(Spring, AnAngleSpringActsAlongItsCompassAngle) {
    // 30°: u = (sin 30°, cos 30°). The force is F(s)·u with s = x·u, whatever the motion
    // across the line.
    const double ux = 0.5, uy = std::sqrt(3.0) / 2;
    play(angle_spring(3000, block(5000, 2500, 1000, 3500, 10000, 400)));
    auto path = [](int k) {
        return Point{8000 * std::cos(2 * kPi * k / 1000.0), 6000 * std::sin(2 * kPi * k / 700.0)};
    };
    expect_along(2000, path, [&](int k, int axis, const TickOutput&) {
        const Point p = path(k);
        const double f = spring_force(p.x * ux + p.y * uy, 1000, 5000, 2500, 3500, 10000, 400);
        return f * (axis == 0 ? ux : uy);
    });
}

TEST_F(Spring, AnAngleSpringAtNinetyDegreesIsAnXSpring) {
    play(angle_spring(9000, block(7000, 3000, -2000, 6000, 2000, 300)));
    expect_along(
        2000, [](int k) { return Point{-9000.0 + 9.0 * k, 4000.0 - 4.0 * k}; },
        [](int k, int axis, const TickOutput&) {
            return axis == 0 ? spring_force(-9000.0 + 9.0 * k, -2000, 7000, 3000, 6000, 2000, 300) : 0.0;
        },
        1e-2);
}

TEST_F(Spring, SpringAtCurrentLocationHoldsTheHandleWhereItWasWhenStarted) {
    // §8.2 SpringAtCurrentLocation(K, Saturation, DeadBand): a relative offset of 0 on x, y.
    const ConditionBlock b = block(4000, 4000, 0, 3000, 3000, 250, OffsetMode::relative);
    const EffectId id = play(condition(EffectType::spring, {Axis::x, Axis::y}, {b, b}));
    const double x0 = 2500, y0 = -1200;
    EXPECT_NEAR(tick_at(x0, y0).force[0], 0, 1e-9);  // the first tick fixes the center
    expect_along(
        1500, [&](int k) { return Point{x0 + 5000 * std::sin(k / 200.0), y0 + 3000 * std::cos(k / 170.0)}; },
        [&](int k, int axis, const TickOutput&) {
            const double x = axis == 0 ? x0 + 5000 * std::sin(k / 200.0) : y0 + 3000 * std::cos(k / 170.0);
            return spring_force(x, axis == 0 ? x0 : y0, 4000, 4000, 3000, 3000, 250);
        });
    // Restarting re-centers it where the handle is now.
    ASSERT_TRUE(engine_->start(id).ok());
    EXPECT_NEAR(tick_at(-6000, 7000).force[0], 0, 1e-9);
    EXPECT_NEAR(tick_at(-5000, 7000).force[0], -4000.0 * (1000 - 250) / 10000, 1e-2);
}

TEST_F(Spring, ARelativeOffsetIsMeasuredFromTheStartPosition) {
    play(condition(EffectType::spring, {Axis::x}, {block(3000, 3000, -1500, 10000, 10000, 0, OffsetMode::relative)}));
    tick_at(4000);  // center = 4000 - 1500 = 2500
    EXPECT_NEAR(tick_at(2500).force[0], 0, 1e-9);
    EXPECT_NEAR(tick_at(6500).force[0], -1200, 1e-2);
    EXPECT_NEAR(tick_at(-500).force[0], 900, 1e-2);
}

TEST_F(Spring, ARelativeAngleSpringIsCenteredOnTheStartPositionAlongItsLine) {
    // 120°: u = (sin 120°, cos 120°). Started with the handle at (3000, 1000), the center
    // along the line is s0 + offset with s0 = 3000·u_x + 1000·u_y.
    const double ux = std::sqrt(3.0) / 2, uy = -0.5;
    play(angle_spring(12000, block(4000, 6000, 500, 10000, 10000, 0, OffsetMode::relative)));
    const double s0 = 3000 * ux + 1000 * uy;
    // 500 short of the center on the - side: k- = 6000 pushes toward +u with 300.
    const TickOutput first = tick_at(3000, 1000);
    EXPECT_NEAR(first.force[0], 300 * ux, 1e-2);
    EXPECT_NEAR(first.force[1], 300 * uy, 1e-2);
    auto path = [](int k) { return Point{3000 - 4.0 * k, 1000 + 3.0 * k}; };
    expect_along(1500, path, [&](int k, int axis, const TickOutput&) {
        const Point p = path(k);
        const double f = spring_force(p.x * ux + p.y * uy, s0 + 500, 4000, 6000, 10000, 10000, 0);
        return f * (axis == 0 ? ux : uy);
    });
}

TEST_F(Spring, CenterSpringPullsTowardTheCenterOnBothAxes) {
    // §8.2 CenterSpring(K, Saturation, DeadBand): K = 6000, saturation 4000, deadband 500.
    const ConditionBlock b = block(6000, 6000, 0, 4000, 4000, 500);
    play(condition(EffectType::spring, {Axis::x, Axis::y}, {b, b}));
    expect_along(
        2000, [](int k) { return Point{9000 * std::cos(k / 100.0), 9000 * std::sin(k / 130.0)}; },
        [](int k, int axis, const TickOutput&) {
            const double p = axis == 0 ? 9000 * std::cos(k / 100.0) : 9000 * std::sin(k / 130.0);
            const double magnitude = std::min(std::max(std::fabs(p) - 500, 0.0) * 6000 / 10000, 4000.0);
            return p > 0 ? -magnitude : magnitude;
        });
}

TEST_F(Spring, SeveralSpringsOnOneAxisSum) {
    // §3.2: a weak spring everywhere plus a stiff one beyond ±3000: the resistance rises
    // where the second one engages.
    play(condition(EffectType::spring, {Axis::x}, {block(1000, 1000)}));
    play(condition(EffectType::spring, {Axis::x}, {block(8000, 8000, 0, 5000, 5000, 3000)}));
    play(condition(EffectType::spring, {Axis::x}, {block(2000, 0, 6000)}));
    expect_along(
        4001, [](int k) { return Point{-10000.0 + 5.0 * k, 0}; },
        [](int k, int axis, const TickOutput&) {
            if (axis != 0) return 0.0;
            const double x = -10000.0 + 5.0 * k;
            return spring_force(x, 0, 1000, 1000, 10000, 10000, 0) +
                   spring_force(x, 0, 8000, 8000, 5000, 5000, 3000) +
                   spring_force(x, 6000, 2000, 0, 10000, 10000, 0);
        });
}

TEST_F(Spring, TheEffectGainScalesTheSpring) {
    EffectParams p = condition(EffectType::spring, {Axis::x}, {block(5000, 5000)});
    p.gain = 4000;
    play(p);
    EXPECT_NEAR(tick_at(6000).force[0], -0.4 * 3000, 1e-2);
}

}  // namespace
}  // namespace feel::test
