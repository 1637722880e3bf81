// A small valid effect of every type, shared by the tests that need "one of each": the
// validator's, the capability and device-class tests. Written from the primer's examples
// and ranges (§6.6, §7.5, §8), never from the code's output.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>

#include "feel/effect.hpp"

namespace feel::test {

// A four-sample profile for the force_profile cases.
inline constexpr std::array<int16_t, 4> kFourSamples = {1000, -1000, 5000, 0};

inline void set_axes(EffectParams& p, std::initializer_list<Axis> axes) {
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) p.axes[i++] = a;
}

// A small valid effect of each type, written from the primer's examples and ranges.
inline EffectParams valid_effect(EffectType t) {
    EffectParams p;
    p.type = t;
    p.duration_us = 1'000'000;
    set_axes(p, {Axis::x});
    const ConditionBlock spring{1000, 1000, 0, 10000, 10000, 0};  // §7.5's spring
    switch (t) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction:
            p.duration_us = kInfiniteUs;
            set_axes(p, {Axis::x, Axis::y});
            p.conditions[0] = spring;
            p.conditions[1] = spring;
            break;
        case EffectType::angle_spring:
            set_axes(p, {Axis::x, Axis::y});
            p.direction = {DirectionKind::polar, {4500, 0, 0}};
            p.conditions[0] = spring;
            break;
        case EffectType::texture:
            set_axes(p, {Axis::y});
            p.texture = {5000, 5000, 2000, 7500};  // §7.5's washboard
            break;
        case EffectType::axis_wall:
            p.wall.hardness = 8000;
            p.wall.offset = 5000;
            break;
        case EffectType::angle_wall:
            set_axes(p, {Axis::x, Axis::y});
            p.wall.hardness = 8000;
            p.wall.angle = 4500;
            break;
        case EffectType::axis_barrier:
            p.barrier = {5000, 5000, 1000, 0, 0, 0, 0};
            break;
        case EffectType::angle_barrier:
            set_axes(p, {Axis::x, Axis::y});
            p.barrier = {5000, 5000, 1000, 0, 13500, 0, 0};
            break;
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop:
            p.constant.magnitude = 7500;
            break;
        case EffectType::sine:
        case EffectType::square:
        case EffectType::triangle:
        case EffectType::saw_up:
        case EffectType::saw_down:
            p.periodic.magnitude = 2000;
            p.periodic.period_us = 10'000;
            break;
        case EffectType::sweep_sine:
        case EffectType::sweep_square:
        case EffectType::sweep_triangle:
        case EffectType::sweep_saw_up:
        case EffectType::sweep_saw_down:
            set_axes(p, {Axis::x, Axis::y});
            p.periodic.magnitude = -3000;
            p.periodic.period_us = 50'000;
            p.periodic.sweep_start_angle = 0;
            p.periodic.sweep_end_angle = 18000;
            break;
        case EffectType::force_profile:
            p.custom = {1, 10'000, 4};
            break;
        case EffectType::ramp:
            p.ramp = {0, -6000};
            break;
        case EffectType::dynamic_recoil:
            set_axes(p, {Axis::x, Axis::y});
            p.dynamic.blast_direction = 18000;
            p.dynamic.blast_intensity = 8000;
            p.dynamic.dynamic_mass = 500;
            p.dynamic.blast_resonance = 3000;
            p.dynamic.blast_decay = 200;
            break;
        case EffectType::dynamic_impact:
            set_axes(p, {Axis::x, Axis::y});
            p.dynamic.impact_direction = 9000;
            p.dynamic.impact_intensity = -4000;
            p.dynamic.dynamic_mass = 800;
            p.dynamic.elasticity = 6000;
            p.dynamic.collision_absorption = 300;
            break;
        case EffectType::dynamic_liquid:
            p.dynamic.density = 400;
            p.dynamic.settle = 2000;
            p.dynamic.viscosity = 700;
            break;
        case EffectType::dynamic_inertia:
            p.dynamic.inertia = 900;
            p.dynamic.play = 100;
            break;
        case EffectType::dynamic_center_drift:
            p.dynamic.stiffness = 3000;
            p.dynamic.drift_resistance = 500;
            break;
        case EffectType::dynamic_control_law:
            set_axes(p, {Axis::x, Axis::y});
            p.dynamic.control_law[0] = {100, 2000, 2000, 10, 0, 0, 0, 0, 0, 0};
            p.dynamic.control_law[1] = {100, 2000, 2000, 10, 500, -500, 6, 100, 50, -300};
            break;
        case EffectType::dynamic_sling:
            set_axes(p, {Axis::x, Axis::y});
            p.dynamic.ball_mass = 300;
            p.dynamic.string_length = 4000;
            p.dynamic.string_compliance = 2000;
            p.dynamic.ball_damping = 100;
            break;
        case EffectType::dynamic_paddle:
            set_axes(p, {Axis::x, Axis::y});
            p.dynamic.ball_mass = 300;
            p.dynamic.initial_velocity = 6000;
            p.dynamic.initial_velocity_direction = 0;
            p.dynamic.paddle_compliance = 4000;
            p.dynamic.paddle_damping = 100;
            p.dynamic.gravity = -2000;
            break;
    }
    return p;
}

// A force profile of `frames` frames on two channels, channel 0 on x and channel 1 on y
// (§4.3.a), each frame held `period_us`; its samples are passed beside it (2 · frames).
inline EffectParams profile_on_xy(int32_t frames, int64_t period_us) {
    EffectParams p;
    p.type = EffectType::force_profile;
    p.duration_us = frames * period_us;
    set_axes(p, {Axis::x, Axis::y});
    p.direction.kind = DirectionKind::none;
    p.custom = {2, period_us, 2 * frames};
    return p;
}

}  // namespace feel::test
