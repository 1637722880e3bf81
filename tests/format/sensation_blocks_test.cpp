// Each block of the format lands in the right EffectParams fields. Every expected value
// is the literal written in the JSON of the same test.
#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

TEST(SensationBlocks, EffectLevelFields) {
    const EffectParams p = params_of(file_with(R"({
        "type": "sine", "duration_us": 2000000, "start_delay_us": 40000, "iterations": 3,
        "axes": ["y", "x"], "direction": {"polar": 13500}, "gain": 7000,
        "trigger_button": 4, "trigger_repeat_interval_us": 250000,
        "envelope": {"impulse_level": 8000, "settle_time_us": 30000, "fade_level": 100, "fade_time_us": 5000},
        "periodic": {"magnitude": 2000, "offset": -300, "period_us": 10000, "phase": 9000}})"));
    EXPECT_EQ(p.type, EffectType::sine);
    EXPECT_EQ(p.duration_us, 2'000'000);
    EXPECT_EQ(p.start_delay_us, 40'000);
    EXPECT_EQ(p.iterations, 3);
    ASSERT_EQ(p.axis_count, 2);
    EXPECT_EQ(p.axes[0], Axis::y);
    EXPECT_EQ(p.axes[1], Axis::x);
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], 13500);
    EXPECT_EQ(p.gain, 7000);
    EXPECT_EQ(p.trigger.kind, TriggerKind::button);
    EXPECT_EQ(p.trigger.index, 4);
    EXPECT_EQ(p.trigger_repeat_interval_us, 250'000);
    EXPECT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope.impulse_level, 8000);
    EXPECT_EQ(p.envelope.settle_time_us, 30'000);
    EXPECT_EQ(p.envelope.fade_level, 100);
    EXPECT_EQ(p.envelope.fade_time_us, 5000);
    EXPECT_EQ(p.periodic.magnitude, 2000);
    EXPECT_EQ(p.periodic.offset, -300);
    EXPECT_EQ(p.periodic.period_us, 10'000);
    EXPECT_EQ(p.periodic.phase, 9000);
}

TEST(SensationBlocks, DefaultsOfOptionalFields) {
    // Omitted optional fields take the documented defaults.
    const EffectParams p = params_of(file_with(R"({"type": "square", "duration_us": 100000, "axes": ["x"],
        "periodic": {"magnitude": 7000, "period_us": 100000}})"));
    EXPECT_EQ(p.start_delay_us, 0);
    EXPECT_EQ(p.iterations, 1);
    EXPECT_EQ(p.gain, 10000);
    EXPECT_EQ(p.direction.kind, DirectionKind::none);
    EXPECT_EQ(p.trigger.kind, TriggerKind::none);
    EXPECT_EQ(p.trigger_repeat_interval_us, 0);
    EXPECT_FALSE(p.has_envelope);
    EXPECT_EQ(p.periodic.offset, 0);
    EXPECT_EQ(p.periodic.phase, 0);

    // An envelope may omit its fade (§6.3: "Fade Level is often set to zero").
    const EffectParams q = params_of(file_with(R"({"type": "vector_force", "axes": ["x"],
        "envelope": {"impulse_level": 9000, "settle_time_us": 40000}, "constant": {"magnitude": 2000}})"));
    EXPECT_EQ(q.duration_us, kInfiniteUs);  // a vector force is endless unless told (§8.3)
    EXPECT_EQ(q.envelope.fade_level, 0);
    EXPECT_EQ(q.envelope.fade_time_us, 0);
}

TEST(SensationBlocks, InfiniteAndHatTrigger) {
    const EffectParams p = params_of(file_with(R"({"type": "constant", "duration_us": "infinite", "iterations": "infinite",
        "axes": ["x"], "trigger_button": "hat2", "constant": {"magnitude": 7500}})"));
    EXPECT_EQ(p.duration_us, kInfiniteUs);
    EXPECT_EQ(p.iterations, kInfiniteIterations);
    EXPECT_EQ(p.trigger.kind, TriggerKind::hat);
    EXPECT_EQ(p.trigger.index, 2);
    EXPECT_EQ(p.constant.magnitude, 7500);
}

TEST(SensationBlocks, DirectionForms) {
    const EffectParams c = params_of(file_with(R"({"type": "constant", "duration_us": 1, "axes": ["x", "y", "z"],
        "direction": {"cartesian": [300, -400, 5]}, "constant": {"magnitude": 1}})"));
    EXPECT_EQ(c.direction.kind, DirectionKind::cartesian);
    EXPECT_EQ(c.direction.value[0], 300);
    EXPECT_EQ(c.direction.value[1], -400);
    EXPECT_EQ(c.direction.value[2], 5);
    const EffectParams s = params_of(file_with(R"({"type": "constant", "duration_us": 1, "axes": ["x", "y", "z"],
        "direction": {"spherical": [4500, 9000]}, "constant": {"magnitude": 1}})"));
    EXPECT_EQ(s.direction.kind, DirectionKind::spherical);
    EXPECT_EQ(s.direction.value[0], 4500);
    EXPECT_EQ(s.direction.value[1], 9000);
    const EffectParams m = params_of(file_with(R"({"type": "constant", "duration_us": 1, "axes": ["rx", "rz"],
        "direction": {"moments": [-1, 2]}, "constant": {"magnitude": 1}})"));
    EXPECT_EQ(m.direction.kind, DirectionKind::moments);
    EXPECT_EQ(m.axes[0], Axis::rx);
    EXPECT_EQ(m.axes[1], Axis::rz);
    EXPECT_EQ(m.direction.value[0], -1);
    EXPECT_EQ(m.direction.value[1], 2);
}

TEST(SensationBlocks, Conditions) {
    const EffectParams p = params_of(file_with(R"({"type": "friction", "duration_us": "infinite", "axes": ["x", "y"],
        "conditions": [
          {"pos_coefficient": 6000, "neg_coefficient": -5000, "offset": 100, "pos_saturation": 9000, "neg_saturation": 8000, "deadband": 50},
          {"pos_coefficient": 1, "neg_coefficient": 2}]})"));
    EXPECT_EQ(p.type, EffectType::friction);
    EXPECT_EQ(p.conditions[0].pos_coefficient, 6000);
    EXPECT_EQ(p.conditions[0].neg_coefficient, -5000);
    EXPECT_EQ(p.conditions[0].offset, 100);
    EXPECT_EQ(p.conditions[0].pos_saturation, 9000);
    EXPECT_EQ(p.conditions[0].neg_saturation, 8000);
    EXPECT_EQ(p.conditions[0].deadband, 50);
    EXPECT_EQ(p.conditions[1].pos_coefficient, 1);
    EXPECT_EQ(p.conditions[1].neg_coefficient, 2);
    EXPECT_EQ(p.conditions[1].offset, 0);             // default
    EXPECT_EQ(p.conditions[1].pos_saturation, 10000);  // default: no limit
    EXPECT_EQ(p.conditions[1].neg_saturation, 10000);
    EXPECT_EQ(p.conditions[1].deadband, 0);

    const EffectParams a = params_of(file_with(R"({"type": "angle_spring", "duration_us": "infinite", "axes": ["x", "y"],
        "direction": {"polar": 4500}, "conditions": [{"pos_coefficient": 3000, "neg_coefficient": 2000, "deadband": 100}]})"));
    EXPECT_EQ(a.type, EffectType::angle_spring);
    EXPECT_EQ(a.direction.value[0], 4500);
    EXPECT_EQ(a.conditions[0].pos_coefficient, 3000);
    EXPECT_EQ(a.conditions[0].neg_coefficient, 2000);
    EXPECT_EQ(a.conditions[0].deadband, 100);
}

TEST(SensationBlocks, Texture) {
    // §7.5's washboard.
    const EffectParams p = params_of(file_with(R"({"type": "texture", "duration_us": "infinite", "axes": ["x", "y"],
        "direction": {"polar": 0}, "texture": {"pos_roughness": 5000, "neg_roughness": 4000, "spacing": 2000, "density": 7500}})"));
    EXPECT_EQ(p.texture.pos_roughness, 5000);
    EXPECT_EQ(p.texture.neg_roughness, 4000);
    EXPECT_EQ(p.texture.spacing, 2000);
    EXPECT_EQ(p.texture.density, 7500);
}

TEST(SensationBlocks, Walls) {
    const EffectParams a = params_of(file_with(R"({"type": "angle_wall", "duration_us": "infinite", "axes": ["x", "y"],
        "wall": {"hardness": 9000, "sense": "negative", "offset": 3000, "offset_mode": "relative", "angle": 4500,
                 "surface_friction": 200, "surface_texture": 300, "clipping": true}})"));
    EXPECT_EQ(a.wall.hardness, 9000);
    EXPECT_EQ(a.wall.sense, WallSense::negative);
    EXPECT_EQ(a.wall.offset, 3000);
    EXPECT_EQ(a.wall.offset_mode, OffsetMode::relative);
    EXPECT_EQ(a.wall.angle, 4500);
    EXPECT_EQ(a.wall.surface_friction, 200);
    EXPECT_EQ(a.wall.surface_texture, 300);
    EXPECT_TRUE(a.wall.clipping);

    const EffectParams x = params_of(file_with(R"({"type": "axis_wall", "duration_us": "infinite", "axes": ["y"],
        "wall": {"hardness": -100, "sense": "positive"}})"));
    EXPECT_EQ(x.wall.hardness, -100);
    EXPECT_EQ(x.wall.sense, WallSense::positive);
    EXPECT_EQ(x.wall.offset_mode, OffsetMode::absolute);  // default
    EXPECT_FALSE(x.wall.clipping);                       // default
    EXPECT_EQ(x.wall.angle, 0);
}

TEST(SensationBlocks, Barriers) {
    const EffectParams a = params_of(file_with(R"({"type": "angle_barrier", "duration_us": "infinite", "axes": ["x", "y"],
        "barrier": {"pos_hardness": 5000, "neg_hardness": -2000, "thickness": 800, "offset": -100, "angle": 13500,
                    "surface_friction": 10, "surface_texture": 20}})"));
    EXPECT_EQ(a.barrier.pos_hardness, 5000);
    EXPECT_EQ(a.barrier.neg_hardness, -2000);
    EXPECT_EQ(a.barrier.thickness, 800);
    EXPECT_EQ(a.barrier.offset, -100);
    EXPECT_EQ(a.barrier.angle, 13500);
    EXPECT_EQ(a.barrier.surface_friction, 10);
    EXPECT_EQ(a.barrier.surface_texture, 20);

    const EffectParams x = params_of(file_with(R"({"type": "axis_barrier", "duration_us": "infinite", "axes": ["z"],
        "barrier": {"pos_hardness": 1, "neg_hardness": 2, "thickness": 3}})"));
    EXPECT_EQ(x.axes[0], Axis::z);
    EXPECT_EQ(x.barrier.pos_hardness, 1);
    EXPECT_EQ(x.barrier.neg_hardness, 2);
    EXPECT_EQ(x.barrier.thickness, 3);
    EXPECT_EQ(x.barrier.offset_mode, OffsetMode::absolute);  // default

    // §3.8: "The Offset-Flag ... same as the wall".
    const EffectParams r = params_of(file_with(R"({"type": "axis_barrier", "duration_us": "infinite", "axes": ["x"],
        "barrier": {"pos_hardness": 1, "neg_hardness": 2, "thickness": 3, "offset": 1500, "offset_mode": "relative"}})"));
    EXPECT_EQ(r.barrier.offset, 1500);
    EXPECT_EQ(r.barrier.offset_mode, OffsetMode::relative);
}

TEST(SensationBlocks, AConditionWithADirectionHasOneBlock) {
    // §3.1 "for multi-axis conditions, you can define a direction": one block applied along it.
    const EffectParams p = params_of(file_with(R"({"type": "damper", "duration_us": "infinite", "axes": ["x", "y", "z"],
        "direction": {"spherical": [4500, 6000]},
        "conditions": [{"pos_coefficient": 7000, "neg_coefficient": 3000, "deadband": 40}]})"));
    EXPECT_EQ(p.direction.kind, DirectionKind::spherical);
    EXPECT_EQ(p.direction.value[0], 4500);
    EXPECT_EQ(p.direction.value[1], 6000);
    EXPECT_EQ(p.conditions[0].pos_coefficient, 7000);
    EXPECT_EQ(p.conditions[0].neg_coefficient, 3000);
    EXPECT_EQ(p.conditions[0].deadband, 40);
    EXPECT_EQ(p.conditions[1], ConditionBlock{});  // not read: left at its defaults
    EXPECT_EQ(p.conditions[2], ConditionBlock{});
}

TEST(SensationBlocks, SweepFields) {
    const EffectParams p = params_of(file_with(R"({"type": "sweep_saw_down", "duration_us": 3000000, "axes": ["x", "y"],
        "periodic": {"magnitude": -4000, "offset": 10, "period_us": 50000, "phase": 18000,
                     "sweep_start_angle": 27000, "sweep_end_angle": 9000, "sweep_sense": "counterclockwise"}})"));
    EXPECT_EQ(p.type, EffectType::sweep_saw_down);
    EXPECT_EQ(p.periodic.magnitude, -4000);
    EXPECT_EQ(p.periodic.offset, 10);
    EXPECT_EQ(p.periodic.period_us, 50'000);
    EXPECT_EQ(p.periodic.phase, 18000);
    EXPECT_EQ(p.periodic.sweep_start_angle, 27000);
    EXPECT_EQ(p.periodic.sweep_end_angle, 9000);
    EXPECT_EQ(p.periodic.sweep_sense, SweepSense::counterclockwise);
}

TEST(SensationBlocks, ConstantRampAndProfile) {
    const EffectParams r = params_of(file_with(R"({"type": "ramp", "duration_us": 2000000, "axes": ["y"],
        "ramp": {"start": 100, "end": -6000}})"));
    EXPECT_EQ(r.ramp.start, 100);
    EXPECT_EQ(r.ramp.end, -6000);

    const EffectParams s = params_of(file_with(R"({"type": "smart_pop", "duration_us": 20000, "axes": ["x"],
        "constant": {"magnitude": -6000}})"));
    EXPECT_EQ(s.constant.magnitude, -6000);

    const SensationFile f = parse_sensation_file(file_with(R"({"type": "force_profile", "duration_us": 40000, "axes": ["x", "y"],
        "custom": {"channels": 2, "sample_period_us": 5000, "samples": [0, -9000, 2000, -6000]}})"), "t.json");
    const EffectSpec& e = f.sensations[0].effects[0];
    EXPECT_EQ(e.params.custom.channels, 2);
    EXPECT_EQ(e.params.custom.sample_period_us, 5000);
    EXPECT_EQ(e.params.custom.sample_count, 4);  // implied by the array
    EXPECT_EQ(e.samples, (std::vector<int16_t>{0, -9000, 2000, -6000}));
}

TEST(SensationBlocks, NamedDynamics) {
    const EffectParams recoil = params_of(file_with(R"({"type": "dynamic_recoil", "duration_us": 500000, "axes": ["x", "y"],
        "dynamic": {"blast_direction": 18000, "blast_intensity": 8000, "dynamic_mass": 500, "blast_resonance": 3000,
                    "blast_decay": 200, "interim_reporting": true}})"));
    EXPECT_EQ(recoil.dynamic.blast_direction, 18000);
    EXPECT_EQ(recoil.dynamic.blast_intensity, 8000);
    EXPECT_EQ(recoil.dynamic.dynamic_mass, 500);
    EXPECT_EQ(recoil.dynamic.blast_resonance, 3000);
    EXPECT_EQ(recoil.dynamic.blast_decay, 200);
    EXPECT_TRUE(recoil.dynamic.interim_reporting);

    const EffectParams impact = params_of(file_with(R"({"type": "dynamic_impact", "duration_us": 500000, "axes": ["x", "y"],
        "dynamic": {"impact_direction": 9000, "impact_intensity": -4000, "dynamic_mass": 800, "elasticity": 6000,
                    "collision_absorption": 300}})"));
    EXPECT_EQ(impact.dynamic.impact_direction, 9000);
    EXPECT_EQ(impact.dynamic.impact_intensity, -4000);
    EXPECT_EQ(impact.dynamic.dynamic_mass, 800);
    EXPECT_EQ(impact.dynamic.elasticity, 6000);
    EXPECT_EQ(impact.dynamic.collision_absorption, 300);
    EXPECT_FALSE(impact.dynamic.interim_reporting);

    const EffectParams liquid = params_of(file_with(R"({"type": "dynamic_liquid", "duration_us": "infinite", "axes": ["x"],
        "dynamic": {"density": 400, "settle": 2000, "viscosity": 700}})"));
    EXPECT_EQ(liquid.dynamic.density, 400);
    EXPECT_EQ(liquid.dynamic.settle, 2000);
    EXPECT_EQ(liquid.dynamic.viscosity, 700);

    const EffectParams inertia = params_of(file_with(R"({"type": "dynamic_inertia", "duration_us": "infinite", "axes": ["x"],
        "dynamic": {"inertia": 900, "play": 100}})"));
    EXPECT_EQ(inertia.dynamic.inertia, 900);
    EXPECT_EQ(inertia.dynamic.play, 100);

    const EffectParams drift = params_of(file_with(R"({"type": "dynamic_center_drift", "duration_us": "infinite", "axes": ["x"],
        "dynamic": {"stiffness": 3000, "drift_resistance": 500}})"));
    EXPECT_EQ(drift.dynamic.stiffness, 3000);
    EXPECT_EQ(drift.dynamic.drift_resistance, 500);

    const EffectParams sling = params_of(file_with(R"({"type": "dynamic_sling", "duration_us": "infinite", "axes": ["x", "y"],
        "dynamic": {"ball_mass": 300, "string_length": 4000, "string_compliance": 2000, "ball_damping": 100}})"));
    EXPECT_EQ(sling.dynamic.ball_mass, 300);
    EXPECT_EQ(sling.dynamic.string_length, 4000);
    EXPECT_EQ(sling.dynamic.string_compliance, 2000);
    EXPECT_EQ(sling.dynamic.ball_damping, 100);

    const EffectParams paddle = params_of(file_with(R"({"type": "dynamic_paddle", "duration_us": 800000, "axes": ["x", "y"],
        "dynamic": {"ball_mass": 300, "initial_velocity": 6000, "initial_velocity_direction": 27000, "paddle_compliance": 4000,
                    "paddle_damping": 100, "gravity": -2000}})"));
    EXPECT_EQ(paddle.dynamic.ball_mass, 300);
    EXPECT_EQ(paddle.dynamic.initial_velocity, 6000);
    EXPECT_EQ(paddle.dynamic.initial_velocity_direction, 27000);
    EXPECT_EQ(paddle.dynamic.paddle_compliance, 4000);
    EXPECT_EQ(paddle.dynamic.paddle_damping, 100);
    EXPECT_EQ(paddle.dynamic.gravity, -2000);
}

TEST(SensationBlocks, ControlLaw) {
    const EffectParams p = params_of(file_with(R"({"type": "dynamic_control_law", "duration_us": "infinite", "axes": ["x", "y"],
        "dynamic": {"control_law": [
            {"mass": 100, "k_pos": 2000, "k_neg": 1500, "b": 10, "vel_init": 500, "pos_init": -500, "half_cycles": 6,
             "length": 100, "drag": 50, "gravity": -300},
            {"mass": 7, "k_pos": 8, "k_neg": 9}],
          "interim_reporting": true}})"));
    const ControlLawBlock& x = p.dynamic.control_law[0];
    EXPECT_EQ(x.mass, 100);
    EXPECT_EQ(x.k_pos, 2000);
    EXPECT_EQ(x.k_neg, 1500);
    EXPECT_EQ(x.b, 10);
    EXPECT_EQ(x.vel_init, 500);
    EXPECT_EQ(x.pos_init, -500);
    EXPECT_EQ(x.half_cycles, 6);
    EXPECT_EQ(x.length, 100);
    EXPECT_EQ(x.drag, 50);
    EXPECT_EQ(x.gravity, -300);
    const ControlLawBlock& y = p.dynamic.control_law[1];
    EXPECT_EQ(y.mass, 7);
    EXPECT_EQ(y.k_pos, 8);
    EXPECT_EQ(y.k_neg, 9);
    EXPECT_EQ(y.b, 0);
    EXPECT_EQ(y.half_cycles, 0);  // 0 = never end (§8.4)
    EXPECT_TRUE(p.dynamic.interim_reporting);
}

TEST(SensationBlocks, CompoundKeepsEffectsAndDelays) {
    const SensationFile f = parse_sensation_file(file_with(R"({"description": "a burst", "effects": [
        {"type": "square", "duration_us": 100000, "axes": ["x"], "periodic": {"magnitude": 5000, "period_us": 100000}},
        {"type": "vector_force", "start_delay_us": 40000, "axes": ["y"], "constant": {"magnitude": -3000}}]})",
                                                           "gun_burst"),
                                                 "t.json");
    ASSERT_EQ(f.sensations.size(), 1u);
    const Sensation& s = f.sensations[0];
    EXPECT_EQ(s.name, "gun_burst");
    EXPECT_EQ(s.description, "a burst");
    EXPECT_TRUE(s.compound);
    ASSERT_EQ(s.effects.size(), 2u);
    EXPECT_EQ(s.effects[0].params.type, EffectType::square);
    EXPECT_EQ(s.effects[0].params.start_delay_us, 0);
    EXPECT_EQ(s.effects[1].params.type, EffectType::vector_force);
    EXPECT_EQ(s.effects[1].params.start_delay_us, 40'000);
    EXPECT_EQ(s.effects[1].params.constant.magnitude, -3000);
    EXPECT_EQ(f.find("gun_burst"), &s);
    EXPECT_EQ(f.find("nope"), nullptr);
}

TEST(SensationBlocks, SensationsKeepFileOrder) {
    const SensationFile f = parse_sensation_file(R"({"format": "feel/1", "sensations": {
        "zulu": {"type": "constant", "duration_us": 1, "axes": ["x"], "constant": {"magnitude": 1}},
        "alpha": {"type": "constant", "duration_us": 1, "axes": ["x"], "constant": {"magnitude": 2}},
        "mike": {"type": "constant", "duration_us": 1, "axes": ["x"], "constant": {"magnitude": 3}}}})",
                                                 "t.json");
    ASSERT_EQ(f.sensations.size(), 3u);
    EXPECT_EQ(f.sensations[0].name, "zulu");
    EXPECT_EQ(f.sensations[1].name, "alpha");
    EXPECT_EQ(f.sensations[2].name, "mike");
}

// One effect of every type, each with the block its type reads.
constexpr const char* kEveryType[] = {
    R"("spring": {"type": "spring", "duration_us": "infinite", "axes": ["x"], "conditions": [{"pos_coefficient": 1000, "neg_coefficient": 1000}]})",
    R"("damper": {"type": "damper", "duration_us": "infinite", "axes": ["x"], "conditions": [{"pos_coefficient": 1000, "neg_coefficient": 1000}]})",
    R"("inertia": {"type": "inertia", "duration_us": "infinite", "axes": ["x"], "conditions": [{"pos_coefficient": 1000, "neg_coefficient": 1000}]})",
    R"("friction": {"type": "friction", "duration_us": "infinite", "axes": ["x"], "conditions": [{"pos_coefficient": 1000, "neg_coefficient": 1000}]})",
    R"("angle_spring": {"type": "angle_spring", "duration_us": "infinite", "axes": ["x", "y"], "direction": {"polar": 4500}, "conditions": [{"pos_coefficient": 1000, "neg_coefficient": 1000}]})",
    R"("axis_barrier": {"type": "axis_barrier", "duration_us": "infinite", "axes": ["x"], "barrier": {"pos_hardness": 1, "neg_hardness": 1, "thickness": 1}})",
    R"("angle_barrier": {"type": "angle_barrier", "duration_us": "infinite", "axes": ["x", "y"], "barrier": {"pos_hardness": 1, "neg_hardness": 1, "thickness": 1, "angle": 0}})",
    R"("axis_wall": {"type": "axis_wall", "duration_us": "infinite", "axes": ["x"], "wall": {"hardness": 1, "sense": "positive"}})",
    R"("angle_wall": {"type": "angle_wall", "duration_us": "infinite", "axes": ["x", "y"], "wall": {"hardness": 1, "sense": "positive", "angle": 0}})",
    R"("texture": {"type": "texture", "duration_us": "infinite", "axes": ["x"], "texture": {"pos_roughness": 1, "neg_roughness": 1, "spacing": 1, "density": 1}})",
    R"("vector_force": {"type": "vector_force", "axes": ["x"], "constant": {"magnitude": 1}})",
    R"("constant": {"type": "constant", "duration_us": 1, "axes": ["x"], "constant": {"magnitude": 1}})",
    R"("smart_pop": {"type": "smart_pop", "duration_us": 1, "axes": ["x"], "constant": {"magnitude": 1}})",
    R"("sine": {"type": "sine", "duration_us": 1, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})",
    R"("square": {"type": "square", "duration_us": 1, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})",
    R"("triangle": {"type": "triangle", "duration_us": 1, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})",
    R"("saw_up": {"type": "saw_up", "duration_us": 1, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})",
    R"("saw_down": {"type": "saw_down", "duration_us": 1, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})",
    R"("sweep_sine": {"type": "sweep_sine", "duration_us": 1, "axes": ["x", "y"], "periodic": {"magnitude": 1, "period_us": 1, "sweep_start_angle": 0, "sweep_end_angle": 1, "sweep_sense": "clockwise"}})",
    R"("sweep_square": {"type": "sweep_square", "duration_us": 1, "axes": ["x", "y"], "periodic": {"magnitude": 1, "period_us": 1, "sweep_start_angle": 0, "sweep_end_angle": 1, "sweep_sense": "clockwise"}})",
    R"("sweep_triangle": {"type": "sweep_triangle", "duration_us": 1, "axes": ["x", "y"], "periodic": {"magnitude": 1, "period_us": 1, "sweep_start_angle": 0, "sweep_end_angle": 1, "sweep_sense": "clockwise"}})",
    R"("sweep_saw_up": {"type": "sweep_saw_up", "duration_us": 1, "axes": ["x", "y"], "periodic": {"magnitude": 1, "period_us": 1, "sweep_start_angle": 0, "sweep_end_angle": 1, "sweep_sense": "clockwise"}})",
    R"("sweep_saw_down": {"type": "sweep_saw_down", "duration_us": 1, "axes": ["x", "y"], "periodic": {"magnitude": 1, "period_us": 1, "sweep_start_angle": 0, "sweep_end_angle": 1, "sweep_sense": "clockwise"}})",
    R"("force_profile": {"type": "force_profile", "duration_us": 1, "axes": ["x"], "custom": {"sample_period_us": 1, "samples": [1]}})",
    R"("ramp": {"type": "ramp", "duration_us": 1, "axes": ["x"], "ramp": {"start": 0, "end": 1}})",
    R"("dynamic_recoil": {"type": "dynamic_recoil", "duration_us": 1, "axes": ["x", "y"], "dynamic": {"blast_direction": 0, "blast_intensity": 1, "dynamic_mass": 1, "blast_resonance": 1, "blast_decay": 0}})",
    R"("dynamic_impact": {"type": "dynamic_impact", "duration_us": 1, "axes": ["x", "y"], "dynamic": {"impact_direction": 0, "impact_intensity": 1, "dynamic_mass": 1, "elasticity": 1, "collision_absorption": 0}})",
    R"("dynamic_liquid": {"type": "dynamic_liquid", "duration_us": 1, "axes": ["x"], "dynamic": {"density": 1, "settle": 1, "viscosity": 0}})",
    R"("dynamic_inertia": {"type": "dynamic_inertia", "duration_us": 1, "axes": ["x"], "dynamic": {"inertia": 1, "play": 0}})",
    R"("dynamic_center_drift": {"type": "dynamic_center_drift", "duration_us": 1, "axes": ["x"], "dynamic": {"stiffness": 1, "drift_resistance": 0}})",
    R"("dynamic_control_law": {"type": "dynamic_control_law", "duration_us": 1, "axes": ["x"], "dynamic": {"control_law": [{"mass": 1, "k_pos": 1, "k_neg": 1}]}})",
    R"("dynamic_sling": {"type": "dynamic_sling", "duration_us": 1, "axes": ["x"], "dynamic": {"ball_mass": 1, "string_length": 0, "string_compliance": 1, "ball_damping": 0}})",
    R"("dynamic_paddle": {"type": "dynamic_paddle", "duration_us": 1, "axes": ["x", "y"], "dynamic": {"ball_mass": 1, "initial_velocity": 0, "initial_velocity_direction": 0, "paddle_compliance": 1, "paddle_damping": 0, "gravity": 0}})",
};
static_assert(std::size(kEveryType) == kEffectTypeCount);

TEST(SensationBlocks, AllThirtyThreeTypesParseAndValidate) {
    std::string text = R"({"format": "feel/1", "sensations": {)";
    for (size_t i = 0; i < std::size(kEveryType); ++i) text += (i ? ",\n" : "\n") + std::string(kEveryType[i]);
    text += "}}";
    const SensationFile f = parse_sensation_file(text, "all.json");
    ASSERT_EQ(f.sensations.size(), static_cast<size_t>(kEffectTypeCount));
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const Sensation& s = f.sensations[static_cast<size_t>(i)];
        // Each sensation is named after its type; the parsed type is that enumerator.
        EXPECT_EQ(s.name, effect_type_name(static_cast<EffectType>(i)));
        EXPECT_EQ(s.effects.at(0).params.type, static_cast<EffectType>(i));
        EXPECT_TRUE(validate_effect(s.effects[0].params, s.effects[0].samples).ok()) << s.name;
    }
}

}  // namespace
}  // namespace feel::format::test
