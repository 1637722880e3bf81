// The fixed-rate loop thread: pacing by absolute deadlines, the skip-don't-burst overrun
// policy, the jitter histograms, and the SCHED_FIFO / mlockall attempts with their
// fallbacks. The design is described in include/feel/runtime/realtime_loop.hpp.
//
// Everything the thread does between its first and its last tick is a clock read, an
// absolute sleep, integer arithmetic, relaxed atomic stores and the callback: no
// allocation, no lock, no exception of its own. Integer nanoseconds throughout; deadlines
// are t0 + floor(n·1e9/rate) computed without overflow for any n a process can reach.
#include "feel/runtime/realtime_loop.hpp"

#include <linux/capability.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

#include "duration_histogram.hpp"

namespace feel::runtime {
namespace {

constexpr int64_t kNsPerS = 1'000'000'000;
constexpr int64_t kUsPerS = 1'000'000;
// Touched before the first tick so that the loop's stack is resident (and locked, when
// memory is) before timing matters. Generous for a callback that renders a busy engine.
constexpr size_t kStackPrefaultBytes = 256 * 1024;

int64_t monotonic_ns() noexcept {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<int64_t>(ts.tv_sec) * kNsPerS + ts.tv_nsec;
}

void sleep_until_ns(int64_t t_ns) noexcept {
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(t_ns / kNsPerS);
    ts.tv_nsec = static_cast<long>(t_ns % kNsPerS);
    // A signal handler may interrupt the sleep; the deadline is absolute, so just go on.
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

// floor(n · unit / rate) for n >= 0, split so that n · unit never overflows.
int64_t scaled_floor(int64_t n, int64_t unit, int64_t rate) noexcept {
    return (n / rate) * unit + (n % rate) * unit / rate;
}

// Tick n's deadline offset from t0, ns.
int64_t tick_offset_ns(int64_t n, int64_t rate) noexcept { return scaled_floor(n, kNsPerS, rate); }

// The last tick whose deadline offset is <= elapsed_ns (elapsed_ns >= 0).
int64_t latest_due_tick(int64_t elapsed_ns, int64_t rate) noexcept {
    int64_t k = (elapsed_ns / kNsPerS) * rate + (elapsed_ns % kNsPerS) * rate / kNsPerS;
    while (tick_offset_ns(k + 1, rate) <= elapsed_ns) ++k;  // rounding: at most one step
    return k;
}

// Single-writer counters: a load and a store, no read-modify-write needed.
void bump(std::atomic<int64_t>& counter, int64_t by = 1) noexcept {
    counter.store(counter.load(std::memory_order_relaxed) + by, std::memory_order_relaxed);
}

// Writes to every page of a stack buffer so that its pages are mapped now, not in a tick.
__attribute__((noinline)) void prefault_stack() noexcept {
    unsigned char buffer[kStackPrefaultBytes];
    volatile unsigned char* const pages = buffer;  // volatile stores: not optimized away
    for (size_t i = 0; i < kStackPrefaultBytes; i += 4096) pages[i] = 0;
}

std::string errno_text(int error) { return std::generic_category().message(error); }

// --- memory locking: process-wide, shared by every loop of the process ------------------

std::mutex g_memory_lock_mutex;
int g_memory_lock_holders = 0;  // loops holding mlockall; munlockall when the last ends

bool has_cap_ipc_lock() noexcept {
    __user_cap_header_struct header{};
    header.version = _LINUX_CAPABILITY_VERSION_3;
    header.pid = 0;
    __user_cap_data_struct data[_LINUX_CAPABILITY_U32S_3] = {};
    if (syscall(SYS_capget, &header, data) != 0) return false;
    return (data[CAP_IPC_LOCK / 32].effective & (1u << (CAP_IPC_LOCK % 32))) != 0;
}

// Locks the process's memory, or explains in `note` why not. Returns whether it holds it.
bool acquire_memory_lock(std::string& note) {
    const std::lock_guard<std::mutex> guard(g_memory_lock_mutex);
    if (g_memory_lock_holders > 0) {
        ++g_memory_lock_holders;
        return true;
    }
    rlimit limit{};
    const bool unlimited = getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY;
    if (!unlimited && !has_cap_ipc_lock()) {
        note = "mlockall not tried: no CAP_IPC_LOCK and RLIMIT_MEMLOCK is " + std::to_string(limit.rlim_cur / 1024) +
               " KiB, and locking future allocations against a finite limit could make them fail";
        return false;
    }
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
        note = "mlockall refused: " + errno_text(errno);
        return false;
    }
    g_memory_lock_holders = 1;
    return true;
}

void release_memory_lock() noexcept {
    const std::lock_guard<std::mutex> guard(g_memory_lock_mutex);
    if (g_memory_lock_holders > 0 && --g_memory_lock_holders == 0) munlockall();
}

}  // namespace

int64_t loop_tick_time_us(int64_t tick, int32_t rate_hz) noexcept {
    // tick = whole·rate + rest: whole seconds, then the rounded µs of the rest (|rest| <
    // rate <= 2^31, so rest·1e6 fits). Only whole·1e6 and the sum can overflow: checked,
    // saturating, never wrapping (no 128-bit arithmetic, which a Cortex-M lacks).
    const int64_t rate = rate_hz;
    const int64_t whole = tick / rate;
    const int64_t rest_us = ((tick % rate) * kUsPerS + rate / 2) / rate;
    int64_t t_us = 0;
    if (__builtin_mul_overflow(whole, kUsPerS, &t_us) || __builtin_add_overflow(t_us, rest_us, &t_us)) {
        return tick < 0 ? std::numeric_limits<int64_t>::min() : std::numeric_limits<int64_t>::max();
    }
    return t_us;
}

std::string RealtimeLoopSetup::describe() const {
    std::string s = "scheduler: ";
    s += fifo ? "SCHED_FIFO priority " + std::to_string(priority) : "SCHED_OTHER (" + scheduling_note + ")";
    s += "; memory: ";
    s += memory_locked ? std::string("locked (mlockall)") : "not locked (" + memory_note + ")";
    s += "; cpu: ";
    s += cpu >= 0 ? std::to_string(cpu) : cpu_note.empty() ? std::string("any") : "any (" + cpu_note + ")";
    return s;
}

struct RealtimeLoop::State {
    // Set by start() before the thread exists; read-only for the thread.
    RealtimeLoopOptions options;
    Callback callback;

    // Written by the loop thread only; read by anyone.
    DurationHistogram period_error;
    DurationHistogram latency;
    DurationHistogram callback_time;
    std::atomic<int64_t> ticks{0};
    std::atomic<int64_t> last_tick{-1};
    std::atomic<int64_t> overruns{0};
    std::atomic<int64_t> missed_ticks{0};
    std::atomic<int32_t> rate_hz{0};
    std::atomic<int64_t> minor_faults{0};  // stored once, when tick_loop() ends
    std::atomic<int64_t> major_faults{0};

    std::atomic<bool> stop_requested{false};
    std::atomic<bool> running{false};
    std::atomic<bool> started{false};   // the thread has settled its scheduling
    int scheduling_error = 0;            // pthread_setschedparam's result; read after `started`
    int affinity_error = 0;              // pthread_setaffinity_np's result; read after `started`
    std::exception_ptr failure;          // the callback's exception; read after join
    std::thread thread;
    bool holds_memory_lock = false;

    void reset(const RealtimeLoopOptions& o) noexcept {
        period_error.clear();
        latency.clear();
        callback_time.clear();
        ticks.store(0);
        last_tick.store(-1);
        overruns.store(0);
        missed_ticks.store(0);
        minor_faults.store(0);
        major_faults.store(0);
        rate_hz.store(o.rate_hz);
        stop_requested.store(false);
        started.store(false);
        scheduling_error = 0;
        affinity_error = 0;
        failure = nullptr;
    }

    void run() noexcept;
    void tick_loop();
};

void RealtimeLoop::State::run() noexcept {
    prefault_stack();
    // An ordinary thread's timed sleeps may end up to its timer slack (50 µs by default)
    // late, so that the kernel can batch wake-ups; the loop wants its deadline, not a
    // batch. 1 ns is the smallest slack (0 would restore the default).
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    if (options.realtime_priority) {
        sched_param param{};
        param.sched_priority = options.fifo_priority;
        scheduling_error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    }
    if (options.cpu >= 0) {
        cpu_set_t cpus;
        CPU_ZERO(&cpus);
        CPU_SET(static_cast<size_t>(options.cpu), &cpus);
        affinity_error = pthread_setaffinity_np(pthread_self(), sizeof cpus, &cpus);
    }
    started.store(true, std::memory_order_release);
    started.notify_one();
    try {
        tick_loop();
    } catch (...) {
        failure = std::current_exception();
    }
    running.store(false, std::memory_order_release);
}

void RealtimeLoop::State::tick_loop() {
    const int64_t rate = options.rate_hz;
    const int64_t limit = options.tick_limit;
    // Tick 0 is due one period from now: room to reach the first sleep before it.
    const int64_t t0 = monotonic_ns() + tick_offset_ns(1, rate);
    int64_t n = 0;
    bool have_previous = false;
    int64_t previous_start = 0;   // ns, when the previous tick began
    int64_t previous_offset = 0;  // ns, its deadline offset
    // Page faults of this thread from here on (the stack is prefaulted, the privileges set):
    // read before the first tick and after the last, never inside one.
    rusage before{};
    getrusage(RUSAGE_THREAD, &before);
    while (!stop_requested.load(std::memory_order_acquire)) {
        if (limit > 0 && n >= limit) break;
        int64_t now = monotonic_ns();
        if (now < t0 + tick_offset_ns(n, rate)) {
            sleep_until_ns(t0 + tick_offset_ns(n, rate));
            // A stop asked for during the sleep ends the loop before the next tick.
            if (stop_requested.load(std::memory_order_acquire)) break;
            now = monotonic_ns();
        }
        if (now >= t0 + tick_offset_ns(n + 1, rate)) {
            // Overrun: tick n could only start after its successor's deadline. Skip to the
            // latest tick that is due (see the header: skip, don't burst).
            const int64_t k = latest_due_tick(now - t0, rate);
            bump(overruns);
            if (limit > 0 && k >= limit) {
                bump(missed_ticks, limit - n);
                break;
            }
            bump(missed_ticks, k - n);
            n = k;
        }
        const int64_t offset = tick_offset_ns(n, rate);
        latency.record(static_cast<uint64_t>(now - (t0 + offset)));
        if (have_previous) {
            const int64_t error = (now - previous_start) - (offset - previous_offset);
            period_error.record(static_cast<uint64_t>(error < 0 ? -error : error));
        }
        have_previous = true;
        previous_start = now;
        previous_offset = offset;

        callback(n, loop_tick_time_us(n, options.rate_hz));

        callback_time.record(static_cast<uint64_t>(monotonic_ns() - now));
        last_tick.store(n, std::memory_order_relaxed);
        bump(ticks);
        ++n;
    }
    rusage after{};
    getrusage(RUSAGE_THREAD, &after);
    minor_faults.store(after.ru_minflt - before.ru_minflt, std::memory_order_relaxed);
    major_faults.store(after.ru_majflt - before.ru_majflt, std::memory_order_relaxed);
}

RealtimeLoop::RealtimeLoop() : state_(std::make_unique<State>()) {}

RealtimeLoop::~RealtimeLoop() {
    request_stop();
    join_and_release();
}

void RealtimeLoop::start(const RealtimeLoopOptions& options, Callback callback) {
    if (state_->thread.joinable()) {
        throw std::logic_error("RealtimeLoop::start: the loop is already running (call stop() or wait() first)");
    }
    if (options.rate_hz < kMinLoopRateHz || options.rate_hz > kMaxLoopRateHz) {
        throw std::invalid_argument("rate_hz = " + std::to_string(options.rate_hz) +
                                    " is out of range (allowed " + std::to_string(kMinLoopRateHz) + ".." +
                                    std::to_string(kMaxLoopRateHz) + " Hz)");
    }
    if (options.tick_limit < 0) {
        throw std::invalid_argument("tick_limit = " + std::to_string(options.tick_limit) +
                                    " is out of range (allowed >= 0; 0 runs until stop())");
    }
    const int min_priority = sched_get_priority_min(SCHED_FIFO);
    const int max_priority = sched_get_priority_max(SCHED_FIFO);
    if (options.realtime_priority && (options.fifo_priority < min_priority || options.fifo_priority > max_priority)) {
        throw std::invalid_argument("fifo_priority = " + std::to_string(options.fifo_priority) +
                                    " is out of range (allowed " + std::to_string(min_priority) + ".." +
                                    std::to_string(max_priority) + ")");
    }
    const long cpu_count = sysconf(_SC_NPROCESSORS_CONF);
    if (options.cpu < -1 || (options.cpu >= 0 && (options.cpu >= cpu_count || options.cpu >= CPU_SETSIZE))) {
        throw std::invalid_argument("cpu = " + std::to_string(options.cpu) + " is out of range (allowed -1 for any, or 0.." +
                                    std::to_string(cpu_count - 1) + ", this machine's CPUs)");
    }
    if (!callback) throw std::invalid_argument("RealtimeLoop::start: the callback is empty");

    State& s = *state_;
    s.reset(options);
    s.options = options;
    s.callback = std::move(callback);

    setup_ = RealtimeLoopSetup{};
    if (options.lock_memory) {
        s.holds_memory_lock = acquire_memory_lock(setup_.memory_note);
        setup_.memory_locked = s.holds_memory_lock;
    } else {
        setup_.memory_note = "not asked for";
    }

    s.running.store(true, std::memory_order_release);
    try {
        s.thread = std::thread([&s] { s.run(); });
    } catch (...) {
        s.running.store(false, std::memory_order_release);
        if (s.holds_memory_lock) release_memory_lock();
        s.holds_memory_lock = false;
        throw;
    }
    s.started.wait(false, std::memory_order_acquire);

    if (!options.realtime_priority) {
        setup_.scheduling_note = "SCHED_FIFO not asked for";
    } else if (s.scheduling_error == 0) {
        setup_.fifo = true;
        setup_.priority = options.fifo_priority;
    } else {
        setup_.scheduling_note = "SCHED_FIFO priority " + std::to_string(options.fifo_priority) +
                                 " refused: " + errno_text(s.scheduling_error);
    }
    if (options.cpu >= 0) {
        if (s.affinity_error == 0) {
            setup_.cpu = options.cpu;
        } else {
            setup_.cpu_note = "pinning to cpu " + std::to_string(options.cpu) + " refused: " + errno_text(s.affinity_error);
        }
    }
}

void RealtimeLoop::request_stop() noexcept { state_->stop_requested.store(true, std::memory_order_release); }

void RealtimeLoop::join_and_release() {
    State& s = *state_;
    if (s.thread.joinable()) s.thread.join();
    if (s.holds_memory_lock) {
        release_memory_lock();
        s.holds_memory_lock = false;
    }
}

void RealtimeLoop::stop() {
    request_stop();
    wait();
}

void RealtimeLoop::wait() {
    join_and_release();
    if (std::exception_ptr failure = std::exchange(state_->failure, nullptr)) std::rethrow_exception(failure);
}

bool RealtimeLoop::running() const noexcept { return state_->running.load(std::memory_order_acquire); }

RealtimeLoopStats RealtimeLoop::stats() const noexcept {
    const State& s = *state_;
    RealtimeLoopStats st;
    st.rate_hz = s.rate_hz.load(std::memory_order_relaxed);
    st.ticks = s.ticks.load(std::memory_order_relaxed);
    st.last_tick = s.last_tick.load(std::memory_order_relaxed);
    st.overruns = s.overruns.load(std::memory_order_relaxed);
    st.missed_ticks = s.missed_ticks.load(std::memory_order_relaxed);
    constexpr double kUs = 1e-3;
    st.period_error_p50_us = s.period_error.quantile(0.50) * kUs;
    st.period_error_p99_us = s.period_error.quantile(0.99) * kUs;
    st.period_error_p999_us = s.period_error.quantile(0.999) * kUs;
    st.period_error_max_us = static_cast<double>(s.period_error.max()) * kUs;
    st.latency_p50_us = s.latency.quantile(0.50) * kUs;
    st.latency_p99_us = s.latency.quantile(0.99) * kUs;
    st.latency_p999_us = s.latency.quantile(0.999) * kUs;
    st.latency_max_us = static_cast<double>(s.latency.max()) * kUs;
    st.callback_p50_us = s.callback_time.quantile(0.50) * kUs;
    st.callback_p99_us = s.callback_time.quantile(0.99) * kUs;
    st.callback_p999_us = s.callback_time.quantile(0.999) * kUs;
    st.callback_max_us = static_cast<double>(s.callback_time.max()) * kUs;
    st.minor_faults = s.minor_faults.load(std::memory_order_relaxed);
    st.major_faults = s.major_faults.load(std::memory_order_relaxed);
    return st;
}

}  // namespace feel::runtime
