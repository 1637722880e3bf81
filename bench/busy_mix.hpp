// A busy mix of effects for benchmarks and real-time tests: every wave family, every
// Spatial Condition and every Dynamic Sensation in turn, with parameters that keep each one
// doing its real work (envelopes, contact with walls and barriers, tethered masses with
// interim reports), and a handle motion that exercises the velocity estimator.
//
// Used by bench/bench_tick.cpp (the cost of one tick), `feel bench loop` (the loop's jitter
// under that load) and the runtime's allocation test. Header-only and free of exceptions, so
// any of them can include it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include "feel/engine.hpp"

namespace feel::bench {

// Samples of the force profile in the mix: 8 samples, interleaved for 2 axes.
inline constexpr std::array<int16_t, 8> kBusyMixSamples = {100, -100, 200, -200, 300, -300, 400, -400};

// Every wave family in turn: constant, vector force, smart pop, five periodics with
// envelopes, five sweeps, force profile, ramp.
inline EffectParams mixed_wave(int i) {
    EffectParams p;
    p.type = static_cast<EffectType>(static_cast<int>(EffectType::vector_force) + i % 15);
    p.duration_us = 1'000'000;
    p.iterations = kInfiniteIterations;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    const bool directed = !is_sweep(p.type) && p.type != EffectType::force_profile;
    p.direction.kind = directed ? DirectionKind::polar : DirectionKind::none;
    p.direction.value[0] = (i * 2350) % 36000;
    p.constant.magnitude = 150;
    p.periodic = {150, 10, 5'000 + 700 * i, (i * 1000) % 36000, 0, 27000, SweepSense::clockwise};
    p.ramp = {-150, 150};
    p.custom = {2, 2000, 8};
    p.has_envelope = supports_envelope(p.type);
    p.envelope = {300, 20'000, 0, 50'000};
    return p;
}

// Every Spatial Condition in turn, with parameters that keep the handle in contact.
inline EffectParams mixed_condition(int i) {
    constexpr EffectType kTypes[] = {EffectType::spring,        EffectType::damper,       EffectType::inertia,
                                     EffectType::friction,      EffectType::angle_spring, EffectType::axis_barrier,
                                     EffectType::angle_barrier, EffectType::axis_wall,    EffectType::angle_wall,
                                     EffectType::texture};
    EffectParams p;
    p.type = kTypes[i % 10];
    p.duration_us = kInfiniteUs;
    const bool one_axis = p.type == EffectType::axis_wall || p.type == EffectType::axis_barrier;
    p.axis_count = one_axis ? 1 : 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    if (p.type == EffectType::angle_spring || p.type == EffectType::texture) {
        p.direction.kind = DirectionKind::polar;
        p.direction.value[0] = (i * 3100) % 36000;
    }
    for (ConditionBlock& c : p.conditions) c = {300, 200, 0, 1000, 1000, 20, OffsetMode::absolute};
    p.texture = {300, 200, 400, 5000};
    p.wall = {300, WallSense::positive, 2000, OffsetMode::absolute, one_axis ? 0 : (i * 1700) % 36000, 200, 100, true};
    p.barrier = {300, 300, 500, -2000, one_axis ? 0 : (i * 2300) % 36000, 200, 100};
    return p;
}

// Every Dynamic Sensation in turn, each with a simulated mass tethered to the handle.
inline EffectParams mixed_dynamic(int i) {
    constexpr EffectType kTypes[] = {EffectType::dynamic_recoil,       EffectType::dynamic_impact,
                                     EffectType::dynamic_liquid,       EffectType::dynamic_inertia,
                                     EffectType::dynamic_center_drift, EffectType::dynamic_control_law,
                                     EffectType::dynamic_sling,        EffectType::dynamic_paddle};
    EffectParams p;
    p.type = kTypes[i % 8];
    p.duration_us = kInfiniteUs;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    DynamicBlock& d = p.dynamic;
    d.blast_direction = d.impact_direction = d.initial_velocity_direction = (i * 4100) % 36000;
    d.blast_intensity = d.impact_intensity = d.initial_velocity = 3000;
    d.dynamic_mass = d.density = d.inertia = d.ball_mass = 2000;
    d.blast_resonance = d.elasticity = d.settle = d.stiffness = d.string_compliance = d.paddle_compliance = 3000;
    d.blast_decay = d.collision_absorption = d.viscosity = d.paddle_damping = 1000;
    d.play = 200;
    d.drift_resistance = 2000;
    d.string_length = 1500;
    d.ball_damping = 500;
    for (ControlLawBlock& c : d.control_law) c = {2000, 3000, 2500, 800, 1000, 0, 0, 100, 200, 0};
    d.interim_reporting = true;
    return p;
}

// Effect i of the mix: of every 8, 3 waves, 3 conditions and 2 dynamics (64 effects: 24
// waves, 24 conditions, 16 dynamics). Each class counts its own members, so the first 15
// waves, 10 conditions and 8 dynamics are every type of their class once (64 effects hold
// every type: 15 wave, 10 condition and 8 dynamic types). Picking a class's type by the
// mix's index i instead would repeat a few types (the dynamics at i % 8 = 6, 7 would all be
// slings and paddles).
inline EffectParams busy_mix_effect(int i) {
    const int kind = i % 8;
    const int round = i / 8;
    if (kind < 3) return mixed_wave(3 * round + kind);
    if (kind < 6) return mixed_condition(3 * round + kind - 3);
    return mixed_dynamic(2 * round + kind - 6);
}

struct BusyMixCounts {
    int waves = 0;
    int conditions = 0;
    int dynamics = 0;
};

inline BusyMixCounts busy_mix_counts(int effects) {
    BusyMixCounts c;
    for (int i = 0; i < effects; ++i) {
        const int kind = i % 8;
        ++(kind < 3 ? c.waves : kind < 6 ? c.conditions : c.dynamics);
    }
    return c;
}

// The outcome of loading the mix: ok, or the index and error of the first effect the
// engine refused to create or start.
struct BusyMixResult {
    Error error{};
    int failed_index = -1;
    [[nodiscard]] bool ok() const noexcept { return error.ok(); }
};

// Creates and starts effect i of the mix on a 2-axis (x, y) engine.
inline BusyMixResult load_busy_mix_effect(Engine& engine, int i) {
    const EffectParams p = busy_mix_effect(i);
    const auto data = p.type == EffectType::force_profile ? std::span<const int16_t>(kBusyMixSamples)
                                                          : std::span<const int16_t>();
    const CreateResult r = engine.create(p, data);
    if (!r.error.ok()) return {r.error, i};
    if (const Error e = engine.start(r.id)) return {e, i};
    return {};
}

// Creates and starts effects 0..effects-1 of the mix on a 2-axis (x, y) engine.
inline BusyMixResult load_busy_mix(Engine& engine, int effects) {
    for (int i = 0; i < effects; ++i) {
        if (BusyMixResult r = load_busy_mix_effect(engine, i); !r.ok()) return r;
    }
    return {};
}

// The handle of tick n at 1 kHz: a circle of 5000 units at 1 Hz with a 40 Hz wiggle,
// quantized to 4096 counts like the joystick's sensor.
inline void move_handle(TickInput& in, int64_t n) {
    constexpr double kTwoPi = 2 * 3.141592653589793;
    const double t = static_cast<double>(n) * 1e-3;
    const double step = 20000.0 / 4096.0;
    const double x = 5000 * std::cos(kTwoPi * t) + 200 * std::sin(kTwoPi * 40 * t);
    const double y = 5000 * std::sin(kTwoPi * t);
    in.position[0] = static_cast<float>(std::round(x / step) * step);
    in.position[1] = static_cast<float>(std::round(y / step) * step);
}

}  // namespace feel::bench
