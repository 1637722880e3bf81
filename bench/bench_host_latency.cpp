// Latency from a host command to the first force change (issue 6, §8 "Latency").
//
// The primer's budget (§2.2, rule i): "the lag time between the onset of a visual event
// and the onset of an associated force event should be less than 25 milliseconds". A game
// triggers the force with a host call; what matters is how long until the motors push.
// This program measures it end to end, the way a game would see it, and splits off the
// device's own share.
//
// What is timed. A constant force on x (magnitude 5000, endless) is created once. Each
// trial waits until the motors are at rest, then
//   * start:          Effect::start()                       0 -> 5000
//   * set_parameters: Effect::set_parameters(magnitude)     2000 <-> 6000, effect playing
// and measures, on the host's std::chrono::steady_clock, from just before the call to the
// arrival on the host of the first state report whose motor force (InputState::force, what
// the device's motors got in that tick) shows the change. The call itself returns when the
// device's answer (CommandStatus) arrives; that time is reported as "ack". The device sends
// state reports every tick: the benchmark sets the report rate to 1000 Hz
// (Device::set_report_rate) on a 1000 Hz device loop, so the report adds no waiting beyond
// the tick. A report that arrived before the call returned is seen when it returns: the
// figure is then an upper bound by the few microseconds between the host's I/O thread
// taking the report and the caller waking up.
//
// Clocks. Host and device run in one process here (the in-process transport, and a
// Peripheral serving a Unix socket and a TCP port on loopback inside the benchmark), so one
// steady clock times everything; no clock is compared across machines. The device's own
// share is measured at the runtime level, without protocol or transport: a DeviceRuntime
// whose host thread sends runtime::Command start, and reads the ack's t_us (the device
// tick that applied the command) and the t_us of the first state report showing the force
// (device time, exact to the tick), plus the host time from send to that report.
//
// Each trial begins at a random phase of the device's 1 ms tick (random_phase()), as a
// game's command would. The device loop is an ordinary thread unless the process may use SCHED_FIFO (it tries);
// the figures depend on the machine and its load. Run:
//   build/bench/bench_host_latency [TRIALS]     (default 200 per row)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/host/device.hpp"
#include "host_bench_support.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/runtime/device_runtime.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/transport/transport.hpp"

namespace {

using namespace feel;
using bench::Clock;
using bench::ms_since;
using bench::percentile;
using bench::require;

constexpr int32_t kReportRateHz = 1000;
constexpr double kBudgetMs = 25;
constexpr const char* kProfile = "iforce2";
constexpr auto kWaitLimit = std::chrono::milliseconds(2000);

// A trial starts right after a state report showed the motors at rest, that is right after
// a device tick: sent at once, every command would wait almost a whole period for the next
// tick, which no game does. A random pause of 0..1 ms (one loop period) first puts the
// command at a uniformly random phase of the device's loop, as a game's would be.
void random_phase() {
    static std::mt19937 rng(20240601);
    std::uniform_int_distribution<int> us(0, 999);
    std::this_thread::sleep_for(std::chrono::microseconds(us(rng)));
}



EffectParams constant_force(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = kInfiniteUs;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.constant.magnitude = magnitude;
    return p;
}


// ---------------------------------------------------------------------------------------
// Through the host API.

struct HostFigures {
    std::vector<double> start_ms, start_ack_ms, update_ms, update_ack_ms;
};

// Waits until a state report shows `done(force x)`; returns the time it was seen.
template <class Done>
Clock::time_point wait_force(host::Device& device, Done done) {
    const Clock::time_point limit = Clock::now() + kWaitLimit;
    for (;;) {
        if (done(device.input().force[0])) return Clock::now();
        if (Clock::now() > limit) throw std::runtime_error("the force did not change within 2 s");
        const host::Result<host::InputState> next = device.wait_input(std::chrono::milliseconds(100));
        if (!next && next.status().kind != host::ErrorKind::timeout) require(next.status(), "wait_input");
    }
}

void wait_full_strength(host::Device& device) {
    const Clock::time_point limit = Clock::now() + kWaitLimit;
    while (device.input().fade_level < 1.0f || device.input().reports_received == 0) {
        if (Clock::now() > limit) throw std::runtime_error("the device did not reach full strength (fade-in)");
        (void)device.wait_input(std::chrono::milliseconds(50));
    }
}

HostFigures measure_host(host::Device& device, int trials) {
    require(device.set_report_rate(kReportRateHz), "set_report_rate");
    wait_full_strength(device);
    HostFigures f;
    host::Result<host::Effect> made = device.create_effect(constant_force(5000));
    require(made.status(), "create_effect");
    host::Effect& effect = made.value();
    for (int i = 0; i < trials; ++i) {
        (void)wait_force(device, [](float x) { return std::fabs(x) < 1; });
        random_phase();
        const Clock::time_point t0 = Clock::now();
        require(effect.start(), "start");
        const Clock::time_point acked = Clock::now();
        const Clock::time_point seen = wait_force(device, [](float x) { return std::fabs(x) > 2500; });
        f.start_ms.push_back(ms_since(t0, seen));
        f.start_ack_ms.push_back(ms_since(t0, acked));
        require(effect.stop(), "stop");
    }
    EffectParams p = constant_force(2000);
    require(effect.set_parameters(p, effect_field::kTypeSpecific), "set_parameters");
    require(effect.start(), "start");
    for (int i = 0; i < trials; ++i) {
        const int32_t from = p.constant.magnitude;
        const int32_t to = from == 2000 ? 6000 : 2000;
        (void)wait_force(device, [from](float x) { return std::fabs(x - static_cast<float>(from)) < 100; });
        random_phase();
        p.constant.magnitude = to;
        const Clock::time_point t0 = Clock::now();
        require(effect.set_parameters(p, effect_field::kTypeSpecific), "set_parameters");
        const Clock::time_point acked = Clock::now();
        const Clock::time_point seen =
            wait_force(device, [to](float x) { return std::fabs(x - static_cast<float>(to)) < 100; });
        f.update_ms.push_back(ms_since(t0, seen));
        f.update_ack_ms.push_back(ms_since(t0, acked));
    }
    require(effect.stop(), "stop");
    return f;
}

// ---------------------------------------------------------------------------------------
// The device's share: the runtime alone.

struct RuntimeFigures {
    std::vector<double> host_ms;      // send -> the state report showing the force, host clock
    std::vector<double> device_us;    // ack t_us -> that report's t_us, device clock
};

RuntimeFigures measure_runtime(int trials) {
    using namespace feel::runtime;
    const sim::DeviceProfile& profile = *sim::find_device_profile(kProfile);
    RuntimeConfig config = runtime_config_for(profile);
    config.report_rate_hz = kReportRateHz;
    DeviceRuntime rt(config, std::make_unique<SimBackend>(profile, sim::Grip::firm,
                                                          sim::TargetMotion::parse("hold:0", 1e9, profile.axis_count)));
    rt.start();
    Report r;
    // Polls until `done(report)`; keeps the host link alive while it waits.
    auto poll_until = [&](auto done) {
        const Clock::time_point limit = Clock::now() + kWaitLimit;
        Clock::time_point last_keep_alive = Clock::now();
        for (;;) {
            while (rt.poll(r)) {
                if (done(r)) return Clock::now();
            }
            if (Clock::now() > limit) throw std::runtime_error("the runtime did not answer within 2 s");
            if (Clock::now() - last_keep_alive > std::chrono::milliseconds(100)) {
                (void)rt.keep_alive();
                last_keep_alive = Clock::now();
            }
            std::this_thread::sleep_for(std::chrono::microseconds(20));
        }
    };
    (void)poll_until([](const Report& x) { return x.kind == ReportKind::state && x.state.safety.fade_level >= 1.0f; });
    const std::optional<uint32_t> created = rt.create(constant_force(5000));
    if (!created) throw std::runtime_error("the command queue is full");
    EffectId id{};
    (void)poll_until([&](const Report& x) {
        if (x.kind != ReportKind::ack || x.ack.sequence != *created) return false;
        if (!x.ack.error.ok()) throw std::runtime_error("create: " + x.ack.error.message());
        id = x.ack.effect;
        return true;
    });
    RuntimeFigures f;
    for (int i = 0; i < trials; ++i) {
        (void)poll_until([](const Report& x) { return x.kind == ReportKind::state && std::fabs(x.state.force[0]) < 1; });
        random_phase();
        const Clock::time_point t0 = Clock::now();
        const std::optional<uint32_t> seq = rt.start_effect(id);
        if (!seq) throw std::runtime_error("the command queue is full");
        int64_t ack_t_us = -1;
        int64_t report_t_us = -1;
        const Clock::time_point seen = poll_until([&](const Report& x) {
            if (x.kind == ReportKind::ack && x.ack.sequence == *seq) ack_t_us = x.ack.t_us;
            if (x.kind == ReportKind::state && std::fabs(x.state.force[0]) > 2500) report_t_us = x.state.t_us;
            return ack_t_us >= 0 && report_t_us >= 0;
        });
        f.host_ms.push_back(ms_since(t0, seen));
        f.device_us.push_back(static_cast<double>(report_t_us - ack_t_us));
        (void)rt.stop_effect(id);
    }
    rt.stop();
    return f;
}

// ---------------------------------------------------------------------------------------

void row(const char* transport, const char* command, const std::vector<double>& ms,
         const std::vector<double>* ack_ms) {
    std::printf("%-14s %-15s %8.3f %8.3f %8.3f", transport, command, percentile(ms, 50), percentile(ms, 99),
                percentile(ms, 100));
    if (ack_ms != nullptr) std::printf("   %8.3f %8.3f", percentile(*ack_ms, 50), percentile(*ack_ms, 99));
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    int trials = 200;
    if (argc > 1) {
        trials = std::atoi(argv[1]);
        if (trials < 1 || trials > 100000) {
            std::fprintf(stderr, "bench_host_latency: TRIALS = %s is out of range (allowed 1..100000)\n", argv[1]);
            return 2;
        }
    }
    try {
        std::printf("feel host latency: host command -> first state report showing the new motor force\n"
                    "device %s (1000 Hz loop), state reports at %d Hz (set_report_rate), %d trials per row,\n"
                    "host std::chrono::steady_clock; times in ms (p50, p99, max; ack = the call's return)\n\n",
                    kProfile, kReportRateHz, trials);
        std::printf("%-14s %-15s %8s %8s %8s   %8s %8s\n", "transport", "command", "p50", "p99", "max", "ack p50",
                    "ack p99");

        const RuntimeFigures runtime = measure_runtime(trials);
        row("runtime only", "start", runtime.host_ms, nullptr);

        double worst_p99 = percentile(runtime.host_ms, 99);
        auto run_host = [&](const char* name, host::Device& device) {
            const HostFigures f = measure_host(device, trials);
            row(name, "start", f.start_ms, &f.start_ack_ms);
            row(name, "set_parameters", f.update_ms, &f.update_ack_ms);
            worst_p99 = std::max({worst_p99, percentile(f.start_ms, 99), percentile(f.update_ms, 99)});
        };

        bench::for_each_transport(kProfile, "feel-bench-latency", run_host);

        std::printf("\ndevice side (runtime ack t_us -> first report t_us showing the force, device clock): "
                    "p50 %.0f us, p99 %.0f us, max %.0f us\n",
                    percentile(runtime.device_us, 50), percentile(runtime.device_us, 99),
                    percentile(runtime.device_us, 100));
        std::printf("budget: the primer's %.0f ms (§2.2 i); worst p99 above %.3f ms: %s\n", kBudgetMs, worst_p99,
                    worst_p99 < kBudgetMs ? "within budget" : "OVER BUDGET");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_host_latency: %s\n", e.what());
        return 1;
    }
    return 0;
}
