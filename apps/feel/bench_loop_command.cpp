// feel bench loop: how steadily the device's local control loop (§2.2) keeps its rate.
//
// The loop does real work: the simulated joystick with every effect slot of its profile
// filled by the busy mix of bench/busy_mix.hpp (waves, conditions and dynamics), a firm
// hand moving the handle in a circle, and each tick the full pass of the device — sense,
// engine tick, drain the dynamics' reports, step the handle's physics. The RealtimeLoop
// runs it for --seconds and measures its period error, latency and work per tick; the
// last line of output is the one-line summary the README quotes:
//
//   p50=12.3us p99=45.6us p99.9=78.9us overruns=0 ticks=60000
//
// (percentiles of the period error, the overrun events, the ticks run). Figures are
// measured, not asserted: they depend on the machine and its load.
//
// --floor runs the very same loop (pacing, privileges, histograms) with an empty tick: what
// the machine itself allows. A virtual machine's wake-ups may come tens of µs late and, now
// and then, milliseconds late whatever the loop does; the device's figures mean something
// only next to that floor, taken on the same machine at the same time (docs/runtime.md).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "busy_mix.hpp"
#include "cli.hpp"
#include "feel/engine.hpp"
#include "feel/runtime/realtime_loop.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::cli {
namespace {

constexpr double kMinSeconds = 1;
constexpr double kMaxSeconds = 3600;
// The hand: a firm grip on a circle through the walls and barriers of the mix.
constexpr const char* kDeviceName = "joystick";
constexpr const char* kMotion = "circle:5000:1";

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string us(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1fus", v);
    return buf;
}

int32_t checked_rate(double rate_hz) {
    const bool whole = std::isfinite(rate_hz) && std::floor(rate_hz) == rate_hz;
    if (!whole || rate_hz < runtime::kMinLoopRateHz || rate_hz > runtime::kMaxLoopRateHz) {
        throw UsageError("--rate = " + number(rate_hz) + " Hz is out of range (allowed a whole number of Hz, " +
                         std::to_string(runtime::kMinLoopRateHz) + ".." +
                         std::to_string(runtime::kMaxLoopRateHz) + ")");
    }
    return static_cast<int32_t>(rate_hz);
}

double checked_seconds(double seconds) {
    if (!std::isfinite(seconds) || seconds < kMinSeconds || seconds > kMaxSeconds) {
        throw UsageError("--seconds = " + number(seconds) + " is out of range (allowed " + number(kMinSeconds) +
                         ".." + number(kMaxSeconds) + " s)");
    }
    return seconds;
}

int32_t checked_cpu(double cpu) {
    const bool whole = std::isfinite(cpu) && std::floor(cpu) == cpu;
    const long cpus = sysconf(_SC_NPROCESSORS_CONF);
    if (!whole || cpu < -1 || cpu >= static_cast<double>(cpus)) {
        throw UsageError("--cpu = " + number(cpu) + " is out of range (allowed -1 for any CPU, or a whole 0.." +
                         std::to_string(cpus - 1) + ", this machine's CPUs)");
    }
    return static_cast<int32_t>(cpu);
}

void print_stats(const runtime::RealtimeLoopStats& s, int32_t rate, int playing_effects, std::ostream& out) {
    out << "work per tick: p50=" << us(s.callback_p50_us) << " p99=" << us(s.callback_p99_us)
        << " p99.9=" << us(s.callback_p999_us) << " max=" << us(s.callback_max_us) << " of a "
        << us(1e6 / rate) << " period\n"
        << "latency after deadline: p50=" << us(s.latency_p50_us) << " p99=" << us(s.latency_p99_us)
        << " p99.9=" << us(s.latency_p999_us) << " max=" << us(s.latency_max_us) << '\n'
        << "page faults of the loop thread during the run: minor=" << s.minor_faults << " major=" << s.major_faults
        << '\n'
        << "period error: max=" << us(s.period_error_max_us) << ", missed ticks=" << s.missed_ticks
        << ", effects playing at the end=" << playing_effects << '\n'
        << "p50=" << us(s.period_error_p50_us) << " p99=" << us(s.period_error_p99_us)
        << " p99.9=" << us(s.period_error_p999_us) << " overruns=" << s.overruns << " ticks=" << s.ticks << '\n';
}

void run_floor(int32_t rate, double seconds, int64_t ticks, const runtime::RealtimeLoopOptions& options,
               std::ostream& out) {
    out << "feel bench loop --floor: the same loop with an empty tick at " << rate << " Hz for " << number(seconds)
        << " s (" << ticks << " ticks): the machine's own timing floor\n";
    runtime::RealtimeLoop loop;
    loop.start(options, [](int64_t, int64_t) {});
    out << loop.setup().describe() << '\n' << std::flush;
    loop.wait();
    print_stats(loop.stats(), rate, 0, out);
}

}  // namespace

void run_bench_loop(const BenchLoopArgs& args, std::ostream& out, std::ostream& /*err*/) {
    const int32_t rate = checked_rate(args.rate_hz);
    const double seconds = checked_seconds(args.seconds);
    const int64_t ticks = std::llround(seconds * rate);
    runtime::RealtimeLoopOptions options;
    options.rate_hz = rate;
    options.tick_limit = ticks;
    options.cpu = checked_cpu(args.cpu);
    if (args.floor) {
        run_floor(rate, seconds, ticks, options, out);
        return;
    }

    const sim::DeviceProfile* profile = sim::find_device_profile(kDeviceName);
    if (profile == nullptr) throw std::runtime_error(std::string("no built-in device \"") + kDeviceName + "\"");
    Engine engine(sim::engine_config_for(*profile));
    const int effects = engine.config().max_effects;
    const bench::BusyMixResult mix = bench::load_busy_mix(engine, effects);
    if (!mix.ok()) {
        throw std::runtime_error("the busy mix does not fit the " + std::string(kDeviceName) + ": effect " +
                                 std::to_string(mix.failed_index) + " (" +
                                 std::string(effect_type_name(bench::busy_mix_effect(mix.failed_index).type)) +
                                 "): " + mix.error.message());
    }
    const bench::BusyMixCounts counts = bench::busy_mix_counts(effects);
    sim::SimDevice device(*profile, sim::Grip::firm, sim::TargetMotion::parse(kMotion, seconds, profile->axis_count));

    out << "feel bench loop: the local control loop at " << rate << " Hz for " << number(seconds) << " s ("
        << ticks << " ticks)\n"
        << "load: " << kDeviceName << ", " << effects << " effects (" << counts.waves << " waves, "
        << counts.conditions << " conditions, " << counts.dynamics << " dynamics), firm hand on " << kMotion
        << "; each tick senses, renders, drains reports and steps the physics\n";

    // Everything the callback touches exists already: it allocates nothing (the runtime's
    // allocation test runs the same work under a counting allocator).
    int64_t previous_t_us = -1;
    TickOutput output;
    runtime::RealtimeLoop loop;
    loop.start(options, [&](int64_t, int64_t t_us) {
        TickInput in;
        in.t_us = t_us;
        device.sense(in);
        engine.tick(in, output);
        DynamicReport report;
        while (engine.pop_report(report)) {
        }
        if (previous_t_us >= 0) device.step(output.force, static_cast<double>(t_us - previous_t_us) * 1e-6);
        previous_t_us = t_us;
    });
    out << loop.setup().describe() << '\n' << std::flush;
    loop.wait();

    print_stats(loop.stats(), rate, output.playing_effects, out);
}

}  // namespace feel::cli
