// Walls (§3.7, §6.6.h) with prescribed motion: the force along ramps in both directions,
// both senses, absolute and relative offsets, hardness and saturation, angles, clipping of
// the reported position, and pressure-mode surface friction and texture.
//
// The expected values come from the definitions, written out here:
//   * positive sense resists crossing the wall while moving in +u, so the solid side is
//     s > surface and the force is −clamp(K·(s − surface), ±10000)·u there;
//   * negative sense mirrors it: solid s < surface, force +clamp(K·(surface − s))·u;
//   * K = hardness/10000 · wall_stiffness; angle a: u = (sin a, cos a), s = position·u;
//   * relative offset: surface = (position when the effect starts)·u + offset;
//   * clipping: the reported position is the sensed one moved back onto the surface;
//   * pressure mode: rubbing force N·(μ + τ·bump)·tanh(|v|/v_s) against the motion along
//     the surface, N the wall's normal force, v_s = 0.1·velocity_ref.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact_fixture.hpp"

namespace feel::test::contact {
namespace {

class WallTest : public ContactFixture {};

TEST_F(WallTest, PositiveSenseIsFreeBelowTheSurfaceAndPushesBackAbove) {
    play(axis_wall(Axis::x, 10000, WallSense::positive, 1000));
    // In at 5 units per tick and back out again: the same force both ways (a spring).
    for (int k = 0; k <= 1200; ++k) {
        const double x = k <= 600 ? -1000 + 5.0 * k : 2000 - 5.0 * (k - 600);
        const TickOutput out = at(x, 300);
        ASSERT_NEAR(out.force[0], -push_back(kWallK, x - 1000), kContactTolerance) << "x=" << x;
        ASSERT_NEAR(out.force[1], 0.0, kContactTolerance) << "x=" << x;
    }
}

TEST_F(WallTest, NegativeSenseIsFreeAboveTheSurfaceAndPushesBackBelow) {
    play(axis_wall(Axis::x, 10000, WallSense::negative, -1500));
    for (int k = 0; k <= 1000; ++k) {
        const double x = k <= 500 ? 500 - 6.0 * k : -2500 + 6.0 * (k - 500);
        const TickOutput out = at(x);
        ASSERT_NEAR(out.force[0], push_back(kWallK, -1500 - x), kContactTolerance) << "x=" << x;
    }
}

TEST_F(WallTest, HardnessScalesTheStiffnessAndANegativeHardnessPullsIn) {
    for (const int32_t hardness : {2500, 10000, -4000}) {
        reset(contact_config());
        play(axis_wall(Axis::y, hardness, WallSense::positive, 0));
        const double k = hardness / 10000.0 * kWallK;
        for (double y = -200; y <= 400; y += 10) {
            const TickOutput out = at(0, y);
            // Force along +y: −clamp(k·depth); for k < 0 that is a pull deeper into the wall.
            const double expected = y > 0 ? -std::clamp(k * y, -10000.0, 10000.0) : 0.0;
            ASSERT_NEAR(out.force[1], expected, kContactTolerance) << "hardness=" << hardness << " y=" << y;
            ASSERT_NEAR(out.force[0], 0.0, kContactTolerance);
        }
    }
}

TEST_F(WallTest, ForceSaturatesAtFullScale) {
    play(axis_wall(Axis::x, 10000, WallSense::positive, 0));
    // K·depth = 50·depth reaches 10000 at depth 200.
    EXPECT_NEAR(at(199).force[0], -9950.0, kContactTolerance);
    EXPECT_NEAR(at(200).force[0], -10000.0, kContactTolerance);
    EXPECT_NEAR(at(5000).force[0], -10000.0, kContactTolerance);
}

TEST_F(WallTest, RelativeOffsetIsMeasuredFromWhereTheHandleWasWhenTheWallStarted) {
    const EffectId id = play(axis_wall(Axis::x, 10000, WallSense::positive, 1000, OffsetMode::relative));
    const double start = -2345;
    // Surface at start + 1000 = -1345.
    for (double x = start; x <= 0; x += 7) {
        const TickOutput out = at(x);
        ASSERT_NEAR(out.force[0], -push_back(kWallK, x - (start + 1000)), kContactTolerance) << "x=" << x;
    }
    // Restarting re-anchors the wall where the handle is now: surface at 3000 + 1000.
    ASSERT_TRUE(engine_->start(id).ok());
    for (double x = 3000; x <= 4500; x += 7) {
        const TickOutput out = at(x);
        ASSERT_NEAR(out.force[0], -push_back(kWallK, x - 4000), kContactTolerance) << "x=" << x;
    }
}

TEST_F(WallTest, RelativeOffsetWithNegativeSense) {
    play(axis_wall(Axis::y, 6000, WallSense::negative, -500, OffsetMode::relative));
    const double start = 800;  // surface at 300, solid below it
    const double k = 0.6 * kWallK;
    for (double y = start; y >= -800; y -= 5) {
        const TickOutput out = at(-100, y);
        ASSERT_NEAR(out.force[1], push_back(k, 300 - y), kContactTolerance) << "y=" << y;
    }
}

TEST_F(WallTest, HorizontalWallActsOnYOnly) {
    // A HorizontalWall (§8.2): an axis_wall on y. Sliding along x never makes an x force
    // (no surface friction here).
    play(axis_wall(Axis::y, 10000, WallSense::positive, 2000));
    for (int k = 0; k < 800; ++k) {
        const double x = -4000 + 10.0 * k;
        const double y = 1900 + 0.25 * k;
        const TickOutput out = at(x, y);
        ASSERT_NEAR(out.force[0], 0.0, kContactTolerance);
        ASSERT_NEAR(out.force[1], -push_back(kWallK, y - 2000), kContactTolerance) << "y=" << y;
    }
}

TEST_F(WallTest, AngleWallPushesAlongItsCompassAngle) {
    for (const int32_t angle : {0, 3000, 4500, 9000, 13500, 18000, 22500, 27000, 33000}) {
        reset(contact_config());
        play(angle_wall(angle, 10000, WallSense::positive, 200));
        const double ux = compass_x(angle), uy = compass_y(angle);
        // The handle crosses the wall along u, 700 units to the side along the tangent.
        for (double s = -1000; s <= 1500; s += 5) {
            const double x = s * ux + 700 * uy;
            const double y = s * uy - 700 * ux;
            const TickOutput out = at(x, y);
            const double push = push_back(kWallK, s - 200);
            ASSERT_NEAR(out.force[0], -push * ux, 0.05) << "angle=" << angle << " s=" << s;
            ASSERT_NEAR(out.force[1], -push * uy, 0.05) << "angle=" << angle << " s=" << s;
        }
    }
}

TEST_F(WallTest, AngleWallNegativeSenseIsSolidBehindItsLine) {
    play(angle_wall(6000, 5000, WallSense::negative, -300));
    const double ux = compass_x(6000), uy = compass_y(6000);
    const double k = 0.5 * kWallK;
    for (double s = 500; s >= -900; s -= 4) {
        const TickOutput out = at(s * ux, s * uy);
        const double push = push_back(k, -300 - s);
        ASSERT_NEAR(out.force[0], push * ux, 0.05) << "s=" << s;
        ASSERT_NEAR(out.force[1], push * uy, 0.05) << "s=" << s;
    }
}

TEST_F(WallTest, AngleWallsAtTheAxisAnglesAreHorizontalAndVerticalWalls) {
    // angle 9000: u = +x, the wall x = 1000, solid beyond it; 27000: u = −x, so s = −x and
    // the wall is x = −1000 with the solid at x < −1000; 0 and 18000 likewise on y. The
    // other axis gets exactly no force.
    struct Case {
        int32_t angle;
        int axis;
        double sign;  // u along the axis
    };
    for (const Case c : {Case{0, 1, 1.0}, Case{9000, 0, 1.0}, Case{18000, 1, -1.0}, Case{27000, 0, -1.0}}) {
        reset(contact_config());
        play(angle_wall(c.angle, 10000, WallSense::positive, 1000));
        for (double q = -2000; q <= 2000; q += 8) {
            const TickOutput out = c.axis == 0 ? at(q, 333) : at(333, q);
            const double push = push_back(kWallK, c.sign * q - 1000);
            ASSERT_NEAR(out.force[c.axis], -push * c.sign, kContactTolerance) << c.angle << " q=" << q;
            ASSERT_EQ(out.force[1 - c.axis], 0.0f) << c.angle << " q=" << q;
        }
    }
}

TEST_F(WallTest, ClippingHoldsTheReportedPositionAtTheSurface) {
    EffectParams wall = axis_wall(Axis::x, 10000, WallSense::positive, 1000);
    wall.wall.clipping = true;
    play(wall);
    for (double x = 0; x <= 3000; x += 3) {
        const TickOutput out = at(x, -250);
        ASSERT_EQ(out.reported_position[0], static_cast<float>(std::min(x, 1000.0))) << "x=" << x;
        ASSERT_EQ(out.reported_position[1], -250.0f);
    }
}

TEST_F(WallTest, ClippingWithNegativeSenseOnY) {
    EffectParams wall = axis_wall(Axis::y, 3000, WallSense::negative, -2000);
    wall.wall.clipping = true;
    play(wall);
    for (double y = 0; y >= -5000; y -= 11) {
        const TickOutput out = at(1234, y);
        ASSERT_EQ(out.reported_position[1], static_cast<float>(std::max(y, -2000.0))) << "y=" << y;
        ASSERT_EQ(out.reported_position[0], 1234.0f);
    }
}

TEST_F(WallTest, ClippingOffReportsTheSensedPosition) {
    play(axis_wall(Axis::x, 10000, WallSense::positive, 0));
    for (double x = -500; x <= 2000; x += 13) {
        const TickOutput out = at(x, 77);
        ASSERT_EQ(out.reported_position[0], static_cast<float>(x));
        ASSERT_EQ(out.reported_position[1], 77.0f);
    }
}

TEST_F(WallTest, ClippingAngleWallsAtAxisAnglesTouchesOneAxisOnly) {
    for (const int32_t angle : {0, 9000, 18000, 27000}) {
        reset(contact_config());
        EffectParams wall = angle_wall(angle, 10000, WallSense::positive, 1500);
        wall.wall.clipping = true;
        play(wall);
        const double ux = std::round(compass_x(angle)), uy = std::round(compass_y(angle));
        for (double s = 0; s <= 4000; s += 9) {
            const double x = s * ux + 321 * uy, y = s * uy - 321 * ux;
            const TickOutput out = at(x, y);
            const double held = std::min(s, 1500.0);
            ASSERT_EQ(out.reported_position[0], static_cast<float>(held * ux + 321 * uy)) << angle << " s=" << s;
            ASSERT_EQ(out.reported_position[1], static_cast<float>(held * uy - 321 * ux)) << angle << " s=" << s;
        }
    }
}

TEST_F(WallTest, ClippingAnObliqueWallProjectsOntoTheWallLine) {
    EffectParams wall = angle_wall(4500, 10000, WallSense::positive, 1000);
    wall.wall.clipping = true;
    play(wall);
    const double ux = compass_x(4500), uy = compass_y(4500);
    for (double s = 0; s <= 3000; s += 10) {
        const double x = s * ux + 600 * uy, y = s * uy - 600 * ux;
        const TickOutput out = at(x, y);
        const double rs = out.reported_position[0] * ux + out.reported_position[1] * uy;
        const double rt = out.reported_position[0] * uy - out.reported_position[1] * ux;
        ASSERT_LE(rs, 1000.0 + 1e-3) << "s=" << s;          // never inside
        ASSERT_NEAR(rs, std::min(s, 1000.0), 2e-3) << "s=" << s;
        ASSERT_NEAR(rt, 600.0, 2e-3) << "s=" << s;            // slides along the wall
    }
}

TEST_F(WallTest, RelativeClippingFollowsTheRelativeSurface) {
    EffectParams wall = axis_wall(Axis::x, 10000, WallSense::negative, -250, OffsetMode::relative);
    wall.wall.clipping = true;
    play(wall);
    // Starts at 1000.5: surface at 750.5 (not a whole number, not exactly a float sum).
    for (double x = 1000.5; x >= 0; x -= 3) {
        const TickOutput out = at(x);
        ASSERT_GE(out.reported_position[0], 750.5f) << "x=" << x;
        ASSERT_NEAR(out.reported_position[0], std::max(x, 750.5), 1e-3) << "x=" << x;
    }
}

// Pressure mode: the handle presses into a horizontal wall (y) at a fixed depth, so the
// wall's normal force is N = K·depth, and slides along x at a steady speed.
class WallSurfaceTest : public ContactFixture {
protected:
    static constexpr double kSlip = 0.1 * 1e5;  // v_s = 0.1·velocity_ref

    // The mean x force over the ticks after the velocity estimate has settled.
    double rub(double depth, double speed, int32_t friction, int32_t texture, double x0 = 0) {
        reset(contact_config());
        EffectParams wall = axis_wall(Axis::y, 10000, WallSense::positive, 0);
        wall.wall.surface_friction = friction;
        wall.wall.surface_texture = texture;
        play(wall);
        double sum = 0;
        int n = 0;
        for (int k = 0; k < 60; ++k) {
            const TickOutput out = at(x0 + speed * 1e-3 * k, depth);
            if (k >= 20) {
                EXPECT_NEAR(out.velocity[0], speed, 1e-3 * std::fabs(speed) + 1) << "estimator precondition";
                sum += out.force[0];
                ++n;
            }
        }
        return sum / n;
    }
};

TEST_F(WallSurfaceTest, FrictionOpposesSlidingAndScalesWithHowHardTheHandlePushes) {
    for (const double speed : {20000.0, -20000.0, 5000.0}) {
        for (const double depth : {40.0, 120.0}) {
            const double n = kWallK * depth;  // 2000 or 6000
            const double expected = -n * 0.5 * std::tanh(std::fabs(speed) / kSlip) * (speed > 0 ? 1 : -1);
            EXPECT_NEAR(rub(depth, speed, 5000, 0), expected, 1e-2 * std::fabs(expected))
                << "speed=" << speed << " depth=" << depth;
        }
    }
}

TEST_F(WallSurfaceTest, NoRubbingOffTheSurface) {
    EXPECT_EQ(rub(-50, 20000, 10000, 10000), 0.0);
}

TEST_F(WallSurfaceTest, TextureAddsResistanceOnRidgesEveryTwoHundredUnits) {
    // Slow enough to sample each ridge: 2 units per tick. Ridges at multiples of 200, each
    // a raised cosine 100 wide; τ = 0.8; μ = 0.
    const double depth = 100, n = kWallK * depth, speed = 2000;
    reset(contact_config());
    EffectParams wall = axis_wall(Axis::y, 10000, WallSense::positive, 0);
    wall.wall.surface_texture = 8000;
    play(wall);
    int on_ridge = 0, between = 0;
    for (int k = 0; k < 400; ++k) {
        const double x = -130 + 2.0 * k;
        const TickOutput out = at(x, depth);
        if (k < 20) continue;
        const double d = std::fabs(x - 200 * std::round(x / 200));
        const double bump = d < 50 ? 0.5 * (1 + std::cos(2 * std::numbers::pi * d / 100)) : 0.0;
        const double expected = -n * 0.8 * bump * std::tanh(speed / kSlip);
        ASSERT_NEAR(out.force[0], expected, 1e-3 * n) << "x=" << x;
        if (bump == 1.0) ++on_ridge;
        if (bump == 0.0) ++between;
    }
    EXPECT_GT(on_ridge, 0);
    EXPECT_GT(between, 0);
}

TEST_F(WallSurfaceTest, ObliqueWallRubsAlongItsTangent) {
    // angle 3000 (30°): u = (sin 30°, cos 30°), tangent t = (cos 30°, −sin 30°).
    const int32_t angle = 3000;
    const double ux = compass_x(angle), uy = compass_y(angle), tx = uy, ty = -ux;
    EffectParams wall = angle_wall(angle, 10000, WallSense::positive, 0);
    wall.wall.surface_friction = 10000;
    play(wall);
    const double depth = 60, n = kWallK * depth, speed = 15000;
    for (int k = 0; k < 60; ++k) {
        const double r = speed * 1e-3 * k;
        const TickOutput out = at(depth * ux + r * tx, depth * uy + r * ty);
        if (k < 20) continue;
        const double rub = n * 1.0 * std::tanh(speed / kSlip);
        ASSERT_NEAR(out.force[0], -n * ux - rub * tx, 0.5) << k;
        ASSERT_NEAR(out.force[1], -n * uy - rub * ty, 0.5) << k;
    }
}

TEST_F(WallSurfaceTest, AFloorOnAThreeAxisDeviceRubsAgainstTheMotionInItsPlane) {
    // An axis_wall on z (a floor at z = 0 with the solid below: negative sense). Sliding
    // diagonally in x, y: the friction opposes the velocity vector, one force of magnitude
    // μ·N·tanh(|v|/v_s), not one per axis.
    reset(contact_config(3));
    EffectParams floor = axis_wall(Axis::z, 10000, WallSense::negative, 0);
    floor.wall.surface_friction = 4000;
    play(floor);
    const double depth = 80, n = kWallK * depth, vx = 9000, vy = -12000, speed = 15000;
    for (int k = 0; k < 60; ++k) {
        const TickOutput out = at(vx * 1e-3 * k, vy * 1e-3 * k, -depth);
        if (k < 20) continue;
        const double rub = 0.4 * n * std::tanh(speed / kSlip);
        ASSERT_NEAR(out.force[0], -rub * vx / speed, 0.5) << k;
        ASSERT_NEAR(out.force[1], -rub * vy / speed, 0.5) << k;
        ASSERT_NEAR(out.force[2], n, kContactTolerance) << k;
    }
}

TEST_F(WallTest, PassivityControllerLeavesSlowContactExactlyAlone) {
    // At most one sensor count of motion per tick the ledger books nothing (the sensor
    // cannot tell such motion from quantization), so the controller never touches the
    // force: it equals the formula, in and out, and at rest.
    reset(contact_config(2, /*passivity=*/true));
    play(axis_wall(Axis::x, 10000, WallSense::positive, 0));
    const double step = 20000.0 / 4096.0;
    for (int k = 0; k <= 400; ++k) {
        const double x = k <= 200 ? -100 + step * k : -100 + step * (400 - k);
        const TickOutput out = at(x);
        ASSERT_NEAR(out.force[0], -push_back(kWallK, x), kContactTolerance) << "x=" << x;
    }
    // In again, slowly, and rest at depth 150.
    for (double x = -100; x < 150; x += step) ASSERT_NEAR(at(x).force[0], -push_back(kWallK, x), kContactTolerance);
    for (int k = 0; k < 100; ++k) ASSERT_NEAR(at(150).force[0], -7500.0, kContactTolerance);
}

TEST_F(WallTest, EffectGainScalesTheWall) {
    EffectParams wall = axis_wall(Axis::x, 10000, WallSense::positive, 0);
    wall.gain = 2500;
    play(wall);
    EXPECT_NEAR(at(100).force[0], -0.25 * 5000.0, kContactTolerance);
}

}  // namespace
}  // namespace feel::test::contact
