// The engine tick with 64 concurrent mixed effects on 2 axes: the cost of one pass of the
// device's 1 kHz local loop (§2.2), which must stay far below the 1000 µs period.
//
// The handle moves (a circle with a wiggle, quantized like the joystick's sensor), so the
// velocity estimator, every condition and every dynamic do their real work each tick.
#include <benchmark/benchmark.h>

#include <vector>

#include "busy_mix.hpp"
#include "feel/engine.hpp"
#include "peer_mix.hpp"

namespace {

using namespace feel;
using namespace feel::bench;

void BM_TickMixedEffects(benchmark::State& state) {
    const int effects = static_cast<int>(state.range(0));
    Engine engine(EngineConfig{});
    // Waves, conditions and dynamics in turn: 3 of every 8 are waves, 3 conditions, 2
    // dynamics (64 effects: 24 waves, 24 conditions, 16 dynamics).
    if (!load_busy_mix(engine, effects).ok()) {
        state.SkipWithError("could not create the mix");
        return;
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

// The 64 effects of every type with the handle's inputs worked out before the timed loop
// (BM_TickMixedEffects times move_handle's sin, cos and round in double too, about 0.1 µs),
// moving as there, or held still where that motion starts. The motion repeats every 1000
// ticks (1 s: the circle's period, forty of the wiggle's), so a table of one second of it
// serves every tick; time goes on increasing.
void BM_TickBusyMix(benchmark::State& state) {
    const bool moving = state.range(0) != 0;
    constexpr int kEffects = 64;
    constexpr int kPeriodTicks = 1000;
    Engine engine(EngineConfig{});
    if (!load_busy_mix(engine, kEffects).ok()) {
        state.SkipWithError("could not create the mix");
        return;
    }
    std::vector<TickInput> motion(kPeriodTicks);
    for (int k = 0; k < kPeriodTicks; ++k) move_handle(motion[static_cast<size_t>(k)], moving ? k : 0);
    TickOutput out;
    int64_t n = 0;
    DynamicReport report;
    for (auto _ : state) {
        ++n;
        TickInput& in = motion[static_cast<size_t>(n % kPeriodTicks)];
        in.t_us = n * 1000;
        engine.tick(in, out);
        while (engine.pop_report(report)) benchmark::DoNotOptimize(report);  // the host drains
        benchmark::DoNotOptimize(out);
    }
    state.counters["effects"] = kEffects;
}
BENCHMARK(BM_TickBusyMix)->ArgName("moving")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

void BM_TickMixedWaves(benchmark::State& state) {
    const int effects = static_cast<int>(state.range(0));
    Engine engine(EngineConfig{});
    for (int i = 0; i < effects; ++i) {
        const EffectParams p = mixed_wave(i);
        const auto data = p.type == EffectType::force_profile ? std::span<const int16_t>(kBusyMixSamples)
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

// Issue 14's 40-effect mix (peer_mix.hpp: 10 periodics with envelopes, 10 springs, 10
// dampers, 5 frictions, 3 ramps, 2 constants on 2 axes) with the handle in a slow circle,
// and the same mix with the handle at rest.
void BM_TickPeerMix(benchmark::State& state) {
    const bool moving = state.range(0) != 0;
    Engine engine(EngineConfig{});
    if (!load_peer_mix(engine)) {
        state.SkipWithError("could not create the mix");
        return;
    }
    TickInput in;
    TickOutput out;
    int64_t n = 0;
    move_handle_in_slow_circle(in, 0);
    for (auto _ : state) {
        ++n;
        if (moving) {
            move_handle_in_slow_circle(in, n);
        } else {
            in.t_us = n * 1000;
        }
        engine.tick(in, out);
        benchmark::DoNotOptimize(out);
    }
    state.counters["effects"] = kPeerMixEffects;
}
BENCHMARK(BM_TickPeerMix)->ArgName("moving")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
