// A few wrappers played on the engine, their forces compared with the primer's physics
// written out here: a spring pushes back in proportion to the displacement (§3.2, the
// Condition Struct of §6.6.a), SpringatCurrentLocation centers on where the handle was,
// constant and vector forces push away from where they come from for as long as their
// duration says (§6.5.b, §8.3), a sine at a quarter period is at its peak (§4.2).
#include <gtest/gtest.h>

#include <memory>

#include "feel/engine.hpp"
#include "feel/iforce.hpp"

namespace feel::iforce {
namespace {

class WrapperForces : public ::testing::Test {
protected:
    WrapperForces() {
        EngineConfig c;
        c.axis_count = 2;
        engine_ = std::make_unique<Engine>(c);
    }

    void play(const EffectParams& p) {
        const CreateResult r = engine_->create(p);
        ASSERT_TRUE(r.error.ok()) << r.error.message();
        ASSERT_TRUE(engine_->start(r.id).ok());
    }

    // One tick with the handle at (x, y); the clock then advances by dt_us.
    TickOutput at(float x, float y, int64_t dt_us = 1000) {
        TickInput in;
        in.t_us = t_us_;
        in.position[0] = x;
        in.position[1] = y;
        TickOutput out;
        engine_->tick(in, out);
        t_us_ += dt_us;
        return out;
    }

    std::unique_ptr<Engine> engine_;
    int64_t t_us_ = 0;
};

TEST_F(WrapperForces, XSpringPushesBackInProportionToTheDisplacement) {
    // KPos 1000, KNeg 2000, offset 1000, no deadband, saturations 10000.
    play(x_spring(1000, 2000, 1000, 10000, 10000, 0));
    // Handle held still at each point (a few ticks so that the velocity estimate is 0).
    for (int i = 0; i < 5; ++i) (void)at(6000, 0);
    TickOutput out = at(6000, 0);
    EXPECT_NEAR(out.force[0], -1000.0 * (6000 - 1000) / 10000, 0.5);  // toward the offset
    EXPECT_NEAR(out.force[1], 0, 1e-3);                                // x only
}

TEST_F(WrapperForces, XSpringsNegativeSideUsesKNegAndItsSaturation) {
    play(x_spring(1000, 2000, 0, 10000, 300, 0));
    TickOutput out = at(-1000, 0);
    EXPECT_NEAR(out.force[0], +2000.0 * 1000 / 10000, 0.5);  // 200 < the negative saturation 300
    for (int i = 0; i < 3; ++i) out = at(-4000, 0);
    EXPECT_NEAR(out.force[0], +300, 0.5);                      // capped at NegSat
}

TEST_F(WrapperForces, CenterSpringPullsBothAxesToTheCenter) {
    play(center_spring(2000, 10000, 0));
    const TickOutput out = at(3000, -4000);
    EXPECT_NEAR(out.force[0], -2000.0 * 3000 / 10000, 0.5);
    EXPECT_NEAR(out.force[1], +2000.0 * 4000 / 10000, 0.5);
}

TEST_F(WrapperForces, SpringAtCurrentLocationCentersWhereTheHandleWas) {
    play(spring_at_current_location(2000, 10000, 0));
    TickOutput out = at(3000, -4000);  // first playing tick: the center is taken here
    EXPECT_NEAR(out.force[0], 0, 0.5);
    EXPECT_NEAR(out.force[1], 0, 0.5);
    out = at(3500, -4000);
    EXPECT_NEAR(out.force[0], -2000.0 * 500 / 10000, 0.5);
    EXPECT_NEAR(out.force[1], 0, 0.5);
}

TEST_F(WrapperForces, ConstantForceFromTheNorthPushesTowardTheUserForItsDuration) {
    play(constant_force(7500, 30000, 0));
    for (int64_t t = 0; t < 30000; t += 1000) {
        const TickOutput out = at(0, 0);
        ASSERT_NEAR(out.force[0], 0, 1e-2) << t;
        ASSERT_NEAR(out.force[1], -7500, 1e-2) << t;
    }
    EXPECT_NEAR(at(0, 0).force[1], 0, 1e-2);  // over after 30 ms
}

TEST_F(WrapperForces, VectorForceFromTheEastPushesLeftUntilStopped) {
    play(vector_force(5000, kInfiniteUs, 9000));
    for (int i = 0; i < 2000; ++i) {
        const TickOutput out = at(0, 0);
        ASSERT_NEAR(out.force[0], -5000, 1e-2) << i;
        ASSERT_NEAR(out.force[1], 0, 1e-2) << i;
    }
}

TEST_F(WrapperForces, SinePeaksAQuarterPeriodIn) {
    // A 100 Hz sine from the west (27000): its positive half pushes toward +x.
    play(periodic(Waveform::sine, 2000, 0, 0, 10000, 1000000, 27000, kNoTrigger, 0));
    TickOutput out;
    for (int i = 0; i <= 2; ++i) out = at(0, 0, 1250);  // ticks at 0, 1250, 2500 µs
    EXPECT_NEAR(out.force[0], +2000, 1.0);
    EXPECT_NEAR(out.force[1], 0, 1.0);
}

}  // namespace
}  // namespace feel::iforce
