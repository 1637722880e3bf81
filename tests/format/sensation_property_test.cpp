// Property: any valid effect, of any type, written to a file and read back is the same
// effect. The generator builds effects from the primer's ranges and the direction rules
// of docs/sensation-format.md, independently of the reader and writer.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>  // after gtest: it uses ::testing without including it

#include <algorithm>
#include <vector>

#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

// A value in [lo, hi], with the ends chosen often: edges are where ranges go wrong.
int64_t pick(int64_t lo, int64_t hi) {
    return *rc::gen::weightedOneOf<int64_t>({{1, rc::gen::just(lo)},
                                             {1, rc::gen::just(hi)},
                                             {6, rc::gen::inRange<int64_t>(lo, hi + 1)}});
}
int32_t pick32(int64_t lo, int64_t hi) { return static_cast<int32_t>(pick(lo, hi)); }
int32_t level() { return pick32(0, 10000); }
int32_t signed_level() { return pick32(-10000, 10000); }
int32_t positive_level() { return pick32(1, 10000); }
int32_t angle() { return pick32(0, 35999); }
bool coin() { return *rc::gen::arbitrary<bool>(); }

// `n` distinct axes drawn from `pool`, in random order.
void set_axes_from(EffectParams& p, std::vector<Axis> pool, int n) {
    for (size_t i = pool.size(); i > 1; --i) std::swap(pool[i - 1], pool[*rc::gen::inRange<size_t>(0, i)]);
    p.axis_count = n;
    for (int i = 0; i < n; ++i) p.axes[i] = pool[static_cast<size_t>(i)];
}

const std::vector<Axis> kAllAxes = {Axis::x, Axis::y, Axis::z, Axis::rx, Axis::ry, Axis::rz};
const std::vector<Axis> kTranslational = {Axis::x, Axis::y, Axis::z};
const std::vector<Axis> kRotational = {Axis::rx, Axis::ry, Axis::rz};

void any_axes(EffectParams& p) { set_axes_from(p, kAllAxes, pick32(1, 6)); }
void xy_axes(EffectParams& p) { set_axes_from(p, {Axis::x, Axis::y}, 2); }

void vector_components(EffectParams& p) {
    bool any = false;
    for (int i = 0; i < p.axis_count; ++i) {
        p.direction.value[i] = signed_level();
        any = any || p.direction.value[i] != 0;
    }
    if (!any) p.direction.value[0] = 1;  // the zero vector names no direction
}

// Axes and a direction that fit together (§6.5). `single_may_omit`: one axis, no direction.
void axes_and_direction(EffectParams& p, bool single_may_omit) {
    const int form = *rc::gen::inRange(single_may_omit ? 0 : 1, 5);
    switch (form) {
        case 0:
            set_axes_from(p, kAllAxes, 1);
            break;
        case 1:
            xy_axes(p);
            p.direction = {DirectionKind::polar, {angle(), 0, 0}};
            break;
        case 2:
            set_axes_from(p, kTranslational, 3);
            p.direction = {DirectionKind::spherical, {angle(), pick32(0, 18000), 0}};
            break;
        case 3:
            set_axes_from(p, kTranslational, pick32(1, 3));
            p.direction.kind = DirectionKind::cartesian;
            vector_components(p);
            break;
        default:
            set_axes_from(p, kRotational, pick32(1, 3));
            p.direction.kind = DirectionKind::moments;
            vector_components(p);
            break;
    }
}

ConditionBlock condition() {
    return {signed_level(), signed_level(), signed_level(), level(), level(), level()};
}

void periodic(EffectParams& p, bool sweep) {
    p.periodic.magnitude = sweep ? signed_level() : level();
    p.periodic.offset = signed_level();
    p.periodic.period_us = pick(1, 65'000'000);
    p.periodic.phase = angle();
    if (sweep) {
        p.periodic.sweep_start_angle = angle();
        p.periodic.sweep_end_angle = angle();
        p.periodic.sweep_sense = coin() ? SweepSense::clockwise : SweepSense::counterclockwise;
    }
}

EffectSpec valid_effect() {
    EffectSpec spec;
    EffectParams& p = spec.params;
    p.type = static_cast<EffectType>(*rc::gen::inRange(0, kEffectTypeCount));
    const EffectType t = p.type;

    const bool needs_finite = t == EffectType::ramp || t == EffectType::smart_pop || is_sweep(t);
    p.duration_us = (!needs_finite && coin()) ? kInfiniteUs : pick(1, 65'000'000);
    p.start_delay_us = coin() ? 0 : pick(0, 65'000'000);
    p.gain = coin() ? 10000 : level();
    p.iterations = coin() ? 1 : (coin() ? kInfiniteIterations : pick32(1, 255));
    switch (*rc::gen::inRange(0, 3)) {
        case 0: break;
        case 1: p.trigger = {TriggerKind::button, pick32(1, 32)}; break;
        default: p.trigger = {TriggerKind::hat, pick32(1, 4)}; break;
    }
    if (p.trigger.kind != TriggerKind::none && coin()) p.trigger_repeat_interval_us = pick(0, 65'000'000);
    if (supports_envelope(t) && coin()) {
        p.has_envelope = true;
        p.envelope = {level(), pick(0, 65'000'000), level(), pick(0, 65'000'000)};
    }

    if (is_periodic(t)) {
        axes_and_direction(p, true);
        periodic(p, false);
        return spec;
    }
    if (is_sweep(t)) {
        xy_axes(p);
        periodic(p, true);
        return spec;
    }
    DynamicBlock& d = p.dynamic;
    switch (t) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction:
            any_axes(p);
            for (int i = 0; i < p.axis_count; ++i) p.conditions[i] = condition();
            break;
        case EffectType::angle_spring:
            xy_axes(p);
            p.direction = {DirectionKind::polar, {angle(), 0, 0}};
            p.conditions[0] = condition();
            break;
        case EffectType::texture:
            axes_and_direction(p, true);
            if (p.axis_count == 1) p.direction = {};  // a texture on one axis lies along it
            p.texture = {positive_level(), positive_level(), positive_level(), positive_level()};
            break;
        case EffectType::axis_wall:
        case EffectType::angle_wall: {
            const bool angled = t == EffectType::angle_wall;
            if (angled) {
                xy_axes(p);
            } else {
                set_axes_from(p, kAllAxes, 1);
            }
            p.wall = {signed_level(), coin() ? WallSense::positive : WallSense::negative, signed_level(),
                      coin() ? OffsetMode::absolute : OffsetMode::relative, angled ? angle() : 0, level(), level(),
                      coin()};
            break;
        }
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: {
            const bool angled = t == EffectType::angle_barrier;
            if (angled) {
                xy_axes(p);
            } else {
                set_axes_from(p, kAllAxes, 1);
            }
            p.barrier = {signed_level(), signed_level(), positive_level(), signed_level(), angled ? angle() : 0,
                         level(), level()};
            break;
        }
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop:
            axes_and_direction(p, true);
            p.constant.magnitude = signed_level();
            break;
        case EffectType::ramp:
            axes_and_direction(p, true);
            p.ramp = {signed_level(), signed_level()};
            break;
        case EffectType::force_profile: {
            if (coin()) {
                axes_and_direction(p, true);
                p.custom.channels = 1;
            } else {
                any_axes(p);
                p.custom.channels = p.axis_count;
            }
            const int frames = pick32(1, 40);
            p.custom.sample_period_us = pick(1, 65'000'000);
            p.custom.sample_count = frames * p.custom.channels;
            for (int i = 0; i < p.custom.sample_count; ++i) spec.samples.push_back(static_cast<int16_t>(signed_level()));
            break;
        }
        case EffectType::dynamic_recoil:
            xy_axes(p);
            d.blast_direction = angle();
            d.blast_intensity = signed_level();
            d.dynamic_mass = positive_level();
            d.blast_resonance = positive_level();
            d.blast_decay = level();
            break;
        case EffectType::dynamic_impact:
            xy_axes(p);
            d.impact_direction = angle();
            d.impact_intensity = signed_level();
            d.dynamic_mass = positive_level();
            d.elasticity = positive_level();
            d.collision_absorption = level();
            break;
        case EffectType::dynamic_liquid:
            any_axes(p);
            d.density = positive_level();
            d.settle = positive_level();
            d.viscosity = level();
            break;
        case EffectType::dynamic_inertia:
            any_axes(p);
            d.inertia = positive_level();
            d.play = level();
            break;
        case EffectType::dynamic_center_drift:
            any_axes(p);
            d.stiffness = positive_level();
            d.drift_resistance = level();
            break;
        case EffectType::dynamic_control_law:
            any_axes(p);
            for (int i = 0; i < p.axis_count; ++i) {
                d.control_law[i] = {positive_level(), positive_level(), positive_level(), level(), signed_level(),
                                    signed_level(), level(), level(), level(), signed_level()};
            }
            break;
        case EffectType::dynamic_sling:
            any_axes(p);
            d.ball_mass = positive_level();
            d.string_length = level();
            d.string_compliance = positive_level();
            d.ball_damping = level();
            break;
        case EffectType::dynamic_paddle:
            xy_axes(p);
            d.ball_mass = positive_level();
            d.initial_velocity = signed_level();
            d.initial_velocity_direction = angle();
            d.paddle_compliance = positive_level();
            d.paddle_damping = level();
            d.gravity = signed_level();
            break;
        default:
            break;
    }
    if (effect_class(t) == EffectClass::dynamic) d.interim_reporting = coin();
    return spec;
}

RC_GTEST_PROP(SensationProperty, AnyValidEffectSurvivesWriteAndRead, ()) {
    SensationFile file;
    const int sensations = *rc::gen::inRange(1, 4);
    for (int s = 0; s < sensations; ++s) {
        Sensation sensation;
        sensation.name = "s" + std::to_string(s);
        if (coin()) sensation.description = "generated";
        sensation.compound = coin();
        const int effects = sensation.compound ? *rc::gen::inRange(1, 4) : 1;
        for (int e = 0; e < effects; ++e) {
            sensation.effects.push_back(valid_effect());
            const EffectSpec& spec = sensation.effects.back();
            const Error err = validate_effect(spec.params, spec.samples);
            if (!err.ok()) {  // the generator makes only valid effects
                RC_FAIL(std::string(effect_type_name(spec.params.type)) + ": " + err.message());
            }
        }
        file.sensations.push_back(std::move(sensation));
    }

    const std::string text = write_sensation_file(file);
    const SensationFile back = parse_sensation_file(text, "generated.json");
    RC_ASSERT(back.sensations.size() == file.sensations.size());
    for (size_t s = 0; s < file.sensations.size(); ++s) {
        const Sensation& a = file.sensations[s];
        const Sensation& b = back.sensations[s];
        RC_ASSERT(a.name == b.name);
        RC_ASSERT(a.description == b.description);
        RC_ASSERT(a.compound == b.compound);
        RC_ASSERT(a.effects.size() == b.effects.size());
        for (size_t e = 0; e < a.effects.size(); ++e) {
            RC_ASSERT(a.effects[e].params == b.effects[e].params);
            RC_ASSERT(a.effects[e].samples == b.effects[e].samples);
        }
    }
    // And the text read back is canonical: it writes to itself.
    RC_ASSERT(write_sensation_file(back) == text);
}

}  // namespace
}  // namespace feel::format::test
