// The time a game's thread spends in a host call: the blocking calls against their
// non-blocking forms (CommandQueue, include/feel/host/command_queue.hpp).
//
// A game frame of 1 ms: each frame the game updates a spring (set_parameters, 2 reports),
// starts or stops a sine, sets the gain and streams a force sample, each timed alone with
// the steady clock around the call; every frame it polls the queue's outcomes (timed too).
// The blocking rows time the same calls on Effect and Device directly. Rows: in process,
// over a Unix socket and over TCP on loopback, the I-FORCE 2.0 profile at 1 kHz. Prints
// p50, p99 and max in µs; any refused command fails the run.
//
//   build/bench/feel_bench_queue_calls [frames]     (default 2000)
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "feel/host/command_queue.hpp"
#include "host_bench_support.hpp"

using namespace feel;
using bench::Clock;

namespace {

double us_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

EffectParams spring_x(int32_t k) {
    EffectParams p;
    p.type = EffectType::spring;
    p.duration_us = kInfiniteUs;
    p.conditions[0] = ConditionBlock{k, k, 0, 10000, 10000, 0};
    return p;
}

EffectParams sine_x() {
    EffectParams p;
    p.type = EffectType::sine;
    p.duration_us = kInfiniteUs;
    p.periodic.magnitude = 2000;
    p.periodic.period_us = 20'000;
    return p;
}

void row(const char* transport, const char* call, const std::vector<double>& us) {
    std::printf("| %s | %s | %.1f | %.1f | %.1f | %zu |\n", transport, call, bench::percentile(us, 50),
                bench::percentile(us, 99), bench::percentile(us, 100), us.size());
}

void measure(const char* transport, host::Device& device, int frames) {
    host::Result<host::Effect> spring = device.create_effect(spring_x(1000));
    host::Result<host::Effect> sine = device.create_effect(sine_x());
    bench::require(spring.status(), "create spring");
    bench::require(sine.status(), "create sine");
    bench::require(spring->start(kInfiniteIterations), "start spring");
    const int32_t axes = device.capabilities().axis_count;
    std::vector<int32_t> force(static_cast<std::size_t>(axes), 0);

    // Blocking: fewer frames (each call waits for the device).
    {
        std::vector<double> set, start_stop, gain;
        const int n = std::max(50, frames / 10);
        for (int i = 0; i < n; ++i) {
            auto t0 = Clock::now();
            bench::require(spring->set_parameters(spring_x(1000 + (i % 50) * 100), effect_field::kTypeSpecific),
                           "set_parameters");
            set.push_back(us_since(t0));
            t0 = Clock::now();
            bench::require(i % 2 ? sine->stop() : sine->start(kInfiniteIterations), "start/stop");
            start_stop.push_back(us_since(t0));
            t0 = Clock::now();
            bench::require(device.set_gain(9000 + (i % 2) * 1000), "set_gain");
            gain.push_back(us_since(t0));
        }
        row(transport, "blocking `Effect::set_parameters`", set);
        row(transport, "blocking `Effect::start` / `stop`", start_stop);
        row(transport, "blocking `Device::set_gain`", gain);
    }

    host::CommandQueue queue(device);
    std::vector<double> set, start_stop, gain, stream, poll;
    std::size_t failures = 0, outcomes = 0;
    std::string first_failure;
    auto next = Clock::now();
    for (int i = 0; i < frames; ++i) {
        next += std::chrono::milliseconds(1);
        auto t0 = Clock::now();
        bench::require(queue.set_parameters(*spring, spring_x(1000 + (i % 50) * 100), effect_field::kTypeSpecific).status(),
                       "queue set_parameters");
        set.push_back(us_since(t0));
        if (i % 10 == 0) {  // a start or stop every 10 frames
            t0 = Clock::now();
            bench::require((i % 20 ? queue.stop(*sine) : queue.start(*sine, kInfiniteIterations)).status(),
                           "queue start/stop");
            start_stop.push_back(us_since(t0));
        }
        t0 = Clock::now();
        bench::require(queue.set_gain(9000 + (i % 2) * 1000).status(), "queue set_gain");
        gain.push_back(us_since(t0));
        force[0] = (i % 200) * 10;
        t0 = Clock::now();
        bench::require(queue.stream_force(force).status(), "queue stream_force");
        stream.push_back(us_since(t0));
        t0 = Clock::now();
        outcomes += queue.poll([&](const host::Outcome& o) {
            if (!o.status.ok() && failures++ == 0) first_failure = o.status.message;
        });
        poll.push_back(us_since(t0));
        std::this_thread::sleep_until(next);
    }
    bench::require(queue.flush(std::chrono::milliseconds(10000)), "flush");
    outcomes += queue.poll([&](const host::Outcome& o) {
        if (!o.status.ok() && failures++ == 0) first_failure = o.status.message;
    });
    row(transport, "`CommandQueue::set_parameters`", set);
    row(transport, "`CommandQueue::start` / `stop`", start_stop);
    row(transport, "`CommandQueue::set_gain`", gain);
    row(transport, "`CommandQueue::stream_force`", stream);
    row(transport, "`CommandQueue::poll`", poll);
    if (failures) {
        std::fprintf(stderr, "%zu of %zu outcomes failed, the first: %s\n", failures, outcomes, first_failure.c_str());
        std::exit(1);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::atoi(argv[1]) : 2000;
    if (frames < 10 || frames > 1'000'000) {
        std::fprintf(stderr, "frames = %d is out of range (allowed 10..1000000)\n", frames);
        return 2;
    }
    std::printf("Time in the call, µs (steady clock), %d frames of 1 ms\n\n", frames);
    std::printf("| transport | call | p50 | p99 | max | calls |\n|---|---|---|---|---|---|\n");
    try {
        bench::for_each_transport("iforce2", "feel-bench-queue",
                                  [&](const char* transport, host::Device& device) { measure(transport, device, frames); });
    } catch (const std::exception& e) {
        std::fprintf(stderr, "feel_bench_queue_calls: %s\n", e.what());
        return 1;
    }
    return 0;
}
