// Barriers (§3.8, §6.6.g) with prescribed motion.
//
// The expected values come from Figure 3-13 and its text, written out here. A barrier of
// thickness t centered on offset o along u; the handle is on one side of it:
//   * on the negative side, the face at o − t/2 resists motion in +u with
//     −clamp(K·(s − (o − t/2)), ±10000);
//   * once the handle has pushed in by more than half the thickness (s > o) it has popped
//     through: it is on the positive side, where the face at o + t/2 pushes it on out
//     with +clamp(K·((o + t/2) − s)); at the center the force flips direction;
//   * and the same from the other side, popping back when s < o;
//   * K is the hardness "depending upon which direction you are crossing it": a crossing
//     that entered the slab moving in +u feels pos_hardness until it leaves the slab, one
//     that entered moving in −u feels neg_hardness.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_fixture.hpp"

namespace feel::test::contact {
namespace {

class BarrierTest : public ContactFixture {};

// The barrier's force along u for a handle at s on the given side (−1 or +1), during a
// crossing of stiffness k.
double barrier_force(double s, int side, double k, double t, double o) {
    if (side < 0) return -push_back(k, s - (o - t / 2));
    return push_back(k, (o + t / 2) - s);
}

TEST_F(BarrierTest, PushingPastHalfTheThicknessPopsThroughFromTheNegativeSide) {
    play(axis_barrier(Axis::x, 10000, 10000, 300, 500));  // faces at 350 and 650, center 500
    bool flipped = false;
    for (double x = 0; x <= 1000; x += 4) {
        const TickOutput out = at(x);
        const int side = x > 500 ? 1 : -1;
        ASSERT_NEAR(out.force[0], barrier_force(x, side, kWallK, 300, 500), kContactTolerance) << "x=" << x;
        if (x > 350 && x <= 500) {
            ASSERT_LT(out.force[0], 0.0f) << "resists going in, x=" << x;
        }
        if (x > 500 && x < 650) {
            ASSERT_GT(out.force[0], 0.0f) << "pushes on through, x=" << x;
            flipped = true;
        }
    }
    EXPECT_TRUE(flipped);
}

TEST_F(BarrierTest, AndFromThePositiveSide) {
    play(axis_barrier(Axis::x, 10000, 10000, 300, 500));
    for (double x = 1000; x >= 0; x -= 4) {
        const TickOutput out = at(x);
        const int side = x < 500 ? -1 : 1;
        ASSERT_NEAR(out.force[0], barrier_force(x, side, kWallK, 300, 500), kContactTolerance) << "x=" << x;
    }
}

TEST_F(BarrierTest, BackAndForthAcrossWithAsymmetricHardness) {
    // Crossing in +x feels pos_hardness 10000 all the way through, crossing back in −x
    // feels neg_hardness 4000: hard one way, soft the other.
    play(axis_barrier(Axis::x, 10000, 4000, 1000, -200));  // faces at −700 and 300
    const double k_pos = kWallK, k_neg = 0.4 * kWallK;
    for (int lap = 0; lap < 3; ++lap) {
        for (double x = -1500; x <= 1100; x += 5) {
            ASSERT_NEAR(at(x).force[0], barrier_force(x, x > -200 ? 1 : -1, k_pos, 1000, -200),
                        kContactTolerance)
                << "lap " << lap << " x=" << x;
        }
        for (double x = 1100; x >= -1500; x -= 5) {
            ASSERT_NEAR(at(x).force[0], barrier_force(x, x < -200 ? -1 : 1, k_neg, 1000, -200),
                        kContactTolerance)
                << "lap " << lap << " x=" << x;
        }
    }
}

TEST_F(BarrierTest, TheCrossingKeepsItsHardnessUntilTheHandleLeavesTheSlab) {
    play(axis_barrier(Axis::x, 8000, 2000, 600, 0));  // faces at ±300
    const double k_pos = 0.8 * kWallK, k_neg = 0.2 * kWallK;
    struct Leg {
        double from, to, k;
    };
    // In from the negative side (pos_hardness), through the center, back again before
    // reaching the far face, and out the near face: all of it at pos_hardness, popping
    // back at the center on the way. Then a fresh crossing from the negative side, and
    // one from the positive side (neg_hardness).
    for (const Leg leg : {Leg{-500, 200, k_pos}, Leg{200, -500, k_pos}, Leg{-500, 500, k_pos}, Leg{500, -500, k_neg}}) {
        const double step = leg.to > leg.from ? 4 : -4;
        for (double x = leg.from; step > 0 ? x <= leg.to : x >= leg.to; x += step) {
            const int side = x > 0 || (x == 0 && step < 0) ? 1 : -1;
            ASSERT_NEAR(at(x).force[0], barrier_force(x, side, leg.k, 600, 0), kContactTolerance)
                << "leg " << leg.from << ".." << leg.to << " x=" << x;
        }
    }
}

TEST_F(BarrierTest, PenetratingLessThanHalfAndBackingOutDoesNotPop) {
    play(axis_barrier(Axis::y, 8000, 8000, 600, 0));  // faces at −300 and 300
    const double k = 0.8 * kWallK;
    for (int rep = 0; rep < 3; ++rep) {
        for (double y = -800; y <= -10; y += 5) {
            ASSERT_NEAR(at(0, y).force[1], -push_back(k, y + 300), kContactTolerance) << "in, y=" << y;
        }
        for (double y = -10; y >= -800; y -= 5) {
            ASSERT_NEAR(at(0, y).force[1], -push_back(k, y + 300), kContactTolerance) << "out, y=" << y;
        }
    }
}

TEST_F(BarrierTest, StartingInsideTakesTheSideOfTheCenterItIsOn) {
    play(axis_barrier(Axis::x, 10000, 10000, 400, 1000));  // faces at 800 and 1200
    // 1050 is past the center on the positive side: the positive face pushes it out to +x.
    EXPECT_NEAR(at(1050).force[0], kWallK * 150, kContactTolerance);
    reset(contact_config());
    play(axis_barrier(Axis::x, 10000, 10000, 400, 1000));
    EXPECT_NEAR(at(950).force[0], -kWallK * 150, kContactTolerance);
}

TEST_F(BarrierTest, ThickBarrierSaturatesBeforeItPops) {
    // K·t/2 = 50·500 = 25000 > 10000: the user must push through full motor force.
    play(axis_barrier(Axis::x, 10000, 10000, 1000, 0));
    for (double x = -1000; x <= 1000; x += 5) {
        const TickOutput out = at(x);
        ASSERT_NEAR(out.force[0], barrier_force(x, x > 0 ? 1 : -1, kWallK, 1000, 0), kContactTolerance);
        ASSERT_LE(std::fabs(out.force[0]), 10000.0f);
    }
}

TEST_F(BarrierTest, AngleBarrierWorksAlongItsAngle) {
    for (const int32_t angle : {0, 4500, 12000, 27000}) {
        reset(contact_config());
        play(angle_barrier(angle, 6000, 9000, 400, 300));
        const double ux = compass_x(angle), uy = compass_y(angle);
        const double k_pos = 0.6 * kWallK;
        for (double s = -500; s <= 1100; s += 4) {
            const TickOutput out = at(s * ux - 250 * uy, s * uy + 250 * ux);
            const double f = barrier_force(s, s > 300 ? 1 : -1, k_pos, 400, 300);  // a +u crossing
            ASSERT_NEAR(out.force[0], f * ux, 0.05) << "angle=" << angle << " s=" << s;
            ASSERT_NEAR(out.force[1], f * uy, 0.05) << "angle=" << angle << " s=" << s;
        }
    }
}

TEST_F(BarrierTest, SurfaceFrictionRubsInPressureMode) {
    EffectParams barrier = axis_barrier(Axis::y, 10000, 10000, 400, 0);  // faces at ±200
    barrier.barrier.surface_friction = 6000;
    play(barrier);
    // Pressed 50 into the negative face (N = 2500), sliding along x at 30000 units/s.
    const double n = kWallK * 50, speed = 30000;
    for (int k = 0; k < 60; ++k) {
        const TickOutput out = at(speed * 1e-3 * k, -150);
        if (k < 20) continue;
        ASSERT_NEAR(out.force[1], -n, kContactTolerance);
        ASSERT_NEAR(out.force[0], -0.6 * n * std::tanh(speed / 1e4), 0.05);
    }
}

TEST_F(BarrierTest, PassivityControllerLeavesASlowCrossingExactlyAlone) {
    // At one sensor count per tick or less the ledger books nothing, and the pop itself is
    // not generated energy: the force is the formula all the way through and back.
    reset(contact_config(2, /*passivity=*/true));
    play(axis_barrier(Axis::x, 10000, 10000, 300, 0));
    const double step = 20000.0 / 4096.0;
    for (double x = -400; x <= 400; x += step) {
        ASSERT_NEAR(at(x).force[0], barrier_force(x, x > 0 ? 1 : -1, kWallK, 300, 0), kContactTolerance)
            << "x=" << x;
    }
    for (double x = 400; x >= -400; x -= step) {
        ASSERT_NEAR(at(x).force[0], barrier_force(x, x < 0 ? -1 : 1, kWallK, 300, 0), kContactTolerance)
            << "x=" << x;
    }
}

// §3.8: "The Offset-Flag ... same as the wall": with a relative offset the barrier's center
// is measured from where the handle is when the effect starts (along u), as the wall's
// surface is (§3.7), and every restart takes the new position.
TEST_F(BarrierTest, ARelativeOffsetCentersTheBarrierFromTheStartPosition) {
    EffectParams p = axis_barrier(Axis::x, 10000, 10000, 300, 500);
    p.barrier.offset_mode = OffsetMode::relative;
    const EffectId id = play(p);
    const double start = -2000;  // center at -2000 + 500 = -1500, faces at -1650 and -1350
    at(start);
    for (double x = start; x <= -1000; x += 4) {
        const TickOutput out = at(x);
        ASSERT_NEAR(out.force[0], barrier_force(x, x > -1500 ? 1 : -1, kWallK, 300, -1500), kContactTolerance)
            << "x=" << x;
    }
    // Restarted at 3000: center 3500, the old place is free space now.
    ASSERT_TRUE(engine_->start(id).ok());
    at(3000);
    EXPECT_NEAR(at(-1500 + 100).force[0], 0, 1e-9);
    EXPECT_NEAR(at(3400).force[0], barrier_force(3400, -1, kWallK, 300, 3500), kContactTolerance);
}

TEST_F(BarrierTest, ARelativeAngleBarrierIsCenteredOnTheStartPositionAlongItsAngle) {
    const int32_t angle = 12000;
    const double ux = compass_x(angle), uy = compass_y(angle);
    EffectParams p = angle_barrier(angle, 6000, 9000, 400, 300);
    p.barrier.offset_mode = OffsetMode::relative;
    play(p);
    const double x0 = 1200, y0 = -800;  // s0 = x0·ux + y0·uy; the center is s0 + 300
    const double s0 = x0 * ux + y0 * uy;
    at(x0, y0);
    const double k_pos = 0.6 * kWallK;
    for (double d = 0; d <= 1100; d += 4) {  // from the start along +u, with a sideways offset
        const double s = s0 + d;
        const TickOutput out = at(x0 + d * ux - 250 * uy, y0 + d * uy + 250 * ux);
        const double f = barrier_force(s, s > s0 + 300 ? 1 : -1, k_pos, 400, s0 + 300);
        ASSERT_NEAR(out.force[0], f * ux, 0.05) << "d=" << d;
        ASSERT_NEAR(out.force[1], f * uy, 0.05) << "d=" << d;
    }
}

}  // namespace
}  // namespace feel::test::contact
