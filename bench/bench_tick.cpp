// The engine tick with 64 concurrent mixed waves on 2 axes: the cost of one pass of the
// device's 1 kHz local loop (§2.2), which must stay far below the 1000 µs period.
#include <benchmark/benchmark.h>

#include <array>

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
