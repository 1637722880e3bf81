// The cost of a friction condition per effect per tick (issue 14's budget: 30 ns).
//
// The engine ticks with N friction effects on x and y (§8.2's Friction(F), one block per
// axis) while the handle moves (the quantized circle with a wiggle of the mixed benchmark),
// so every block advances its model on every tick. N = 0 is the same engine and motion
// with no effect: the velocity estimator and the tick's fixed work. The cost of one
// friction effect is (time(N) - time(0)) / N; the README reports it.
#include <benchmark/benchmark.h>

#include "busy_mix.hpp"
#include "feel/engine.hpp"

namespace {

using namespace feel;
using namespace feel::bench;

EffectParams friction_on_xy(int32_t coefficient) {
    EffectParams p;
    p.type = EffectType::friction;
    p.duration_us = kInfiniteUs;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    for (int i = 0; i < 2; ++i) {
        p.conditions[i].pos_coefficient = coefficient;
        p.conditions[i].neg_coefficient = coefficient;
    }
    return p;
}

void BM_TickFrictionEffects(benchmark::State& state) {
    const int effects = static_cast<int>(state.range(0));
    EngineConfig config;
    config.device_damping = 0.5f * 0.05f / 4.45f;  // the joystick's: the passivity-bound stiffness applies
    config.device_mass = 0.15f * 0.05f / 4.45f;    // the joystick's: the stop guard runs
    Engine engine(config);
    for (int i = 0; i < effects; ++i) {
        const CreateResult r = engine.create(friction_on_xy(1000 + 250 * i));
        if (!r.error.ok() || !engine.start(r.id).ok()) {
            state.SkipWithError("could not create the frictions");
            return;
        }
    }
    TickInput in;
    TickOutput out;
    int64_t n = 0;
    for (auto _ : state) {
        ++n;
        in.t_us = n * 1000;
        move_handle(in, n);
        engine.tick(in, out);
        benchmark::DoNotOptimize(out);
    }
    state.counters["effects"] = effects;
}
BENCHMARK(BM_TickFrictionEffects)->Arg(0)->Arg(32)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
