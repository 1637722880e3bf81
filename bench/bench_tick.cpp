// The engine tick with 64 concurrent mixed effects on 2 axes: the cost of one pass of the
// device's 1 kHz local loop (§2.2), which must stay far below the 1000 µs period.
//
// The handle moves (a circle with a wiggle, quantized like the joystick's sensor), so the
// velocity estimator, every condition and every dynamic do their real work each tick.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>

#include "feel/engine.hpp"

namespace {

using namespace feel;

// Every wave family in turn: constant, vector force, smart pop, five periodics with
// envelopes, five sweeps, force profile, ramp.
EffectParams mixed_wave(int i) {
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
EffectParams mixed_condition(int i) {
    constexpr EffectType kTypes[] = {EffectType::spring,       EffectType::damper,        EffectType::inertia,
                                     EffectType::friction,     EffectType::angle_spring,  EffectType::axis_barrier,
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
EffectParams mixed_dynamic(int i) {
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

// A circle of 5000 units at 1 Hz with a 40 Hz wiggle, quantized to 4096 counts.
void move_handle(TickInput& in, int64_t n) {
    const double t = static_cast<double>(n) * 1e-3;
    const double step = 20000.0 / 4096.0;
    const double x = 5000 * std::cos(2 * 3.141592653589793 * t) + 200 * std::sin(2 * 3.141592653589793 * 40 * t);
    const double y = 5000 * std::sin(2 * 3.141592653589793 * t);
    in.position[0] = static_cast<float>(std::round(x / step) * step);
    in.position[1] = static_cast<float>(std::round(y / step) * step);
}

void BM_TickMixedEffects(benchmark::State& state) {
    const int effects = static_cast<int>(state.range(0));
    Engine engine(EngineConfig{});
    const std::array<int16_t, 8> samples = {100, -100, 200, -200, 300, -300, 400, -400};
    for (int i = 0; i < effects; ++i) {
        // Waves, conditions and dynamics in turn: 3 of every 8 are waves, 3 conditions, 2
        // dynamics (64 effects: 24 waves, 24 conditions, 16 dynamics).
        const int kind = i % 8;
        const EffectParams p = kind < 3 ? mixed_wave(i) : kind < 6 ? mixed_condition(i) : mixed_dynamic(i);
        const auto data = p.type == EffectType::force_profile ? std::span<const int16_t>(samples)
                                                              : std::span<const int16_t>();
        const CreateResult r = engine.create(p, data);
        if (!r.error.ok() || !engine.start(r.id).ok()) {
            state.SkipWithError("could not create the mix");
            return;
        }
    }
    TickInput in;
    TickOutput out;
    int64_t n = 0;
    DynamicReport report;
    for (auto _ : state) {
        ++n;
        in.t_us = n * 1000;
        move_handle(in, n);
        engine.tick(in, out);
        while (engine.pop_report(report)) benchmark::DoNotOptimize(report);  // the host drains
        benchmark::DoNotOptimize(out);
    }
    state.counters["effects"] = effects;
}
BENCHMARK(BM_TickMixedEffects)->Arg(1)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

void BM_TickMixedWaves(benchmark::State& state) {
    const int effects = static_cast<int>(state.range(0));
    Engine engine(EngineConfig{});
    const std::array<int16_t, 8> samples = {100, -100, 200, -200, 300, -300, 400, -400};
    for (int i = 0; i < effects; ++i) {
        const EffectParams p = mixed_wave(i);
        const auto data = p.type == EffectType::force_profile ? std::span<const int16_t>(samples)
                                                              : std::span<const int16_t>();
        const CreateResult r = engine.create(p, data);
        if (!r.error.ok() || !engine.start(r.id).ok()) {
            state.SkipWithError("could not create the mix");
            return;
        }
    }
    TickInput in;
    TickOutput out;
    for (auto _ : state) {
        in.t_us += 1000;
        engine.tick(in, out);
        benchmark::DoNotOptimize(out);
    }
    state.counters["effects"] = effects;
}
BENCHMARK(BM_TickMixedWaves)->Arg(1)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
