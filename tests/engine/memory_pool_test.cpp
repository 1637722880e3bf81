// The parameter memory (§2.2, issue 5 §3): effects cost bytes by the blocks they hold, a
// create that does not fit fails with device_full and disturbs nothing, freeing returns
// the bytes. Every expected cost below is summed by hand from the documented table
// (docs/runtime.md, pool_cost in feel/engine.hpp): effect 14, envelope 14, constant 2,
// periodic 12, advanced periodic 16, ramp 4, custom 8 + 2 per sample, condition 8 per
// block, texture 8, wall 12, barrier 14, dynamic 20 per axis.
#include <array>
#include <vector>

#include "engine_fixture.hpp"

namespace feel::test {
namespace {

Engine make_engine(int32_t pool_bytes, int32_t max_effects = 64, int32_t max_samples = 4096, int32_t axes = 2) {
    EngineConfig c;
    c.axis_count = axes;
    c.max_effects = max_effects;
    c.max_samples = max_samples;
    c.pool_bytes = pool_bytes;
    return Engine(c);
}

EffectParams on_xy(EffectType type) {
    EffectParams p;
    p.type = type;
    p.duration_us = 100'000;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    return p;
}

struct Priced {
    const char* what;
    EffectParams params;
    std::vector<int16_t> samples;
    int32_t bytes;  // by hand from the table
};

std::vector<Priced> priced_effects() {
    std::vector<Priced> out;
    out.push_back({"constant", constant_on_x(1000, 100'000), {}, 14 + 2});
    EffectParams enveloped = constant_on_x(1000, 100'000);
    enveloped.has_envelope = true;
    enveloped.envelope = {10'000, 10'000, 0, 10'000};
    out.push_back({"constant with envelope", enveloped, {}, 14 + 14 + 2});
    EffectParams sine = periodic_on_x(EffectType::sine, 5000, 0, 10'000, 0, 100'000);
    sine.has_envelope = true;
    out.push_back({"sine with envelope", sine, {}, 14 + 14 + 12});
    out.push_back({"square", periodic_on_x(EffectType::square, 5000, 0, 10'000, 0, 100'000), {}, 14 + 12});
    EffectParams sweep = on_xy(EffectType::sweep_sine);
    sweep.periodic = {5000, 0, 10'000, 0, 0, 9000, SweepSense::clockwise};
    out.push_back({"sweep", sweep, {}, 14 + 16});
    EffectParams ramp = constant_on_x(0, 100'000);
    ramp.type = EffectType::ramp;
    ramp.ramp = {-1000, 1000};
    out.push_back({"ramp", ramp, {}, 14 + 4});
    EffectParams profile = on_xy(EffectType::force_profile);
    profile.custom = {2, 1000, 10};
    out.push_back({"two-channel profile of 10 samples", profile, std::vector<int16_t>(10, 7), 14 + 8 + 2 * 10});
    EffectParams spring1 = constant_on_x(0, kInfiniteUs);
    spring1.type = EffectType::spring;
    out.push_back({"spring on one axis", spring1, {}, 14 + 8});
    EffectParams spring2 = on_xy(EffectType::spring);
    out.push_back({"spring on two axes", spring2, {}, 14 + 8 + 8});
    EffectParams angle_spring = on_xy(EffectType::angle_spring);
    angle_spring.direction.kind = DirectionKind::polar;
    out.push_back({"angle spring", angle_spring, {}, 14 + 8});
    EffectParams texture = on_xy(EffectType::texture);
    texture.direction.kind = DirectionKind::polar;
    texture.texture = {4000, 3000, 500, 5000};
    out.push_back({"texture", texture, {}, 14 + 8});
    EffectParams wall = constant_on_x(0, kInfiniteUs);
    wall.type = EffectType::axis_wall;
    wall.wall = {8000, WallSense::positive, 2000, OffsetMode::absolute, 0, 0, 0, false};
    out.push_back({"axis wall", wall, {}, 14 + 12});
    EffectParams barrier = on_xy(EffectType::angle_barrier);
    barrier.barrier = {6000, 7000, 400, 1000, 3000, 0, 0};
    out.push_back({"angle barrier", barrier, {}, 14 + 14});
    EffectParams recoil = on_xy(EffectType::dynamic_recoil);
    recoil.dynamic.blast_intensity = 4000;
    out.push_back({"recoil on x and y", recoil, {}, 14 + 20 + 20});
    return out;
}

TEST(MemoryPool, EveryEffectCostsTheBytesOfItsBlocks) {
    for (const Priced& e : priced_effects()) {
        EXPECT_EQ(effect_pool_bytes(e.params), e.bytes) << e.what;
        Engine engine = make_engine(4096);
        const int32_t before = engine.pool().free_bytes;
        const CreateResult r = engine.create(e.params, e.samples);
        ASSERT_TRUE(r.error.ok()) << e.what << ": " << r.error.message();
        EXPECT_EQ(before - engine.pool().free_bytes, e.bytes) << e.what;
    }
}

TEST(MemoryPool, ADynamicCostsAControlLawPerAxis) {
    EffectParams law;
    law.type = EffectType::dynamic_control_law;
    law.duration_us = kInfiniteUs;
    law.axis_count = 6;  // x y z rx ry rz, the default axes
    EXPECT_EQ(effect_pool_bytes(law), 14 + 6 * 20);
    Engine engine = make_engine(1000, 8, 16, 6);
    ASSERT_TRUE(engine.create(law).error.ok());
    EXPECT_EQ(engine.pool().free_bytes, 1000 - 134);
}

TEST(MemoryPool, PoolReportsItsSizes) {
    Engine engine = make_engine(500, 12, 100);
    PoolInfo p = engine.pool();
    EXPECT_EQ(p.total_bytes, 500);
    EXPECT_EQ(p.free_bytes, 500);
    EXPECT_EQ(p.max_effects, 12);
    EXPECT_EQ(p.free_effects, 12);
    EXPECT_EQ(p.max_dynamics, 12);  // EngineConfig's 0: one per slot
    EXPECT_EQ(p.free_dynamics, 12);
    EXPECT_EQ(p.max_stateful_conditions, 12);
    EXPECT_EQ(p.free_stateful_conditions, 12);
    EXPECT_EQ(p.total_samples, 100);
    EXPECT_EQ(p.free_samples, 100);
    EffectParams profile = constant_on_x(0, kInfiniteUs);
    profile.type = EffectType::force_profile;
    profile.custom = {1, 1000, 30};
    ASSERT_TRUE(engine.create(profile, std::vector<int16_t>(30, 1)).error.ok());
    p = engine.pool();
    EXPECT_EQ(p.free_bytes, 500 - (14 + 8 + 60));
    EXPECT_EQ(p.free_effects, 11);
    EXPECT_EQ(p.free_samples, 70);
}

TEST(MemoryPool, ACreateThatDoesNotFitFailsWithDeviceFullAndDisturbsNothing) {
    Engine engine = make_engine(100);
    std::vector<EffectId> ids;
    for (int i = 0; i < 3; ++i) {  // 3 x 16 bytes
        const CreateResult r = engine.create(constant_on_x(1000, kInfiniteUs));
        ASSERT_TRUE(r.error.ok());
        ASSERT_TRUE(engine.start(r.id).ok());
        ids.push_back(r.id);
    }
    EffectParams sine = periodic_on_x(EffectType::sine, 5000, 0, 10'000, 0, kInfiniteUs);
    sine.has_envelope = true;  // 40 bytes: 88 used, 12 free
    ASSERT_TRUE(engine.create(sine).error.ok());
    const PoolInfo before = engine.pool();
    EXPECT_EQ(before.free_bytes, 12);

    const CreateResult full = engine.create(constant_on_x(1000, kInfiniteUs));  // needs 16
    EXPECT_EQ(full.error.code, ErrorCode::device_full);
    EXPECT_STREQ(full.error.field, "pool_bytes");
    EXPECT_EQ(full.error.value, 16);
    EXPECT_EQ(full.error.allowed.max, 12);
    EXPECT_FALSE(full.id.valid());

    const PoolInfo after = engine.pool();
    EXPECT_EQ(after.free_bytes, before.free_bytes);
    EXPECT_EQ(after.free_effects, before.free_effects);
    EXPECT_EQ(after.free_samples, before.free_samples);
    TickOutput out;
    engine.tick(TickInput{}, out);
    EXPECT_EQ(out.force[0], 3000.0f);  // the three resident constants still play
    for (EffectId id : ids) EXPECT_EQ(engine.state(id), EffectState::playing);
}

TEST(MemoryPool, FreeingAnEffectReturnsItsBytes) {
    Engine engine = make_engine(100);
    std::vector<EffectId> ids;
    for (int i = 0; i < 6; ++i) {  // 6 x 16 = 96 bytes
        const CreateResult r = engine.create(constant_on_x(1000, kInfiniteUs));
        ASSERT_TRUE(r.error.ok()) << i;
        ids.push_back(r.id);
    }
    EXPECT_EQ(engine.pool().free_bytes, 4);
    EXPECT_EQ(engine.create(constant_on_x(1000, kInfiniteUs)).error.code, ErrorCode::device_full);
    ASSERT_TRUE(engine.destroy(ids[2]).ok());
    EXPECT_EQ(engine.pool().free_bytes, 20);
    EXPECT_TRUE(engine.create(constant_on_x(1000, kInfiniteUs)).error.ok());
    EXPECT_EQ(engine.pool().free_bytes, 4);
    for (EffectId id : ids) (void)engine.destroy(id);
    EXPECT_EQ(engine.pool().free_bytes, 100 - 16);  // the one created after the destroy stays
}

TEST(MemoryPool, SlotsLimitAsWellAsBytes) {
    Engine engine = make_engine(10'000, 2);
    ASSERT_TRUE(engine.create(constant_on_x(1000, kInfiniteUs)).error.ok());
    ASSERT_TRUE(engine.create(constant_on_x(1000, kInfiniteUs)).error.ok());
    const CreateResult r = engine.create(constant_on_x(1000, kInfiniteUs));
    EXPECT_EQ(r.error.code, ErrorCode::device_full);
    EXPECT_EQ(engine.pool().free_bytes, 10'000 - 32);
}

TEST(MemoryPool, AnUpdateThatGrowsAnEffectNeedsTheBytes) {
    Engine engine = make_engine(60);
    const CreateResult a = engine.create(constant_on_x(1000, kInfiniteUs));  // 16
    EffectParams sine = periodic_on_x(EffectType::sine, 5000, 0, 10'000, 0, kInfiniteUs);
    const CreateResult b = engine.create(sine);  // 26: 42 used, 18 free
    ASSERT_TRUE(a.error.ok());
    ASSERT_TRUE(b.error.ok());
    EffectParams with_envelope = sine;
    with_envelope.has_envelope = true;  // +14: fits
    ASSERT_TRUE(engine.update(b.id, with_envelope, effect_field::kEnvelope, false).ok());
    EXPECT_EQ(engine.pool().free_bytes, 4);
    EffectParams enveloped_constant = constant_on_x(1000, kInfiniteUs);
    enveloped_constant.has_envelope = true;  // +14 with 4 free: refused, nothing changes
    const Error e = engine.update(a.id, enveloped_constant, effect_field::kEnvelope, false);
    EXPECT_EQ(e.code, ErrorCode::device_full);
    EXPECT_EQ(e.value, 30);         // the effect's cost after the update
    EXPECT_EQ(e.allowed.max, 20);   // what it could have: the 4 free and its own 16
    EffectParams now;
    ASSERT_TRUE(engine.params(a.id, now).ok());
    EXPECT_FALSE(now.has_envelope);
    EXPECT_EQ(engine.pool().free_bytes, 4);
    // Dropping the envelope again gives its 14 bytes back.
    ASSERT_TRUE(engine.update(b.id, sine, effect_field::kEnvelope, false).ok());
    EXPECT_EQ(engine.pool().free_bytes, 18);
}

TEST(MemoryPool, AProfileThatGrowsNeedsBytesAndSamples) {
    Engine engine = make_engine(100, 8, 20);
    EffectParams p = constant_on_x(0, kInfiniteUs);
    p.type = EffectType::force_profile;
    p.custom = {1, 1000, 10};
    const CreateResult r = engine.create(p, std::vector<int16_t>(10, 5));  // 14 + 8 + 20 = 42
    ASSERT_TRUE(r.error.ok());
    p.custom.sample_count = 20;  // 62 bytes: fits both the 100 bytes and the 20 samples
    ASSERT_TRUE(engine.update(r.id, p, effect_field::kTypeSpecific, false, std::vector<int16_t>(20, 6)).ok());
    EXPECT_EQ(engine.pool().free_bytes, 100 - 62);
    EXPECT_EQ(engine.pool().free_samples, 0);
    p.custom.sample_count = 21;  // 21 samples where only 20 are
    const Error e = engine.update(r.id, p, effect_field::kTypeSpecific, false, std::vector<int16_t>(21, 7));
    EXPECT_EQ(e.code, ErrorCode::device_full);
    EXPECT_EQ(engine.pool().free_bytes, 100 - 62);
    TickOutput out;
    ASSERT_TRUE(engine.start(r.id).ok());
    engine.tick(TickInput{}, out);
    EXPECT_EQ(out.force[0], 6.0f);  // the 20-sample profile is intact
}

TEST(MemoryPool, APoolOfZeroHoldsEverySlotOfTheLargestEffectAndAllSamples) {
    // 4 slots and 100 samples: 4 x (14 + 6 x 20) + 2 x 100 bytes.
    Engine engine = make_engine(0, 4, 100, 6);
    EXPECT_EQ(engine.pool().total_bytes, 4 * 134 + 200);
    EffectParams law;
    law.type = EffectType::dynamic_control_law;
    law.duration_us = kInfiniteUs;
    law.axis_count = 6;
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(engine.create(law).error.ok()) << i;
    EffectParams profile = constant_on_x(0, kInfiniteUs);
    profile.type = EffectType::force_profile;
    profile.custom = {1, 1000, 100};
    ASSERT_TRUE(engine.create(profile, std::vector<int16_t>(100, 1)).error.ok());
    EXPECT_EQ(engine.pool().free_effects, 0);
}

// A small device holds fewer dynamics and conditions with memory than it has slots
// (EngineConfig::max_dynamics, max_stateful_conditions): the one over is refused with
// device_full naming the capacity, changes nothing, and effects that keep no memory still fit.
TEST(MemoryPool, DynamicsAndConditionsWithMemoryHaveCapacitiesOfTheirOwn) {
    EngineConfig c;
    c.max_effects = 8;
    c.max_dynamics = 2;
    c.max_stateful_conditions = 1;
    Engine engine(c);
    EffectParams law = on_xy(EffectType::dynamic_control_law);
    const EffectId first = engine.create(law).id;
    ASSERT_TRUE(first.valid());
    ASSERT_TRUE(engine.create(law).error.ok());
    const PoolInfo before = engine.pool();
    EXPECT_EQ(before.max_dynamics, 2);
    EXPECT_EQ(before.free_dynamics, 0);
    const CreateResult third = engine.create(law);
    EXPECT_EQ(third.error.code, ErrorCode::device_full);
    EXPECT_STREQ(third.error.field, "resident dynamics (EngineConfig::max_dynamics)");
    EXPECT_EQ(third.error.allowed.max, 2);
    EXPECT_EQ(third.error.value, 3);
    EXPECT_NE(third.error.message().find("allowed 0..2"), std::string::npos) << third.error.message();
    EXPECT_EQ(engine.pool().free_bytes, before.free_bytes);
    EXPECT_EQ(engine.pool().free_effects, before.free_effects);

    ASSERT_TRUE(engine.create(on_xy(EffectType::friction)).error.ok());
    const CreateResult second = engine.create(on_xy(EffectType::friction));
    EXPECT_EQ(second.error.code, ErrorCode::device_full);
    EXPECT_STREQ(second.error.field, "stateful conditions (max_stateful_conditions)");
    EXPECT_EQ(second.error.allowed.max, 1);
    EXPECT_TRUE(engine.create(on_xy(EffectType::spring)).error.ok());  // keeps no memory
    EXPECT_TRUE(engine.create(constant_on_x(1000, kInfiniteUs)).error.ok());

    ASSERT_TRUE(engine.destroy(first).ok());
    EXPECT_EQ(engine.pool().free_dynamics, 1);
    EXPECT_TRUE(engine.create(law).error.ok());
}

TEST(MemoryPool, MoreDynamicsOrConditionsWithMemoryThanSlotsIsAConfigError) {
    EngineConfig c;
    c.max_effects = 8;
    c.max_dynamics = 9;
    EXPECT_STREQ(Engine(c).create(constant_on_x(1000, kInfiniteUs)).error.field, "max_dynamics");
    c.max_dynamics = 0;
    c.max_stateful_conditions = -1;
    const CreateResult r = Engine(c).create(constant_on_x(1000, kInfiniteUs));
    EXPECT_STREQ(r.error.field, "max_stateful_conditions");
    EXPECT_EQ(r.error.allowed.max, 8);
}

TEST(MemoryPool, ABadPoolSizeIsAConfigError) {
    for (int32_t bad : {-1, (1 << 30) + 1}) {
        Engine engine = make_engine(bad);
        const CreateResult r = engine.create(constant_on_x(1000, kInfiniteUs));
        EXPECT_EQ(r.error.code, ErrorCode::invalid_parameter) << bad;
        EXPECT_STREQ(r.error.field, "pool_bytes");
        EXPECT_EQ(r.error.allowed.max, 1 << 30);
        EXPECT_EQ(engine.pool().total_bytes, 0);
    }
}

}  // namespace
}  // namespace feel::test
