// The cost of a friction condition per effect per tick (issue 14's budget: 30 ns).
//
// The engine ticks with N friction effects on x and y (§8.2's Friction(F), one block per
// axis) while the handle moves (the quantized circle with a wiggle of the mixed benchmark),
// so every block advances its model on every tick. N = 0 is the same engine and motion
// with no effect: the velocity estimator and the tick's fixed work. The cost of one
// friction effect is (time(N) - time(0)) / N; the README reports it.
#include <benchmark/benchmark.h>

#include "busy_mix.hpp"
#include "condition_mix.hpp"
#include "feel/engine.hpp"

namespace {

using namespace feel;
using namespace feel::bench;

void BM_TickFrictionEffects(benchmark::State& state) {
    const int effects = static_cast<int>(state.range(0));
    Engine engine(joystick_condition_config());  // the passivity-bound stiffness and the stop guard apply
    if (!load_conditions(engine, EffectType::friction, effects)) {
        state.SkipWithError("could not create the frictions");
        return;
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
