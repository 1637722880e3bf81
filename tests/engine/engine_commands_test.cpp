// The command interface (issue 5 §2), each command against its definition: start with
// iterations and solo (DirectInput's Start with dwIterations and DIES_SOLO), partial
// updates with and without restart (SetParameters with DIEP_* and DIEP_START), status,
// and device control (DISFFC_PAUSE/CONTINUE, SETACTUATORSOFF/ON, STOPALL, RESET).
//
// Expected forces come from the effects' formulas: a ramp is start + (end - start)·τ/T
// (§6.6.e), a constant is its magnitude, a profile holds each sample for its period.
#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using EngineCommands = EngineFixture;

EffectParams ramp_on_x(int32_t start, int32_t end, int64_t duration_us) {
    EffectParams p = constant_on_x(0, duration_us);
    p.type = EffectType::ramp;
    p.ramp = {start, end};
    return p;
}

double ramp_at(double start, double end, double tau_us, double duration_us) {
    return start + (end - start) * tau_us / duration_us;
}

// --- start with iterations and solo --------------------------------------------------------

TEST_F(EngineCommands, StartWithIterationsPlaysThatManyIterationsThisTimeOnly) {
    const EffectId id = create(ramp_on_x(0, 10'000, 10'000));  // its own count: 1
    ASSERT_TRUE(engine_->start(id, 3, false).ok());
    // Three 10 ms ramps back to back, then nothing.
    expect_forces(30'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? ramp_at(0, 10'000, static_cast<double>(t % 10'000), 10'000) : 0.0;
    });
    EXPECT_EQ(engine_->status(id).state, EffectState::playing);
    EXPECT_EQ(tick().force[0], 0.0f);
    EffectStatus st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::stopped);
    EXPECT_EQ(st.last_end, PlayEnd::finished);
    EXPECT_EQ(st.iterations, 3);
    EXPECT_EQ(st.completed_iterations, 3);

    // start(id) plays the effect's own single iteration again.
    ASSERT_TRUE(engine_->start(id).ok());
    expect_forces(10'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? ramp_at(0, 10'000, static_cast<double>(t), 10'000) : 0.0;
    });
    EXPECT_EQ(tick().force[0], 0.0f);
    st = engine_->status(id);
    EXPECT_EQ(st.iterations, 1);
    EXPECT_EQ(st.completed_iterations, 1);
    EXPECT_EQ(st.starts, 2u);
}

TEST_F(EngineCommands, StartWithInfiniteIterationsNeverEnds) {
    const EffectId id = create(constant_on_x(1000, 2000));
    ASSERT_TRUE(engine_->start(id, kInfiniteIterations, false).ok());
    for (int n = 0; n < 1000; ++n) ASSERT_EQ(tick().force[0], 1000.0f) << n;  // 500 iterations
    const EffectStatus st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::playing);
    EXPECT_EQ(st.iterations, kInfiniteIterations);
    EXPECT_EQ(st.completed_iterations, 499);  // the 500th plays now
}

TEST_F(EngineCommands, ABadIterationCountIsRefusedAndChangesNothing) {
    const EffectId id = play(ramp_on_x(0, 10'000, 100'000));
    for (int n = 0; n < 10; ++n) tick();
    for (int32_t bad : {0, 256, -2}) {
        const Error e = engine_->start(id, bad, true);
        EXPECT_EQ(e.code, ErrorCode::invalid_parameter) << bad;
        EXPECT_STREQ(e.field, "iterations");
        EXPECT_EQ(e.allowed.min, 1);
        EXPECT_EQ(e.allowed.max, 255);
    }
    // The effect was not restarted: it is 10 ms in.
    EXPECT_NEAR(tick().force[0], ramp_at(0, 10'000, 10'000, 100'000), kForceTolerance);
    EXPECT_EQ(engine_->status(id).starts, 1u);
    EXPECT_EQ(engine_->start(EffectId{}, 2, false).code, ErrorCode::invalid_handle);
}

TEST_F(EngineCommands, SoloStopsEveryOtherEffect) {
    const EffectId a = play(constant_on_x(1000, kInfiniteUs));
    const EffectId b = play(constant_on_x(2000, kInfiniteUs));
    const EffectId c = create(constant_on_x(4000, kInfiniteUs));
    EXPECT_EQ(tick().force[0], 3000.0f);
    ASSERT_TRUE(engine_->start(c, 1, true).ok());
    const TickOutput out = tick();
    EXPECT_EQ(out.force[0], 4000.0f);
    EXPECT_EQ(out.playing_effects, 1);
    for (EffectId other : {a, b}) {
        EXPECT_EQ(engine_->status(other).state, EffectState::stopped);
        EXPECT_EQ(engine_->status(other).last_end, PlayEnd::stopped);
    }
    // Solo is a start option, not a mode: the others can play beside it again.
    ASSERT_TRUE(engine_->start(a).ok());
    EXPECT_EQ(tick().force[0], 5000.0f);
}

TEST_F(EngineCommands, SoloRestartsTheSoloEffectItself) {
    const EffectId id = play(ramp_on_x(0, 10'000, 100'000));
    for (int n = 0; n < 50; ++n) tick();
    ASSERT_TRUE(engine_->start(id, 1, true).ok());
    EXPECT_EQ(tick().force[0], 0.0f);  // τ = 0 again
    EXPECT_EQ(engine_->status(id).state, EffectState::playing);
}

// --- update ------------------------------------------------------------------------------

TEST_F(EngineCommands, UpdateWithoutRestartKeepsTheClock) {
    const EffectId id = play(ramp_on_x(2000, 6000, 1'000'000));
    for (int n = 0; n < 400; ++n) tick();  // t = 0 .. 399 ms
    EffectParams p;
    p.type = EffectType::ramp;
    p.ramp = {2000, -6000};
    ASSERT_TRUE(engine_->update(id, p, effect_field::kTypeSpecific, false).ok());
    // The play goes on at τ = 400 ms with the new end.
    expect_forces(100'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? ramp_at(2000, -6000, 400'000.0 + static_cast<double>(t), 1'000'000) : 0.0;
    });
    EXPECT_EQ(engine_->status(id).starts, 1u);
    EXPECT_EQ(engine_->status(id).elapsed_us, 499'000);
}

TEST_F(EngineCommands, UpdateWithRestartStartsFromTheBeginning) {
    const EffectId id = play(ramp_on_x(2000, 6000, 1'000'000));
    for (int n = 0; n < 400; ++n) tick();
    EffectParams p;
    p.type = EffectType::ramp;
    p.ramp = {2000, -6000};
    ASSERT_TRUE(engine_->update(id, p, effect_field::kTypeSpecific, true).ok());
    expect_forces(100'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? ramp_at(2000, -6000, static_cast<double>(t), 1'000'000) : 0.0;
    });
    EXPECT_EQ(engine_->status(id).starts, 2u);
}

TEST_F(EngineCommands, UpdateOnlyChangesTheFieldsOfTheMask) {
    EffectParams original = constant_on_x(8000, kInfiniteUs);
    original.gain = 10'000;
    const EffectId id = play(original);
    EffectParams p = constant_on_x(-3000, 5000);  // magnitude and duration are not in the mask
    p.gain = 2500;
    ASSERT_TRUE(engine_->update(id, p, effect_field::kGain, false).ok());
    EXPECT_NEAR(tick().force[0], 2000, kForceTolerance);  // 8000 at gain 2500
    EffectParams now;
    ASSERT_TRUE(engine_->params(id, now).ok());
    EffectParams expected = original;
    expected.gain = 2500;
    EXPECT_EQ(now, expected);
}

// A slot keeps a spring's blocks as the curves its tick reads (src/engine/slot_params.hpp):
// every coefficient, offset, saturation and deadband of the primer's ranges reads back as given.
TEST_F(EngineCommands, ParamsGiveBackEveryConditionValueAsCreated) {
    for (int32_t v = -10'000; v <= 10'000; ++v) {
        EffectParams p = constant_on_x(0, kInfiniteUs);
        p.type = EffectType::spring;
        p.conditions[0] = {v, -v, v, v < 0 ? -v : v, 10'000 - (v < 0 ? -v : v), v < 0 ? -v : v, OffsetMode::relative};
        const CreateResult r = engine_->create(p);
        ASSERT_TRUE(r.error.ok()) << v << ": " << r.error.message();
        EffectParams now;
        ASSERT_TRUE(engine_->params(r.id, now).ok());
        ASSERT_EQ(now, p) << "coefficient " << v;
        ASSERT_TRUE(engine_->destroy(r.id).ok());
    }
}

// A slot keeps a friction's blocks in 16-bit fields (slot_params.hpp, SlotConditionBlock):
// every value of the primer's ranges reads back as given.
TEST_F(EngineCommands, ParamsGiveBackEveryFrictionValueAsCreated) {
    for (int32_t v = -10'000; v <= 10'000; ++v) {
        EffectParams p = constant_on_x(0, kInfiniteUs);
        p.type = EffectType::friction;
        p.axis_count = 2;
        p.axes[1] = Axis::y;
        const int32_t level = v < 0 ? -v : v;
        p.conditions[0] = {v, -v, v, level, 10'000 - level, level, OffsetMode::absolute};
        p.conditions[1] = {-v, v, -v, 10'000 - level, level, 10'000 - level, OffsetMode::absolute};
        const CreateResult r = engine_->create(p);
        ASSERT_TRUE(r.error.ok()) << v << ": " << r.error.message();
        EffectParams now;
        ASSERT_TRUE(engine_->params(r.id, now).ok());
        ASSERT_EQ(now, p) << "value " << v;
        ASSERT_TRUE(engine_->destroy(r.id).ok());
    }
}

// The 32-bit times of a slot (the start delay, a period, a profile's sample period: 64-bit
// in EffectParams) hold the primer's largest, 65e6 µs, and the smallest.
TEST_F(EngineCommands, ParamsGiveBackTheLongestAndShortestTimes) {
    for (const int64_t t : {int64_t{1}, kMaxTimeUs}) {
        EffectParams wave = constant_on_x(0, kInfiniteUs);
        wave.type = EffectType::sine;
        wave.start_delay_us = t;
        wave.periodic.period_us = t;
        wave.periodic.magnitude = 5000;
        const std::array<int16_t, 2> samples{100, -100};
        EffectParams profile = constant_on_x(0, kInfiniteUs);
        profile.type = EffectType::force_profile;
        profile.start_delay_us = t;
        profile.custom = {1, t, 2};
        for (const EffectParams& p : {wave, profile}) {
            const bool is_profile = p.type == EffectType::force_profile;
            const CreateResult r = engine_->create(p, is_profile ? std::span<const int16_t>(samples)
                                                                : std::span<const int16_t>());
            ASSERT_TRUE(r.error.ok()) << t << ": " << r.error.message();
            EffectParams now;
            ASSERT_TRUE(engine_->params(r.id, now).ok());
            EXPECT_EQ(now, p) << "time " << t;
            ASSERT_TRUE(engine_->destroy(r.id).ok());
        }
    }
}

// A slot keeps a direction's values in 16 bits (slot_params.hpp, SlotDirection): every polar
// and spherical angle and every cartesian and moments component the validator admits reads
// back as given, and one past either end is refused.
TEST_F(EngineCommands, ParamsGiveBackEveryDirectionValueAsCreated) {
    reset(6);
    const auto wave = [](DirectionKind kind, int32_t a, int32_t b, int32_t c) {
        EffectParams p = constant_on_x(4000, kInfiniteUs);
        p.axis_count = kind == DirectionKind::polar ? 2 : 3;
        const bool rotations = kind == DirectionKind::moments;
        p.axes[0] = rotations ? Axis::rx : Axis::x;
        p.axes[1] = rotations ? Axis::ry : Axis::y;
        p.axes[2] = rotations ? Axis::rz : Axis::z;
        p.direction.kind = kind;
        p.direction.value[0] = a;
        if (kind != DirectionKind::polar) p.direction.value[1] = b;
        if (kind == DirectionKind::cartesian || kind == DirectionKind::moments) p.direction.value[2] = c;
        return p;
    };
    const auto round_trip = [&](const EffectParams& p) {
        const CreateResult r = engine_->create(p);
        ASSERT_TRUE(r.error.ok()) << r.error.message();
        EffectParams now;
        ASSERT_TRUE(engine_->params(r.id, now).ok());
        ASSERT_EQ(now, p);
        ASSERT_TRUE(engine_->destroy(r.id).ok());
    };
    for (int32_t angle = 0; angle <= 35'999; ++angle) {
        ASSERT_NO_FATAL_FAILURE(round_trip(wave(DirectionKind::polar, angle, 0, 0))) << "polar " << angle;
        ASSERT_NO_FATAL_FAILURE(round_trip(wave(DirectionKind::spherical, angle, angle % 18'001, 0)))
            << "spherical " << angle;
    }
    for (int32_t v = -10'000; v <= 10'000; ++v) {
        const int32_t other = 10'000 - (v < 0 ? -v : v);  // never all three 0
        ASSERT_NO_FATAL_FAILURE(round_trip(wave(DirectionKind::cartesian, v, other, -v))) << "cartesian " << v;
        ASSERT_NO_FATAL_FAILURE(round_trip(wave(DirectionKind::moments, -v, v, other))) << "moments " << v;
    }
    EXPECT_FALSE(engine_->create(wave(DirectionKind::polar, 36'000, 0, 0)).error.ok());
    EXPECT_FALSE(engine_->create(wave(DirectionKind::polar, -1, 0, 0)).error.ok());
    EXPECT_FALSE(engine_->create(wave(DirectionKind::spherical, 0, 18'001, 0)).error.ok());
    EXPECT_FALSE(engine_->create(wave(DirectionKind::spherical, 0, -1, 0)).error.ok());
    EXPECT_FALSE(engine_->create(wave(DirectionKind::cartesian, 10'001, 0, 0)).error.ok());
    EXPECT_FALSE(engine_->create(wave(DirectionKind::moments, 0, 0, -10'001)).error.ok());
}

// A dynamic's record keeps the fields of its type in 16 bits (slot_params.hpp,
// SlotDynamicBlock): every value each field's range admits reads back as given, and one
// past either end is refused, so the values tried are exactly the ones the validator admits.
TEST_F(EngineCommands, ParamsGiveBackEveryDynamicValueAsCreated) {
    struct Field {
        const char* name;
        int32_t& (*at)(EffectParams&);
        Range range;
    };
    struct Type {
        EffectType type;
        std::vector<Field> fields;
    };
    using namespace range;
    const std::vector<Type> types = {
        {EffectType::dynamic_recoil,
         {{"blast_direction", [](EffectParams& p) -> int32_t& { return p.dynamic.blast_direction; }, kAngle},
          {"blast_intensity", [](EffectParams& p) -> int32_t& { return p.dynamic.blast_intensity; }, kSignedLevel},
          {"dynamic_mass", [](EffectParams& p) -> int32_t& { return p.dynamic.dynamic_mass; }, kDynamicMass},
          {"blast_resonance", [](EffectParams& p) -> int32_t& { return p.dynamic.blast_resonance; }, kDynamicStiffness},
          {"blast_decay", [](EffectParams& p) -> int32_t& { return p.dynamic.blast_decay; }, kLevel}}},
        {EffectType::dynamic_impact,
         {{"impact_direction", [](EffectParams& p) -> int32_t& { return p.dynamic.impact_direction; }, kAngle},
          {"impact_intensity", [](EffectParams& p) -> int32_t& { return p.dynamic.impact_intensity; }, kSignedLevel},
          {"dynamic_mass", [](EffectParams& p) -> int32_t& { return p.dynamic.dynamic_mass; }, kDynamicMass},
          {"elasticity", [](EffectParams& p) -> int32_t& { return p.dynamic.elasticity; }, kDynamicStiffness},
          {"collision_absorption", [](EffectParams& p) -> int32_t& { return p.dynamic.collision_absorption; },
           kLevel}}},
        {EffectType::dynamic_liquid,
         {{"density", [](EffectParams& p) -> int32_t& { return p.dynamic.density; }, kDynamicMass},
          {"settle", [](EffectParams& p) -> int32_t& { return p.dynamic.settle; }, kDynamicStiffness},
          {"viscosity", [](EffectParams& p) -> int32_t& { return p.dynamic.viscosity; }, kLevel}}},
        {EffectType::dynamic_inertia,
         {{"inertia", [](EffectParams& p) -> int32_t& { return p.dynamic.inertia; }, kDynamicMass},
          {"play", [](EffectParams& p) -> int32_t& { return p.dynamic.play; }, kLevel}}},
        {EffectType::dynamic_center_drift,
         {{"stiffness", [](EffectParams& p) -> int32_t& { return p.dynamic.stiffness; }, kDynamicStiffness},
          {"drift_resistance", [](EffectParams& p) -> int32_t& { return p.dynamic.drift_resistance; }, kLevel}}},
        {EffectType::dynamic_sling,
         {{"ball_mass", [](EffectParams& p) -> int32_t& { return p.dynamic.ball_mass; }, kDynamicMass},
          {"string_length", [](EffectParams& p) -> int32_t& { return p.dynamic.string_length; }, kLevel},
          {"string_compliance", [](EffectParams& p) -> int32_t& { return p.dynamic.string_compliance; },
           kDynamicStiffness},
          {"ball_damping", [](EffectParams& p) -> int32_t& { return p.dynamic.ball_damping; }, kLevel}}},
        {EffectType::dynamic_paddle,
         {{"ball_mass", [](EffectParams& p) -> int32_t& { return p.dynamic.ball_mass; }, kDynamicMass},
          {"initial_velocity", [](EffectParams& p) -> int32_t& { return p.dynamic.initial_velocity; }, kSignedLevel},
          {"initial_velocity_direction",
           [](EffectParams& p) -> int32_t& { return p.dynamic.initial_velocity_direction; }, kAngle},
          {"paddle_compliance", [](EffectParams& p) -> int32_t& { return p.dynamic.paddle_compliance; },
           kDynamicStiffness},
          {"paddle_damping", [](EffectParams& p) -> int32_t& { return p.dynamic.paddle_damping; }, kLevel},
          {"gravity", [](EffectParams& p) -> int32_t& { return p.dynamic.gravity; }, kSignedLevel}}},
        {EffectType::dynamic_control_law,
         {{"mass", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].mass; }, kDynamicMass},
          {"k_pos", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].k_pos; }, kDynamicStiffness},
          {"k_neg", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].k_neg; }, kDynamicStiffness},
          {"b", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].b; }, kLevel},
          {"vel_init", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].vel_init; }, kSignedLevel},
          {"pos_init", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].pos_init; }, kSignedLevel},
          {"half_cycles", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].half_cycles; },
           kHalfCycles},
          {"length", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].length; }, kLevel},
          {"drag", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].drag; }, kLevel},
          {"gravity", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[0].gravity; }, kSignedLevel},
          {"y: mass", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[1].mass; }, kDynamicMass},
          {"y: vel_init", [](EffectParams& p) -> int32_t& { return p.dynamic.control_law[1].vel_init; },
           kSignedLevel}}},
    };
    for (const Type& type : types) {
        EffectParams base;
        base.type = type.type;
        base.axis_count = 2;
        base.axes[0] = Axis::x;
        base.axes[1] = Axis::y;
        base.dynamic.interim_reporting = true;
        int64_t values = 0;
        for (const Field& f : type.fields) {
            f.at(base) = static_cast<int32_t>(f.range.min);
            values = std::max(values, f.range.max - f.range.min + 1);
        }
        for (const Field& f : type.fields) {  // the ends of the admitted range
            for (const int64_t outside : {f.range.min - 1, f.range.max + 1}) {
                EffectParams p = base;
                f.at(p) = static_cast<int32_t>(outside);
                EXPECT_FALSE(engine_->create(p).error.ok()) << f.name << " = " << outside;
            }
        }
        for (int64_t k = 0; k < values; ++k) {  // every field through its whole range
            EffectParams p = base;
            for (const Field& f : type.fields) {
                f.at(p) = static_cast<int32_t>(f.range.min + k % (f.range.max - f.range.min + 1));
            }
            const CreateResult r = engine_->create(p);
            ASSERT_TRUE(r.error.ok()) << effect_type_name(type.type) << " " << k << ": " << r.error.message();
            EffectParams now;
            ASSERT_TRUE(engine_->params(r.id, now).ok());
            ASSERT_EQ(now, p) << effect_type_name(type.type) << " " << k;
            ASSERT_TRUE(engine_->destroy(r.id).ok());
        }
    }
}

// What an effect never reads is not kept (Engine::params): another type's block, an
// envelope without has_envelope, a trigger's index without a trigger.
TEST_F(EngineCommands, ParamsGiveBackWhatAnEffectDoesNotReadAsDefaults) {
    EffectParams p = constant_on_x(3000, kInfiniteUs);
    p.periodic.magnitude = 7000;
    p.envelope.impulse_level = 9000;
    p.trigger.index = 77;
    EffectParams now;
    ASSERT_TRUE(engine_->params(create(p), now).ok());
    EXPECT_EQ(now, constant_on_x(3000, kInfiniteUs));
}

TEST_F(EngineCommands, ALongerDurationExtendsAPlayAndAShorterOneEndsIt) {
    const EffectId a = play(constant_on_x(1000, 100'000));
    for (int n = 0; n < 50; ++n) tick();  // 50 ms in
    EffectParams p = constant_on_x(0, 200'000);
    ASSERT_TRUE(engine_->update(a, p, effect_field::kDuration, false).ok());
    expect_forces(150'000, 1000, [](int64_t, int axis) { return axis == 0 ? 1000.0 : 0.0; });  // to 200 ms
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->status(a).last_end, PlayEnd::finished);

    reset(2);
    const EffectId b = play(constant_on_x(1000, 100'000));
    for (int n = 0; n < 50; ++n) tick();
    p.duration_us = 20'000;  // already past: the play is over at the next tick
    ASSERT_TRUE(engine_->update(b, p, effect_field::kDuration, false).ok());
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->status(b).state, EffectState::stopped);
    EXPECT_EQ(engine_->status(b).last_end, PlayEnd::finished);
}

TEST_F(EngineCommands, FewerIterationsEndAPlayAtOnceAndMoreExtendIt) {
    // Three iterations of 100 ms; 150 ms in, the second plays. Lowering the count to 1 ends
    // the play at the next tick (the first iteration is already done); raising a count of 2
    // to 3 plays the third too (to 300 ms).
    EffectParams p = constant_on_x(1000, 100'000);
    p.iterations = 3;
    const EffectId a = play(p);
    for (int n = 0; n < 150; ++n) tick();
    p.iterations = 1;
    ASSERT_TRUE(engine_->update(a, p, effect_field::kIterations, false).ok());
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->status(a).state, EffectState::stopped);
    EXPECT_EQ(engine_->status(a).last_end, PlayEnd::finished);

    reset(2);
    p.iterations = 2;
    const EffectId b = play(p);
    for (int n = 0; n < 150; ++n) tick();
    p.iterations = 3;
    ASSERT_TRUE(engine_->update(b, p, effect_field::kIterations, false).ok());
    expect_forces(150'000, 1000, [](int64_t, int axis) { return axis == 0 ? 1000.0 : 0.0; });  // to 300 ms
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->status(b).last_end, PlayEnd::finished);
}

TEST_F(EngineCommands, UpdateLeavesAStoppedEffectStoppedUnlessItRestarts) {
    const EffectId id = create(constant_on_x(1000, kInfiniteUs));
    EffectParams p = constant_on_x(3000, kInfiniteUs);
    ASSERT_TRUE(engine_->update(id, p, effect_field::kTypeSpecific, false).ok());
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->state(id), EffectState::stopped);
    ASSERT_TRUE(engine_->update(id, p, 0, true).ok());  // an empty mask with restart: DIEP_START alone
    EXPECT_EQ(tick().force[0], 3000.0f);
}

TEST_F(EngineCommands, UpdatingAProfilesSamplesKeepsItsClock) {
    EffectParams p = constant_on_x(0, kInfiniteUs);
    p.type = EffectType::force_profile;
    p.custom = {1, 1000, 3};
    const std::array<int16_t, 3> first = {100, 200, 300};
    const EffectId id = play(p, first);
    EXPECT_EQ(tick().force[0], 100.0f);
    EXPECT_EQ(tick().force[0], 200.0f);  // τ = 1 ms
    p.custom.sample_count = 4;
    const std::array<int16_t, 4> second = {-1, -2, -3, -4};
    ASSERT_TRUE(engine_->update(id, p, effect_field::kTypeSpecific, false, second).ok());
    EXPECT_EQ(tick().force[0], -3.0f);  // τ = 2 ms: the third sample of the new profile
    EXPECT_EQ(tick().force[0], -4.0f);
    EXPECT_EQ(tick().force[0], -1.0f);  // it loops over its four samples
}

TEST_F(EngineCommands, AnInvalidUpdateChangesNothing) {
    EffectParams sine = periodic_on_x(EffectType::sine, 5000, 0, 20'000, 0, kInfiniteUs);
    const EffectId id = play(sine);
    for (int n = 0; n < 7; ++n) tick();
    const PoolInfo pool_before = engine_->pool();
    const EffectStatus status_before = engine_->status(id);

    struct Case {
        const char* what;
        EffectParams params;
        uint32_t mask;
        ErrorCode code;
        const char* field;
    };
    EffectParams bad_phase = sine;
    bad_phase.periodic.phase = 36000;
    EffectParams other_type = constant_on_x(1000, kInfiniteUs);
    EffectParams bad_axes = sine;
    bad_axes.axis_count = 2;
    bad_axes.axes[1] = Axis::z;  // the fixture's device has x and y
    bad_axes.direction.kind = DirectionKind::cartesian;
    bad_axes.direction.value[0] = 1;
    bad_axes.direction.value[1] = 1;
    EffectParams repeat_without_trigger = sine;
    repeat_without_trigger.trigger_repeat_interval_us = 1000;
    EffectParams envelope_on_gain = sine;
    envelope_on_gain.gain = 10'001;
    const Case cases[] = {
        {"phase out of range", bad_phase, effect_field::kTypeSpecific, ErrorCode::invalid_parameter, "periodic.phase"},
        {"type change", other_type, effect_field::kTypeSpecific, ErrorCode::invalid_parameter, "type"},
        {"axis the device lacks", bad_axes, effect_field::kAxes | effect_field::kDirection,
         ErrorCode::invalid_parameter, "axes[1]"},
        {"merged params break a rule", repeat_without_trigger, effect_field::kTriggerRepeat,
         ErrorCode::invalid_parameter, "trigger_repeat_interval_us"},
        {"gain out of range", envelope_on_gain, effect_field::kGain | effect_field::kTypeSpecific,
         ErrorCode::invalid_parameter, "gain"},
        {"mask bit that names no field", sine, 1u << 20, ErrorCode::invalid_parameter, "field_mask"},
    };
    for (const Case& c : cases) {
        const Error e = engine_->update(id, c.params, c.mask, true);
        EXPECT_EQ(e.code, c.code) << c.what << ": " << e.message();
        EXPECT_STREQ(e.field, c.field) << c.what;
    }
    const std::array<int16_t, 2> samples = {1, 2};
    EXPECT_EQ(engine_->update(id, sine, effect_field::kTypeSpecific, false, samples).code, ErrorCode::invalid_parameter);
    EXPECT_EQ(engine_->update(EffectId{3, 0}, sine, effect_field::kGain, false).code, ErrorCode::invalid_handle);

    EffectParams now;
    ASSERT_TRUE(engine_->params(id, now).ok());
    EXPECT_EQ(now, sine);
    const EffectStatus status_after = engine_->status(id);
    EXPECT_EQ(status_after.starts, status_before.starts);
    EXPECT_EQ(status_after.elapsed_us, status_before.elapsed_us);
    EXPECT_EQ(engine_->pool().free_bytes, pool_before.free_bytes);
    // It plays on from 7 ms as if nothing had been asked.
    expect_forces(20'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? 5000 * std::sin(2 * kPi * (7000.0 + static_cast<double>(t)) / 20'000) : 0.0;
    }, 0.05);
}

// --- status ------------------------------------------------------------------------------

TEST_F(EngineCommands, StatusFollowsAPlayThroughItsIterations) {
    EffectParams p = ramp_on_x(0, 10'000, 10'000);
    p.iterations = 3;
    p.start_delay_us = 5000;
    const EffectId id = create(p);
    EffectStatus st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::stopped);
    EXPECT_EQ(st.iterations, 3);
    EXPECT_EQ(st.starts, 0u);
    EXPECT_EQ(st.last_end, PlayEnd::none);

    ASSERT_TRUE(engine_->start(id).ok());
    EXPECT_EQ(engine_->status(id).state, EffectState::pending);
    for (int n = 0; n < 3; ++n) tick();  // t = 0, 1, 2 ms: inside the 5 ms delay
    st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::delayed);
    EXPECT_EQ(st.elapsed_us, 2000);
    for (int n = 0; n < 25; ++n) tick();  // up to 27 ms: 22 ms past the delay
    st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::playing);
    EXPECT_EQ(st.elapsed_us, 27'000);
    EXPECT_EQ(st.completed_iterations, 2);
    EXPECT_EQ(st.last_end, PlayEnd::none);

    ASSERT_TRUE(engine_->stop(id).ok());
    st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::stopped);
    EXPECT_EQ(st.last_end, PlayEnd::stopped);
    EXPECT_EQ(st.completed_iterations, 2);
    EXPECT_EQ(st.elapsed_us, 27'000);

    ASSERT_TRUE(engine_->start(id).ok());
    for (int n = 0; n < 40; ++n) tick();  // 5 + 3·10 = 35 ms play
    st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::stopped);
    EXPECT_EQ(st.last_end, PlayEnd::finished);
    EXPECT_EQ(st.completed_iterations, 3);
    EXPECT_EQ(st.starts, 2u);

    EXPECT_EQ(engine_->status(EffectId{}).state, EffectState::free);
    ASSERT_TRUE(engine_->destroy(id).ok());
    EXPECT_EQ(engine_->status(id).state, EffectState::free);
}

// --- device control ----------------------------------------------------------------------

TEST_F(EngineCommands, PauseFreezesARampHalfwayAndItResumesFromWhereItWas) {
    const EffectId id = play(ramp_on_x(0, 10'000, 1'000'000));
    expect_forces(501'000, 1000, [](int64_t t, int axis) {  // t = 0 .. 500 ms
        return axis == 0 ? ramp_at(0, 10'000, static_cast<double>(t), 1'000'000) : 0.0;
    });
    engine_->pause();
    EXPECT_TRUE(engine_->paused());
    for (int n = 0; n < 1000; ++n) {  // a second of pause
        const TickOutput out = tick();
        ASSERT_EQ(out.force[0], 0.0f) << n;
        ASSERT_EQ(out.playing_effects, 0);
    }
    EffectStatus st = engine_->status(id);
    EXPECT_EQ(st.state, EffectState::playing);
    EXPECT_EQ(st.elapsed_us, 500'000);  // its time stood still
    engine_->resume();
    EXPECT_FALSE(engine_->paused());
    // From 501 ms of effect time on, to the end of the ramp.
    expect_forces(499'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? ramp_at(0, 10'000, 501'000.0 + static_cast<double>(t), 1'000'000) : 0.0;
    });
    EXPECT_EQ(tick().force[0], 0.0f);  // 1000 ms of effect time: over, a second late
    st = engine_->status(id);
    EXPECT_EQ(st.last_end, PlayEnd::finished);
}

TEST_F(EngineCommands, PauseHoldsStartDelaysAndPendingStarts) {
    EffectParams delayed = constant_on_x(1000, kInfiniteUs);
    delayed.start_delay_us = 10'000;
    play(delayed);
    for (int n = 0; n < 5; ++n) tick();  // 5 of its 10 ms delay
    engine_->pause();
    const EffectId late = create(constant_on_x(2000, kInfiniteUs));
    ASSERT_TRUE(engine_->start(late).ok());  // started while paused: waits
    for (int n = 0; n < 100; ++n) tick();
    EXPECT_EQ(engine_->state(late), EffectState::pending);
    engine_->resume();
    // The late one begins now; the delayed one still has 5 ms of its delay to wait.
    expect_forces(5000, 1000, [](int64_t, int axis) { return axis == 0 ? 2000.0 : 0.0; });
    EXPECT_EQ(tick().force[0], 3000.0f);
}

TEST_F(EngineCommands, PauseSilencesConditionsAndDynamicsToo) {
    EffectParams spring = constant_on_x(0, kInfiniteUs);
    spring.type = EffectType::spring;
    spring.conditions[0] = {5000, 5000, 0, 10'000, 10'000, 0, OffsetMode::absolute};
    play(spring);
    TickInput in;
    in.position[0] = 4000;
    TickOutput out;
    in.t_us = 0;
    engine_->tick(in, out);
    EXPECT_NEAR(out.force[0], -2000, 1.0);  // -0.5 · 4000
    engine_->pause();
    in.t_us = 1000;
    engine_->tick(in, out);
    EXPECT_EQ(out.force[0], 0.0f);
}

TEST_F(EngineCommands, ActuatorsOffSilenceTheOutputWhileEffectsPlayOn) {
    const EffectId id = play(ramp_on_x(0, 10'000, 1'000'000));
    for (int n = 0; n < 500; ++n) tick();  // to 499 ms
    engine_->set_actuators_enabled(false);
    EXPECT_FALSE(engine_->actuators_enabled());
    for (int n = 0; n < 300; ++n) {  // 500 .. 799 ms
        const TickOutput out = tick();
        ASSERT_EQ(out.force[0], 0.0f);
        ASSERT_FALSE(out.saturated);
        ASSERT_EQ(out.playing_effects, 1);  // it still plays
    }
    EXPECT_EQ(engine_->status(id).elapsed_us, 799'000);  // unlike pause, its clock ran
    engine_->set_actuators_enabled(true);
    EXPECT_NEAR(tick().force[0], ramp_at(0, 10'000, 800'000, 1'000'000), kForceTolerance);
}

TEST_F(EngineCommands, AReusedOutputForgetsTheMassOfAStoppedDynamic) {
    EffectParams recoil;
    recoil.type = EffectType::dynamic_recoil;
    recoil.duration_us = kInfiniteUs;
    recoil.axis_count = 2;
    recoil.dynamic.blast_intensity = 5000;
    const EffectId id = play(recoil);
    TickInput in;
    TickOutput out;  // one output reused tick after tick, as a loop does
    for (int n = 0; n < 20; ++n) {
        in.t_us = 1000 * n;
        engine_->tick(in, out);
    }
    ASSERT_TRUE(out.has_mass);
    ASSERT_TRUE(engine_->stop(id).ok());
    in.t_us = 20'000;
    engine_->tick(in, out);
    EXPECT_FALSE(out.has_mass);
    EXPECT_EQ(out.mass_position[0], 0.0f);
    EXPECT_EQ(out.mass_velocity[1], 0.0f);
}

TEST_F(EngineCommands, StopAllStopsEveryEffectAndKeepsThemResident) {
    const EffectId a = play(constant_on_x(1000, kInfiniteUs));
    const EffectId b = play(constant_on_x(2000, kInfiniteUs));
    const EffectId c = create(constant_on_x(4000, kInfiniteUs));  // never started
    tick();
    engine_->stop_all();
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->status(a).last_end, PlayEnd::stopped);
    EXPECT_EQ(engine_->status(b).last_end, PlayEnd::stopped);
    EXPECT_EQ(engine_->status(c).last_end, PlayEnd::none);  // it was not playing
    ASSERT_TRUE(engine_->start(b).ok());
    EXPECT_EQ(tick().force[0], 2000.0f);
}

TEST_F(EngineCommands, ResetReturnsThePowerOnState) {
    reset(2, 8, 64);
    const PoolInfo empty = engine_->pool();
    const EffectId a = play(constant_on_x(1000, kInfiniteUs));
    EffectParams profile = constant_on_x(0, kInfiniteUs);
    profile.type = EffectType::force_profile;
    profile.custom = {1, 1000, 4};
    const std::array<int16_t, 4> samples = {1, 2, 3, 4};
    const EffectId b = play(profile, samples);
    EffectParams recoil;
    recoil.type = EffectType::dynamic_recoil;
    recoil.duration_us = kInfiniteUs;
    recoil.axis_count = 2;  // x and y: a recoil aims in the plane
    recoil.dynamic.blast_intensity = 5000;
    recoil.dynamic.interim_reporting = true;
    const EffectId c = play(recoil);
    ASSERT_TRUE(engine_->set_gain(3000).ok());
    for (int n = 0; n < 50; ++n) tick();
    engine_->pause();
    engine_->set_actuators_enabled(false);

    engine_->reset();
    for (EffectId id : {a, b, c}) {
        EXPECT_EQ(engine_->state(id), EffectState::free);
        EXPECT_EQ(engine_->start(id).code, ErrorCode::invalid_handle);
    }
    const PoolInfo after = engine_->pool();
    EXPECT_EQ(after.free_bytes, empty.free_bytes);
    EXPECT_EQ(after.free_bytes, after.total_bytes);
    EXPECT_EQ(after.free_effects, 8);
    EXPECT_EQ(after.free_samples, 64);
    EXPECT_EQ(engine_->gain(), 10'000);
    EXPECT_FALSE(engine_->paused());
    EXPECT_TRUE(engine_->actuators_enabled());
    DynamicReport report;
    EXPECT_FALSE(engine_->pop_report(report));
    // The device works as new, at full gain.
    play(constant_on_x(1000, kInfiniteUs));
    EXPECT_EQ(tick().force[0], 1000.0f);
}

}  // namespace
}  // namespace feel::test
