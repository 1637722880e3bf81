// The fixed-rate loop: the ticks and times it hands the callback, the skip-don't-burst
// overrun policy, stopping (from outside, from the callback, by a tick limit, by an
// exception), option checks, and whether it reports truthfully the scheduling it got.
//
// Timing is measured, never asserted: the machine running the tests may be loaded, so a
// test never expects a tick to be on time. The assertions hold however late the ticks are
// (every accounting identity allows skipped ticks), except lower bounds that absolute
// deadlines and sleeps guarantee: the loop is never early.
#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "feel/runtime/realtime_loop.hpp"
#include "support/sanitizers.hpp"

namespace feel::runtime {
namespace {

using Clock = std::chrono::steady_clock;

// The callback records into memory sized in advance: it must not allocate.
struct TickLog {
    explicit TickLog(std::size_t capacity) : ticks(capacity), times(capacity) {}
    void add(int64_t tick, int64_t t_us) {
        const int64_t i = count.load(std::memory_order_relaxed);
        if (i < static_cast<int64_t>(ticks.size())) {
            ticks[static_cast<std::size_t>(i)] = tick;
            times[static_cast<std::size_t>(i)] = t_us;
        }
        count.store(i + 1, std::memory_order_release);
    }
    std::vector<int64_t> ticks;
    std::vector<int64_t> times;
    std::atomic<int64_t> count{0};
};

RealtimeLoopOptions quiet_options(int32_t rate_hz, int64_t tick_limit) {
    RealtimeLoopOptions o;
    o.rate_hz = rate_hz;
    o.tick_limit = tick_limit;
    o.lock_memory = false;  // the tests that need it ask for it
    return o;
}

// Ticks strictly increase from the first, every t_us is round(tick · 1e6 / rate), and run
// plus skipped ticks account for every tick up to the limit.
void expect_consistent(const TickLog& log, const RealtimeLoopStats& stats, int32_t rate_hz, int64_t limit) {
    const int64_t n = log.count.load();
    ASSERT_LE(n, static_cast<int64_t>(log.ticks.size()));
    EXPECT_EQ(n, stats.ticks);
    EXPECT_EQ(stats.ticks + stats.missed_ticks, limit);
    EXPECT_EQ(stats.missed_ticks == 0, stats.overruns == 0);
    EXPECT_LE(stats.overruns, stats.missed_ticks);
    for (int64_t i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (i > 0) {
            ASSERT_GT(log.ticks[k], log.ticks[k - 1]) << "at call " << i;
        }
        const double exact = static_cast<double>(log.ticks[k]) * 1e6 / rate_hz;
        ASSERT_EQ(log.times[k], std::llround(exact)) << "tick " << log.ticks[k];
    }
    if (n > 0) {
        EXPECT_EQ(stats.last_tick, log.ticks[static_cast<std::size_t>(n - 1)]);
    }
    EXPECT_LT(stats.last_tick, limit);
}

TEST(RealtimeLoop, RunsItsTicksWithTimesFromTheTickCount) {
    constexpr int64_t kTicks = 200;  // 0.2 s at 1 kHz
    TickLog log(kTicks);
    RealtimeLoop loop;
    const auto before = Clock::now();
    loop.start(quiet_options(1000, kTicks), [&](int64_t tick, int64_t t_us) { log.add(tick, t_us); });
    EXPECT_TRUE(loop.running());
    loop.wait();
    const auto elapsed = Clock::now() - before;
    EXPECT_FALSE(loop.running());

    const RealtimeLoopStats stats = loop.stats();
    EXPECT_EQ(stats.rate_hz, 1000);
    expect_consistent(log, stats, 1000, kTicks);
    if (stats.overruns == 0) {
        EXPECT_EQ(log.ticks.front(), 0);
        EXPECT_EQ(log.times[kTicks - 1], 199'000);
    }
    // Tick 0 is due a period after start(), tick 199 199 periods later, and no deadline is
    // ever taken early: the run cannot take less than 200 ms.
    EXPECT_GE(elapsed, std::chrono::milliseconds(200));
    // The histograms saw every tick; their order is a property of quantiles.
    EXPECT_LE(stats.period_error_p50_us, stats.period_error_p99_us);
    EXPECT_LE(stats.period_error_p99_us, stats.period_error_p999_us);
    EXPECT_LE(stats.period_error_p999_us, stats.period_error_max_us);
    EXPECT_LE(stats.latency_p50_us, stats.latency_max_us);
    EXPECT_GE(stats.latency_p50_us, 0.0);
}

TEST(RealtimeLoop, RoundsTimesToTheMicrosecondWhenThePeriodIsNotWhole) {
    constexpr int64_t kTicks = 300;  // 0.1 s at 3 kHz, period 333.3 µs
    TickLog log(kTicks);
    RealtimeLoop loop;
    loop.start(quiet_options(3000, kTicks), [&](int64_t tick, int64_t t_us) { log.add(tick, t_us); });
    loop.wait();
    expect_consistent(log, loop.stats(), 3000, kTicks);
}

TEST(RealtimeLoop, TickTimeIsExactForHugeTickCounts) {
    // round(n · 1e6 / rate) in 128-bit integers, where n · 1e6 does not fit 64 bits: the
    // true time where it fits in int64, INT64_MAX (saturated, never wrapped) where not.
    __extension__ using Wide = unsigned __int128;
    constexpr int64_t kMax = std::numeric_limits<int64_t>::max();
    for (const int32_t rate : {1, 100, 999, 1000, 3000, 7919, 20000}) {
        // The last tick whose time fits: floor((INT64_MAX + 1/2) · rate / 1e6), and the next.
        const Wide last_fitting = ((static_cast<Wide>(kMax) * 2 + 1) * static_cast<Wide>(rate)) / 2'000'000u;
        const auto fits = static_cast<int64_t>(std::min<Wide>(last_fitting, static_cast<Wide>(kMax)));
        for (const int64_t n : {int64_t{0}, int64_t{1}, int64_t{2}, int64_t{12345}, int64_t{1} << 40,
                                int64_t{9'000'000'000'000}, int64_t{9'000'000'000'000'000}, fits - 1, fits,
                                fits == kMax ? kMax : fits + 1, kMax}) {
            const Wide exact = (static_cast<Wide>(n) * 1'000'000u + static_cast<Wide>(rate / 2)) / static_cast<Wide>(rate);
            const int64_t expected = exact > static_cast<Wide>(kMax) ? kMax : static_cast<int64_t>(exact);
            EXPECT_EQ(expected, loop_tick_time_us(n, rate)) << "tick " << n << " at " << rate << " Hz";
        }
    }
}

TEST(RealtimeLoop, StopJoinsTheThreadAndNoTickFollows) {
    std::atomic<int64_t> calls{0};
    RealtimeLoop loop;
    loop.start(quiet_options(1000, 0), [&](int64_t, int64_t) { calls.fetch_add(1); });
    const auto give_up = Clock::now() + std::chrono::seconds(5);
    while (calls.load() < 20 && Clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ASSERT_GE(calls.load(), 20);
    loop.stop();
    EXPECT_FALSE(loop.running());
    const int64_t after_stop = calls.load();
    EXPECT_EQ(after_stop, loop.stats().ticks);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(calls.load(), after_stop) << "the callback ran after stop() returned";
    loop.stop();  // harmless when stopped
}

TEST(RealtimeLoop, TheDestructorStopsARunningLoop) {
    std::atomic<int64_t> calls{0};
    {
        RealtimeLoop loop;
        loop.start(quiet_options(1000, 0), [&](int64_t, int64_t) { calls.fetch_add(1); });
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const int64_t after = calls.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(calls.load(), after);
}

TEST(RealtimeLoop, TheCallbackCanEndTheLoop) {
    TickLog log(64);
    RealtimeLoop loop;
    loop.start(quiet_options(2000, 0), [&](int64_t tick, int64_t t_us) {
        log.add(tick, t_us);
        if (tick >= 10) loop.request_stop();
    });
    loop.wait();
    const int64_t n = log.count.load();
    ASSERT_GT(n, 0);
    // The loop ended right after the first tick at or past 10, whatever was skipped.
    const int64_t last = log.ticks[static_cast<std::size_t>(n - 1)];
    EXPECT_GE(last, 10);
    for (int64_t i = 0; i + 1 < n; ++i) EXPECT_LT(log.ticks[static_cast<std::size_t>(i)], 10);
    EXPECT_EQ(loop.stats().last_tick, last);
    EXPECT_EQ(loop.stats().ticks, n);
}

TEST(RealtimeLoop, ASlowCallbackOverrunsAndTheLoopSkipsInsteadOfBursting) {
    // Every 10th tick takes 3.5 periods: the next three deadlines pass while it runs.
    constexpr int64_t kTicks = 60;
    TickLog log(kTicks);
    RealtimeLoop loop;
    loop.start(quiet_options(1000, kTicks), [&](int64_t tick, int64_t t_us) {
        log.add(tick, t_us);
        if (tick % 10 == 0) std::this_thread::sleep_for(std::chrono::microseconds(3500));
    });
    loop.wait();
    const RealtimeLoopStats stats = loop.stats();
    expect_consistent(log, stats, 1000, kTicks);

    // Each slow tick started at or after its deadline D(n) and ended after D(n) + 3.5 ms,
    // past D(n+3): ticks n+1 and n+2 can never run, so every slow tick but a final one is
    // followed by an overrun that skips at least those two, and the next tick run is n+3
    // or later, never n+1 in a catch-up burst.
    int64_t slow_and_followed = 0;
    const int64_t n = log.count.load();
    for (int64_t i = 0; i + 1 < n; ++i) {
        const int64_t tick = log.ticks[static_cast<std::size_t>(i)];
        if (tick % 10 != 0) continue;
        ++slow_and_followed;
        EXPECT_GE(log.ticks[static_cast<std::size_t>(i + 1)], tick + 3) << "a burst after tick " << tick;
    }
    EXPECT_GE(slow_and_followed, 1);
    EXPECT_GE(stats.overruns, slow_and_followed);
    EXPECT_GE(stats.missed_ticks, 2 * slow_and_followed);
    EXPECT_GE(stats.callback_max_us, 3500.0);
}

TEST(RealtimeLoop, AnExceptionFromTheCallbackStopsTheLoopAndIsRethrown) {
    std::atomic<int64_t> completed{0};
    RealtimeLoop loop;
    loop.start(quiet_options(1000, 0), [&](int64_t tick, int64_t) {
        if (tick >= 5) throw std::runtime_error("sensor bus fault");
        completed.fetch_add(1);
    });
    try {
        loop.wait();
        FAIL() << "wait() did not rethrow";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "sensor bus fault");
    }
    EXPECT_FALSE(loop.running());
    EXPECT_EQ(loop.stats().ticks, completed.load());
    EXPECT_NO_THROW(loop.stop());  // rethrown once only
}

TEST(RealtimeLoop, RefusesBadOptionsNamingTheAllowedRange) {
    RealtimeLoop loop;
    auto nothing = [](int64_t, int64_t) {};
    auto message_of = [&](const RealtimeLoopOptions& o) -> std::string {
        try {
            loop.start(o, nothing);
            loop.stop();
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "accepted";
    };
    RealtimeLoopOptions o = quiet_options(99, 1);
    EXPECT_EQ(message_of(o), "rate_hz = 99 is out of range (allowed 100..20000 Hz)");
    o.rate_hz = 20001;
    EXPECT_EQ(message_of(o), "rate_hz = 20001 is out of range (allowed 100..20000 Hz)");
    o = quiet_options(1000, -1);
    EXPECT_NE(message_of(o).find("tick_limit = -1 is out of range"), std::string::npos);
    o = quiet_options(1000, 1);
    o.fifo_priority = 0;
    EXPECT_EQ(message_of(o), "fifo_priority = 0 is out of range (allowed 1..99)");
    o.fifo_priority = 100;
    EXPECT_EQ(message_of(o), "fifo_priority = 100 is out of range (allowed 1..99)");
    o.realtime_priority = false;  // the priority is not used then
    EXPECT_EQ(message_of(o), "accepted");
    const long cpus = sysconf(_SC_NPROCESSORS_CONF);
    o.cpu = static_cast<int32_t>(cpus);
    EXPECT_EQ(message_of(o), "cpu = " + std::to_string(cpus) + " is out of range (allowed -1 for any, or 0.." +
                                 std::to_string(cpus - 1) + ", this machine's CPUs)");
    o.cpu = -2;
    EXPECT_NE(message_of(o).find("cpu = -2 is out of range"), std::string::npos);
    EXPECT_THROW(loop.start(quiet_options(1000, 1), RealtimeLoop::Callback{}), std::invalid_argument);
    EXPECT_FALSE(loop.running());
}

TEST(RealtimeLoop, RefusesToStartTwice) {
    RealtimeLoop loop;
    loop.start(quiet_options(1000, 0), [](int64_t, int64_t) {});
    EXPECT_THROW(loop.start(quiet_options(1000, 0), [](int64_t, int64_t) {}), std::logic_error);
    loop.stop();
    // Restartable once stopped, with fresh counters.
    TickLog log(5);
    loop.start(quiet_options(1000, 5), [&](int64_t tick, int64_t t_us) { log.add(tick, t_us); });
    loop.wait();
    expect_consistent(log, loop.stats(), 1000, 5);
}

// VmLck of /proc/self/status, kB: the memory locked by the process.
long locked_kb() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmLck:") {
            long kb = -1;
            status >> kb;
            return kb;
        }
        status.ignore(1 << 12, '\n');
    }
    return -1;
}

// setup() must say what the thread really got: the test asks the thread itself.
TEST(RealtimeLoop, ReportsTheSchedulingAndMemoryLockingItObtained) {
    FEEL_SKIP_UNDER_SANITIZER("its mlockall() is a no-op that says yes: the lock it reports cannot be seen in VmLck");
    for (const bool ask : {true, false}) {
        std::atomic<int> policy{-1};
        std::atomic<int> priority{-1};
        std::atomic<long> locked_while_running{-1};
        RealtimeLoopOptions o = quiet_options(1000, 0);
        o.realtime_priority = ask;
        o.lock_memory = ask;
        RealtimeLoop loop;
        loop.start(o, [&](int64_t, int64_t) {
            if (policy.load() != -1) return;
            sched_param param{};
            int p = -1;
            pthread_getschedparam(pthread_self(), &p, &param);
            priority.store(param.sched_priority);
            policy.store(p);
        });
        locked_while_running = locked_kb();
        const auto give_up = Clock::now() + std::chrono::seconds(5);
        while (policy.load() == -1 && Clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        loop.stop();
        const RealtimeLoopSetup& setup = loop.setup();
        SCOPED_TRACE(setup.describe());
        if (setup.fifo) {
            EXPECT_TRUE(ask);
            EXPECT_EQ(policy.load(), SCHED_FIFO);
            EXPECT_EQ(priority.load(), 80);
            EXPECT_EQ(setup.priority, 80);
            EXPECT_NE(setup.describe().find("SCHED_FIFO priority 80"), std::string::npos);
        } else {
            EXPECT_EQ(policy.load(), SCHED_OTHER);
            EXPECT_FALSE(setup.scheduling_note.empty());
            if (!ask) {
                EXPECT_EQ(setup.scheduling_note, "SCHED_FIFO not asked for");
            }
        }
        if (setup.memory_locked) {
            EXPECT_TRUE(ask);
            EXPECT_GT(locked_while_running.load(), 0);
            EXPECT_EQ(locked_kb(), 0) << "the lock outlived the loop";
        } else {
            EXPECT_FALSE(setup.memory_note.empty());
            if (!ask) {
                EXPECT_EQ(setup.memory_note, "not asked for");
            }
        }
    }
}

// Pinning: the tick runs on the CPU asked for (sched_getcpu inside the tick, the kernel's
// word), and setup() says so. The loop skips the ticks it wakes too late for, and a thread
// pinned to one CPU cannot move off it when another process holds that CPU: so the loop is
// given up to 5 s and stopped after its first 20 ticks, rather than given 20 ticks (20 ms)
// that a busy CPU can let pass unrun.
TEST(RealtimeLoop, PinsTheThreadToTheCpuAskedFor) {
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    const auto last = static_cast<int32_t>(cpus - 1);
    RealtimeLoopOptions o = quiet_options(1000, 5000);
    o.realtime_priority = false;
    o.cpu = last;
    std::atomic<int> wrong{0};
    std::atomic<int> ran{0};
    RealtimeLoop loop;
    loop.start(o, [&](int64_t, int64_t) {
        if (sched_getcpu() != last) wrong.fetch_add(1);
        ran.fetch_add(1);
    });
    while (ran.load() < 20 && loop.running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    loop.stop();
    EXPECT_GT(ran.load(), 0);
    EXPECT_EQ(wrong.load(), 0);
    EXPECT_EQ(loop.setup().cpu, last);
    EXPECT_NE(loop.setup().describe().find("cpu: " + std::to_string(last)), std::string::npos)
        << loop.setup().describe();
    RealtimeLoop any;
    any.start(quiet_options(1000, 1), [](int64_t, int64_t) {});
    any.wait();
    EXPECT_EQ(any.setup().cpu, -1);
    EXPECT_NE(any.setup().describe().find("cpu: any"), std::string::npos) << any.setup().describe();
}

// Page faults are counted from the first tick to the last: a tick that writes one byte to
// a page of a fresh, unlocked anonymous mapping makes the kernel map that page on its first
// touch, one minor fault per page (the mapping exists before the loop starts; nothing is
// allocated inside the ticks).
TEST(RealtimeLoop, CountsThePageFaultsOfItsTicks) {
    constexpr int64_t kTicks = 64;
    const auto page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
    void* map = mmap(nullptr, page * kTicks, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(map, MAP_FAILED);
    auto* bytes = static_cast<volatile unsigned char*>(map);
    RealtimeLoopOptions o = quiet_options(2000, kTicks);
    o.realtime_priority = false;
    RealtimeLoop loop;
    loop.start(o, [&](int64_t tick, int64_t) { bytes[static_cast<size_t>(tick) * page] = 1; });
    loop.wait();
    const RealtimeLoopStats st = loop.stats();
    // Skipped ticks touch nothing: one fault per tick that ran, at least.
    EXPECT_GE(st.minor_faults, st.ticks);
    EXPECT_EQ(st.major_faults, 0);
    munmap(map, page * kTicks);
}

}  // namespace
}  // namespace feel::runtime
