// The engine's common machinery: gains, summing, clamping, slots and handles.
#include <array>
#include <limits>
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

// Every field of EngineConfig with a rule, just outside it: the refusal names the field and
// the value with the range engine.hpp documents, or the rule's sentence, in the order the
// fields are checked (the config is otherwise the default).
TEST_F(EngineMachinery, InvalidConfigNamesTheFieldAndItsRange) {
    struct Case {
        void (*set)(EngineConfig&);
        const char* field;
        int64_t value, min, max;  // for a range
        const char* rule;         // else
    };
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    const Case cases[] = {
        {[](EngineConfig& c) { c.axis_count = 0; }, "axis_count", 0, 1, kMaxAxes, nullptr},
        {[](EngineConfig& c) { c.max_effects = 65536; }, "max_effects", 65536, 1, 65535, nullptr},
        {[](EngineConfig& c) { c.max_samples = (1 << 24) + 1; }, "max_samples", (1 << 24) + 1, 0, 1 << 24, nullptr},
        {[](EngineConfig& c) { c.pool_bytes = -1; }, "pool_bytes", -1, 0, 1 << 30, nullptr},
        {[](EngineConfig& c) { c.max_effects = 8, c.max_dynamics = 9; }, "max_dynamics", 9, 0, 8, nullptr},
        {[](EngineConfig& c) { c.max_effects = 8, c.max_stateful_conditions = 9; }, "max_stateful_conditions", 9, 0, 8,
         nullptr},
        {[](EngineConfig& c) { c.velocity_ref = 0; }, "velocity_ref", 0, 0, 0, "must be a finite number > 0"},
        {[](EngineConfig& c) { c.acceleration_ref = kNaN; }, "acceleration_ref", 0, 0, 0,
         "must be a finite number > 0"},
        {[](EngineConfig& c) { c.sensor_step = -1; }, "sensor_step", 0, 0, 0, "must be a finite number > 0"},
        {[](EngineConfig& c) { c.device_damping = -1; }, "device_damping", 0, 0, 0, "must be a finite number >= 0"},
        {[](EngineConfig& c) { c.device_mass = kNaN; }, "device_mass", 0, 0, 0, "must be a finite number >= 0"},
        {[](EngineConfig& c) { c.wall_stiffness = 0; }, "wall_stiffness", 0, 0, 0, "must be a finite number > 0"},
        {[](EngineConfig& c) { c.dynamic_mass_ref = 0; }, "dynamic_mass_ref", 0, 0, 0, "must be a finite number > 0"},
        {[](EngineConfig& c) { c.dynamic_stiffness_ref = -2; }, "dynamic_stiffness_ref", 0, 0, 0,
         "must be a finite number > 0"},
        {[](EngineConfig& c) { c.dynamic_damping_ref = kNaN; }, "dynamic_damping_ref", 0, 0, 0,
         "must be a finite number > 0"},
        {[](EngineConfig& c) { c.gravity_ref = 0; }, "gravity_ref", 0, 0, 0, "must be a finite number > 0"},
        {[](EngineConfig& c) { c.interim_report_hz = 1001; }, "interim_report_hz", 0, 0, 0,
         "must be between 1 and 1000 Hz"},
        {[](EngineConfig& c) { c.report_capacity = 0; }, "report_capacity", 0, 1, 65535, nullptr},
    };
    for (const Case& k : cases) {
        EngineConfig c;
        k.set(c);
        const Error e = Engine(c).create(constant_on_x(1000, kInfiniteUs)).error;
        EXPECT_EQ(e.code, ErrorCode::invalid_parameter) << k.field;
        EXPECT_STREQ(e.field, k.field);
        EXPECT_EQ(e.has_range, k.rule == nullptr) << k.field;
        if (k.rule == nullptr) {
            EXPECT_EQ(e.value, k.value) << k.field;
            EXPECT_EQ(e.allowed.min, k.min) << k.field;
            EXPECT_EQ(e.allowed.max, k.max) << k.field;
        } else {
            EXPECT_STREQ(e.rule, k.rule);
        }
    }
    // Two faults: the first in the order of the checks is named (the counts before the scales,
    // report_capacity after them).
    EngineConfig two;
    two.report_capacity = 0;
    two.gravity_ref = 0;
    EXPECT_STREQ(Engine(two).create(constant_on_x(1000, kInfiniteUs)).error.field, "gravity_ref");
    two.max_effects = 0;
    EXPECT_STREQ(Engine(two).create(constant_on_x(1000, kInfiniteUs)).error.field, "max_effects");
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
