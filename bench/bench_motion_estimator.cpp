// The velocity and acceleration estimator alone (src/engine/motion_estimator.hpp), 2 axes
// at 1 kHz, on the motions of bench_tick.cpp: the peer mix's slow circle, the busy mix's
// circle with a 40 Hz wiggle (the hardest: the window shrinks every few ticks), a slow
// quantized ramp and a handle at rest.
#include <benchmark/benchmark.h>

#include "busy_mix.hpp"
#include "motion_estimator.hpp"
#include "peer_mix.hpp"

namespace {

using namespace feel;
using namespace feel::bench;

enum Motion : int64_t { slow_circle, wiggle_circle, slow_ramp, at_rest };

void BM_MotionEstimator(benchmark::State& state) {
    const auto motion = static_cast<Motion>(state.range(0));
    const bool with_acceleration = state.range(1) != 0;  // the tick fits it only when an inertia plays
    detail::MotionEstimator estimator;
    estimator.configure(20000.0f / 4096.0f);
    TickInput in;
    int64_t n = 0;
    for (auto _ : state) {
        ++n;
        switch (motion) {
            case slow_circle: move_handle_in_slow_circle(in, n); break;
            case wiggle_circle: move_handle(in, n); break;
            case slow_ramp:
                in.position[0] = static_cast<float>(std::round((-9000.0 + 2.0 * static_cast<double>(n % 9000)) / 4.8828125) * 4.8828125);
                in.position[1] = 0;
                break;
            case at_rest: break;
        }
        in.t_us = n * 1000;
        estimator.update(in.t_us, in.position, 2, with_acceleration);
        benchmark::DoNotOptimize(estimator.velocity(0));
        benchmark::DoNotOptimize(estimator.velocity(1));
    }
}
BENCHMARK(BM_MotionEstimator)
    ->ArgNames({"motion", "acceleration"})
    ->ArgsProduct({{0, 1, 2, 3}, {1, 0}})
    ->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
