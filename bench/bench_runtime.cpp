// One tick of the assembled device runtime (issue 5, §11 "tick cost"): the whole pass of
// the local processor, not just the engine. Commands drained, the simulated joystick's
// sensors read, reflexes, the engine with every effect slot holding the busy mix (waves,
// conditions, dynamics), the safety monitor, the motors (the handle's physics, stepped a
// tick), IDF on the reported position, the dynamics' reports forwarded and a state report
// posted every tick (1 kHz reports, the most the runtime sends). The host drains the
// report queue and sends a keep-alive every tenth tick, inside the timed loop.
//
// Arg: 1 with IDF filtering both classes, 0 with IDF off (the filter still runs its model).
#include <benchmark/benchmark.h>

#include <memory>
#include <span>

#include "busy_mix.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"

namespace {

using namespace feel;
using namespace feel::runtime;

void BM_RuntimePipelineTick(benchmark::State& state) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    RuntimeConfig config = runtime_config_for(joystick);
    config.report_rate_hz = 1000;
    config.safety.host_timeout_us = kInfiniteUs;
    const bool idf = state.range(0) != 0;
    config.idf.settings = {.periodic = idf, .impulse = idf};
    RuntimePipeline pipeline(config, std::make_unique<SimBackend>(joystick, sim::Grip::firm,
                                                                  sim::TargetMotion::parse("circle:5000:1", 1e6, 2)));
    HostLink host(pipeline.commands(), pipeline.reports());
    int64_t n = 0;
    Report report;
    // Every slot of the joystick holds an effect of the mix, created and started through
    // the command queue.
    const int effects = config.engine.max_effects;
    for (int i = 0; i < effects; ++i) {
        const EffectParams p = bench::busy_mix_effect(i);
        const auto data = p.type == EffectType::force_profile ? std::span<const int16_t>(bench::kBusyMixSamples)
                                                              : std::span<const int16_t>();
        (void)host.create(p, data);
        pipeline.tick(n++);
        EffectId id{};
        while (host.poll(report)) {
            if (report.kind == ReportKind::ack && report.ack.command == CommandKind::create) id = report.ack.effect;
        }
        if (!id.valid() || !host.start_effect(id)) {
            state.SkipWithError("could not load the mix");
            return;
        }
    }
    for (int i = 0; i < 600; ++i) {  // past the safety fade-in: full forces from here on
        pipeline.tick(n++);
        while (host.poll(report)) benchmark::DoNotOptimize(report);
    }
    for (auto _ : state) {
        if (n % 10 == 0) (void)host.keep_alive();
        pipeline.tick(n++);
        while (host.poll(report)) benchmark::DoNotOptimize(report);
    }
    const RuntimeCounters c = pipeline.counters();
    state.counters["effects"] = effects;
    state.counters["playing"] = pipeline.last_output().playing_effects;
    state.counters["dropped"] = static_cast<double>(c.dropped_state_reports + c.dropped_dynamic_reports);
}
BENCHMARK(BM_RuntimePipelineTick)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
