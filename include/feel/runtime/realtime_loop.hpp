// feel::runtime — the fixed-rate thread of the device's local control loop (§2.2).
//
// The primer's devices run their local loop at about 1 kHz (figure 2-4): read the sensors,
// compute the forces, drive the motors, again and again, next to the host's ~100 Hz game
// loop. RealtimeLoop is the clock of that loop: a thread that calls a callback once per
// period, `callback(tick, t_us)`, and measures how well it keeps time.
//
// Pacing. Tick n is due at the absolute deadline D(n) = t0 + n·period on CLOCK_MONOTONIC,
// and the thread sleeps with clock_nanosleep(TIMER_ABSTIME) until it. Deadlines are
// computed from the tick index, never by adding periods to the last wake-up, so a late
// wake-up delays one tick and does not shift every later one: the loop never drifts.
//
// Time. The callback's t_us is the tick's nominal time, tick·period (rounded to the
// nearest µs when the period is not a whole number of µs): effect time comes from the tick
// count, never from the clock. The clock only paces. So whatever the scheduler does, the
// effects see the same times, and an effect plays identically here and in a render.
//
// Overruns: skip, don't burst. When the loop gets to tick n only after D(n+1) has passed
// (the previous callback ran long, or the thread was preempted), tick n is an overrun. The
// loop then skips every tick whose deadline has passed except the latest, k, and runs k at
// once: its t_us stays aligned with the wall clock, and the callback is never called in a
// burst of back-to-back catch-up ticks (which would hammer the motors with stale forces and
// push the following ticks late too). The skipped ticks are counted as missed; the tick
// numbers the callback sees then jump from n-1 to k. Each such event counts as one overrun.
// A tick that starts late but before its successor's deadline is not an overrun; its
// lateness shows in the jitter figures.
//
// Jitter. The loop records, without allocating, three histograms: the period error (the
// interval between two consecutive tick starts minus its nominal length, in absolute
// value), the latency (tick start minus its deadline) and the callback's run time. Their
// p50/p99/p99.9 and maxima are in stats(), readable from any thread while it runs.
//
// Privileges. Where the process may, the thread runs under SCHED_FIFO (pthread_setschedparam)
// and the process's memory is locked (mlockall(MCL_CURRENT | MCL_FUTURE)), so that no other
// ordinary thread preempts it and no page fault stalls it. In any case its timer slack is
// 1 ns (PR_SET_TIMERSLACK), so the kernel does not delay its wake-ups to batch them. Where it may not, the loop runs
// as an ordinary thread with unlocked memory and says so in setup(); nothing fails.
// Memory is locked only when the process has CAP_IPC_LOCK or an unlimited RLIMIT_MEMLOCK:
// with a finite limit, MCL_FUTURE would make later allocations of any thread fail once
// the limit is reached, which is worse than an occasional page fault.
//
// Real-time safety. The thread's work between start and stop (sleeping, clock reads,
// bookkeeping, the call of the callback) never allocates, locks or throws; the callback
// must keep the same rules (docs/runtime.md). start(), stop() and wait() are not real-time
// safe and belong to one controlling thread; request_stop(), running() and stats() are
// real-time safe and may be called from any thread, the callback included.
#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <string>

namespace feel::runtime {

// Loop rates accepted, whole Hz: the primer's ~1 kHz with a decade of room either way.
inline constexpr int32_t kMinLoopRateHz = 100;
inline constexpr int32_t kMaxLoopRateHz = 20000;
inline constexpr int32_t kDefaultLoopRateHz = 1000;

struct RealtimeLoopOptions {
    int32_t rate_hz = kDefaultLoopRateHz;  // kMinLoopRateHz..kMaxLoopRateHz, whole Hz
    // Ticks to run before the loop stops by itself: ticks 0..tick_limit-1 (skipped ticks
    // count, so it ends at the same wall time however many overran). 0: until stop().
    int64_t tick_limit = 0;                // >= 0
    bool realtime_priority = true;         // try SCHED_FIFO; off: stay an ordinary thread
    int32_t fifo_priority = 80;            // 1..99 (Linux SCHED_FIFO range), when trying
    bool lock_memory = true;               // try mlockall(MCL_CURRENT | MCL_FUTURE)
    // Pin the loop thread to this CPU (0..CPU count − 1, pthread_setaffinity_np); -1: no pinning,
    // the thread may run on any CPU. A refusal is reported in setup(), never fatal.
    int32_t cpu = -1;
};

// What the loop obtained from the system. Filled by start(), before it returns.
struct RealtimeLoopSetup {
    bool fifo = false;            // the thread runs under SCHED_FIFO
    int32_t priority = 0;         // its SCHED_FIFO priority, 0 when not fifo
    std::string scheduling_note;  // when not fifo: why (not asked, or the system's refusal)
    bool memory_locked = false;   // mlockall held while this loop runs
    std::string memory_note;      // when not locked: why
    int32_t cpu = -1;             // the CPU the thread is pinned to, -1 when not pinned
    std::string cpu_note;         // when pinning was asked for and refused: why

    // One line, e.g. "scheduler: SCHED_FIFO priority 80; memory: locked (mlockall)" or
    // "scheduler: SCHED_OTHER (SCHED_FIFO refused: Operation not permitted); memory: ...",
    // followed by "; cpu: 1" or "; cpu: any" (or why pinning was refused).
    [[nodiscard]] std::string describe() const;
};

// A snapshot of the loop's counters. Durations in µs.
struct RealtimeLoopStats {
    int32_t rate_hz = 0;              // the rate of the last start()
    int64_t ticks = 0;                // callbacks run
    int64_t last_tick = -1;           // index of the last tick run, -1 before the first
    int64_t overruns = 0;             // times the loop found a whole period passed (see above)
    int64_t missed_ticks = 0;         // ticks skipped by those overruns, never run
    // |interval between consecutive tick starts − nominal interval|, over ticks - 1 intervals.
    double period_error_p50_us = 0;
    double period_error_p99_us = 0;
    double period_error_p999_us = 0;
    double period_error_max_us = 0;
    // Tick start minus its deadline (>= 0): how late each tick began.
    double latency_p50_us = 0;
    double latency_p99_us = 0;
    double latency_p999_us = 0;
    double latency_max_us = 0;
    // The callback's run time per tick.
    double callback_p50_us = 0;
    double callback_p99_us = 0;
    double callback_p999_us = 0;
    double callback_max_us = 0;
    // Page faults the loop thread took between its first tick and its last (getrusage
    // RUSAGE_THREAD; minor: the page was in memory but not mapped, major: read from disk).
    // Set when the loop has stopped; 0 while it runs.
    int64_t minor_faults = 0;
    int64_t major_faults = 0;
};

// Tick n's nominal time, µs: round(n · 1e6 / rate_hz) (halves up), exact whenever it fits
// in int64 (2^63 µs = 292 000 years; at 20 kHz, every n < 1.8e17), and saturating at
// INT64_MAX beyond, never wrapping (INT64_MIN for negative n, which no loop produces).
// rate_hz >= 1. This is the t_us the callback receives.
[[nodiscard]] int64_t loop_tick_time_us(int64_t tick, int32_t rate_hz) noexcept;

class RealtimeLoop {
public:
    // Called once per tick on the loop thread with the tick index (0, 1, 2, ... with jumps
    // after overruns) and its nominal time in µs. Must not allocate, lock or block. An
    // exception thrown from it stops the loop; stop() or wait() rethrows it.
    using Callback = std::function<void(int64_t tick, int64_t t_us)>;

    // Allocates the loop's bookkeeping (its histograms); starts nothing.
    RealtimeLoop();
    // Stops the loop if it runs (an exception of the callback is dropped).
    ~RealtimeLoop();
    RealtimeLoop(const RealtimeLoop&) = delete;
    RealtimeLoop& operator=(const RealtimeLoop&) = delete;

    // Starts the thread and returns once it runs with its privileges settled (setup()).
    // Tick 0 is due one period after that. Clears the previous run's stats. Throws
    // std::invalid_argument naming a bad option and its allowed range, or an empty
    // callback; std::logic_error if the loop is already running (or stopped by itself and
    // not yet waited for); std::system_error if no thread can be made.
    void start(const RealtimeLoopOptions& options, Callback callback);

    // Asks the loop to end after the tick in progress, or before the next one. Real-time
    // safe, any thread, the callback included; returns at once.
    void request_stop() noexcept;
    // request_stop(), then joins the thread. Within one period (plus the callback in
    // progress). Rethrows the callback's exception, if it threw. Harmless when not
    // running. Not from the callback.
    void stop();
    // Joins the thread once it ends by itself (tick_limit reached, request_stop() called,
    // or the callback threw). Blocks forever if none of these happens. Rethrows the
    // callback's exception, if it threw. Harmless when not started. Not from the callback.
    void wait();

    // Any thread. True from start() until the thread has finished its last tick.
    [[nodiscard]] bool running() const noexcept;
    // Any thread, real-time safe. Exact once the loop has stopped.
    [[nodiscard]] RealtimeLoopStats stats() const noexcept;
    // What start() obtained. Controlling thread.
    [[nodiscard]] const RealtimeLoopSetup& setup() const noexcept { return setup_; }

private:
    struct State;
    void join_and_release();

    std::unique_ptr<State> state_;
    RealtimeLoopSetup setup_;
};

}  // namespace feel::runtime
