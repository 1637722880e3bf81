// Nothing allocates while the loop runs: a hooked global allocator counts every allocation
// of the process while the RealtimeLoop ticks a busy mix (waves, conditions and dynamics in
// every slot of the simulated joystick, held by a hand moving in a circle), takes commands
// from an SPSC queue and posts reports to another that this thread drains at the same
// time. The count must be zero.
//
// The window of counting opens only once the loop is running (its start-up allocates: the
// thread itself) and closes before it is stopped; during the window this thread does
// nothing but sleep, read a clock and pop reports, so anything counted is the loop's or
// the queues'.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <thread>

#include "../../bench/busy_mix.hpp"
#include "feel/engine.hpp"
#include "feel/runtime/realtime_loop.hpp"
#include "feel/runtime/spsc_queue.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/sim_device.hpp"
#include "support/counting_allocator.hpp"

namespace feel::runtime {
namespace {

TEST(RealtimeLoopAllocation, TheCounterSeesAllocationsOfAnyThread) {
    counting = true;
    std::thread other([] {
        auto* probe = new int(7);
        delete probe;
    });
    other.join();
    counting = false;
    EXPECT_GE(allocations.exchange(0), 2);  // the thread's state and the probe
}

struct Command {
    int32_t gain;  // device gain to set, 0..10000
};

struct Report {
    int64_t t_us;
    float force[2];
    int32_t playing;
};

TEST(RealtimeLoopAllocation, ABusyLoopWithQueuesNeverAllocates) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    Engine engine(sim::engine_config_for(joystick));
    // The whole joystick: every effect slot of its profile holds an effect of the mix.
    const int effects = engine.config().max_effects;
    const bench::BusyMixResult mix = bench::load_busy_mix(engine, effects);
    ASSERT_TRUE(mix.ok()) << "effect " << mix.failed_index << ": " << mix.error.message();
    sim::SimDevice device(joystick, sim::Grip::firm, sim::TargetMotion::parse("circle:5000:1", 1, 2));

    SpscQueue<Command> commands(1024);
    SpscQueue<Report> reports(256);
    for (int i = 0; i < 1000; ++i) ASSERT_TRUE(commands.try_push(Command{5000 + 5 * i}));

    std::atomic<int64_t> commands_applied{0};
    std::atomic<int64_t> reports_dropped{0};
    std::atomic<int64_t> dynamic_reports{0};
    int64_t previous_t_us = -1;
    TickOutput out;

    RealtimeLoopOptions options;  // 1 kHz, until stopped
    options.lock_memory = false;
    RealtimeLoop loop;
    loop.start(options, [&](int64_t, int64_t t_us) {
        Command c{};
        if (commands.try_pop(c) && engine.set_gain(c.gain).ok()) commands_applied.fetch_add(1, std::memory_order_relaxed);
        TickInput in;
        in.t_us = t_us;
        device.sense(in);
        engine.tick(in, out);
        DynamicReport dynamic;
        while (engine.pop_report(dynamic)) dynamic_reports.fetch_add(1, std::memory_order_relaxed);
        if (previous_t_us >= 0) device.step(out.force, static_cast<double>(t_us - previous_t_us) * 1e-6);
        previous_t_us = t_us;
        if (!reports.try_push(Report{t_us, {out.force[0], out.force[1]}, out.playing_effects})) {
            reports_dropped.fetch_add(1, std::memory_order_relaxed);
        }
    });

    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (loop.stats().ticks < 20 && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const int64_t ticks_before = loop.stats().ticks;

    int64_t reports_received = 0;
    Report report{};
    counting = true;
    const auto window_end = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
    while (std::chrono::steady_clock::now() < window_end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        while (reports.try_pop(report)) ++reports_received;
    }
    counting = false;
    const int64_t ticks_counted = loop.stats().ticks - ticks_before;
    loop.stop();

    EXPECT_EQ(allocations.load(), 0) << "over " << ticks_counted << " ticks";
    ASSERT_GE(ticks_before, 20);
    EXPECT_GT(ticks_counted, 100);  // the window saw real work (300 ms at 1 kHz)
    EXPECT_GT(reports_received, 100);
    EXPECT_GT(commands_applied.load(), 100);
    EXPECT_GT(dynamic_reports.load(), 0);
    // Waves and conditions play forever; some dynamics (a recoil, an impact, a paddle
    // ball) end by themselves with a final report.
    const bench::BusyMixCounts counts = bench::busy_mix_counts(effects);
    EXPECT_GE(out.playing_effects, counts.waves + counts.conditions);
    EXPECT_EQ(device.nonfinite_forces(), 0);
    EXPECT_EQ(device.rejected_steps(), 0);
}

}  // namespace
}  // namespace feel::runtime
