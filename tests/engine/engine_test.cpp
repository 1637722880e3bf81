// The engine's common machinery: gains, summing, clamping, slots and handles.
#include <array>
#include <vector>

#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using EngineMachinery = EngineFixture;

TEST_F(EngineMachinery, EffectsOnAnAxisSum) {
    play(constant_on_x(1000, kInfiniteUs));
    play(constant_on_x(-300, kInfiniteUs));
    play(on_xy_polar(constant_on_x(2000, kInfiniteUs), 18000));  // from the south: +y
    const TickOutput out = tick();
    EXPECT_NEAR(out.force[0], 700, kForceTolerance);
    EXPECT_NEAR(out.force[1], 2000, kForceTolerance);
    EXPECT_EQ(out.playing_effects, 3);
}

TEST_F(EngineMachinery, EffectGainAndDeviceGainScale) {
    EffectParams p = constant_on_x(8000, kInfiniteUs);
    p.gain = 5000;
    play(p);
    EXPECT_NEAR(tick().force[0], 4000, kForceTolerance);
    ASSERT_TRUE(engine_->set_gain(2500).ok());
    EXPECT_NEAR(tick().force[0], 1000, kForceTolerance);
    EXPECT_EQ(engine_->gain(), 2500);
}

TEST_F(EngineMachinery, DeviceGainOutOfRangeIsRefusedAndNothingChanges) {
    const Error e = engine_->set_gain(10001);
    EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(e.field, "gain");
    EXPECT_EQ(e.allowed.min, 0);
    EXPECT_EQ(e.allowed.max, 10000);
    EXPECT_EQ(engine_->gain(), 10000);
}

TEST_F(EngineMachinery, SumIsClampedToTheDeviceMaximumAndReportsSaturation) {
    play(constant_on_x(9000, kInfiniteUs));
    play(constant_on_x(9000, kInfiniteUs));
    TickOutput out = tick();
    EXPECT_EQ(out.force[0], 10000.0f);
    EXPECT_TRUE(out.saturated);
    reset(2);
    play(constant_on_x(-9000, kInfiniteUs));
    play(constant_on_x(-9000, kInfiniteUs));
    out = tick();
    EXPECT_EQ(out.force[0], -10000.0f);
    EXPECT_TRUE(out.saturated);
}

TEST_F(EngineMachinery, PoolRefusesTheEffectThatDoesNotFitAndDisturbsNothing) {
    reset(2, 4);
    std::vector<EffectId> ids;
    for (int i = 0; i < 4; ++i) ids.push_back(play(constant_on_x(1000, kInfiniteUs)));
    const CreateResult full = engine_->create(constant_on_x(1000, kInfiniteUs));
    EXPECT_EQ(full.error.code, ErrorCode::device_full);
    EXPECT_FALSE(full.id.valid());
    EXPECT_EQ(tick().force[0], 4000.0f);  // the four resident effects still play
}

TEST_F(EngineMachinery, FreedSlotIsReusedAndTheOldHandleGoesStale) {
    reset(2, 1);
    const EffectId first = create(constant_on_x(1000, kInfiniteUs));
    ASSERT_TRUE(engine_->destroy(first).ok());
    const EffectId second = create(constant_on_x(2000, kInfiniteUs));
    EXPECT_EQ(first.index, second.index);
    EXPECT_NE(first.generation, second.generation);
    EXPECT_EQ(engine_->start(first).code, ErrorCode::invalid_handle);
    EXPECT_EQ(engine_->destroy(first).code, ErrorCode::invalid_handle);
    EXPECT_EQ(engine_->state(first), EffectState::free);
    EXPECT_EQ(engine_->state(second), EffectState::stopped);
}

TEST_F(EngineMachinery, SampleMemoryIsFixedAndCompactsBeforeSayingFull) {
    reset(2, 8, 30);
    const std::array<int16_t, 10> ten{};
    const std::array<int16_t, 20> twenty{};
    EffectParams p = constant_on_x(0, 10'000);
    p.type = EffectType::force_profile;
    p.custom = {1, 1000, 10};
    const EffectId a = create(p, ten);
    const EffectId b = create(p, ten);
    const EffectId c = create(p, ten);
    (void)b;
    // Full: 30 of 30.
    EXPECT_EQ(engine_->create(p, ten).error.code, ErrorCode::device_full);
    // Free a and c: 20 free, but in two gaps of 10. A 20-sample profile fits only by
    // compaction.
    ASSERT_TRUE(engine_->destroy(a).ok());
    ASSERT_TRUE(engine_->destroy(c).ok());
    p.custom.sample_count = 20;
    const CreateResult big = engine_->create(p, twenty);
    EXPECT_TRUE(big.error.ok()) << big.error.message();
    p.custom.sample_count = 10;
    EXPECT_EQ(engine_->create(p, ten).error.code, ErrorCode::device_full);
}

TEST_F(EngineMachinery, CompactionKeepsEveryProfileIntact) {
    reset(1, 8, 6);
    EffectParams p = constant_on_x(0, kInfiniteUs);
    p.type = EffectType::force_profile;
    p.custom = {1, 1000, 2};
    const std::array<int16_t, 2> first = {1, 2}, middle = {3, 4}, last = {5, 6};
    const EffectId a = create(p, first);
    const EffectId b = create(p, middle);
    const EffectId c = create(p, last);
    ASSERT_TRUE(engine_->destroy(a).ok());
    ASSERT_TRUE(engine_->destroy(c).ok());
    const EffectId d = create(p, first);  // fits the first gap
    p.custom = {1, 1000, 2};
    (void)d;
    // b still plays its own samples after any moves.
    ASSERT_TRUE(engine_->start(b).ok());
    EXPECT_EQ(tick().force[0], 3.0f);
    EXPECT_EQ(tick().force[0], 4.0f);
}

TEST_F(EngineMachinery, AnAxisTheDeviceLacksIsRefused) {
    reset(1);  // a wheel: x only
    EffectParams p = constant_on_x(1000, kInfiniteUs);
    p.axes[0] = Axis::y;
    const CreateResult r = engine_->create(p);
    EXPECT_EQ(r.error.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(r.error.field, "axes[0]");
}

TEST_F(EngineMachinery, InvalidConfigRefusesEveryCreate) {
    EngineConfig c;
    c.axis_count = 7;
    Engine bad(c);
    const CreateResult r = bad.create(constant_on_x(1000, kInfiniteUs));
    EXPECT_EQ(r.error.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(r.error.field, "axis_count");
    TickOutput out;
    bad.tick(TickInput{}, out);
    EXPECT_EQ(out.force[0], 0.0f);
}

TEST_F(EngineMachinery, InvalidParamsAreRefusedByTheSharedValidator) {
    EffectParams p = periodic_on_x(EffectType::sine, 1000, 0, 10'000, 36000, kInfiniteUs);
    const CreateResult r = engine_->create(p);
    EXPECT_EQ(r.error.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(r.error.field, "periodic.phase");
    EXPECT_EQ(r.error.allowed.max, 35999);
}

TEST_F(EngineMachinery, AConstantSpeedRampReadsItsExactVelocity) {
    // 10 units every 2 ms, unquantized: every window of the estimator sees a straight line,
    // so from the second tick on the velocity is the ramp's slope and the acceleration 0.
    // (An inertia of no mass plays: the engine fits the acceleration when one reads it.)
    EffectParams inertia;
    inertia.type = EffectType::inertia;
    const CreateResult created = engine_->create(inertia, {});
    ASSERT_TRUE(created.error.ok());
    ASSERT_TRUE(engine_->start(created.id).ok());
    TickInput in;
    TickOutput out;
    for (int k = 0; k < 80; ++k) {
        in.t_us = 2000 * k;
        in.position[0] = 100.0f + 10.0f * static_cast<float>(k);
        engine_->tick(in, out);
        if (k == 0) continue;
        // The estimator is single precision: a few float ulps of the speed, and an
        // acceleration within 2e-6 of the default acceleration_ref (1e7 units/s²).
        ASSERT_NEAR(out.velocity[0], 5'000, 2e-6 * 5'000) << "tick " << k;
        ASSERT_NEAR(out.acceleration[0], 0, 20.0) << "tick " << k;
        ASSERT_EQ(out.velocity[1], 0.0f) << "tick " << k;  // y holds still
    }
}

}  // namespace
}  // namespace feel::test
