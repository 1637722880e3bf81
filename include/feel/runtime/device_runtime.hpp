// feel::runtime — the device runtime: the primer's local processor on its own thread (§2.2).
//
// The primer's devices run two loops side by side (figure 2-4): the host's game loop at
// about 100 Hz, which sends high-level commands, and the device's local control loop at
// about 1 kHz, which reads the sensors, computes the forces and drives the motors. The
// DeviceRuntime is the device's side: a RuntimePipeline (runtime_pipeline.hpp: engine,
// reflexes, safety, IDF, backend, the two queues) ticked by a RealtimeLoop thread
// (realtime_loop.hpp) at the configured rate, 1 kHz by default. The host side is this
// object's HostLink: send() and the convenience calls put commands on the command queue,
// poll() takes the acks, state reports and dynamics' reports off the report queue.
//
//   DeviceRuntime rt(runtime_config_for(profile), std::make_unique<SimBackend>(...));
//   rt.start();
//   const auto seq = rt.create(params);            // ... its ack carries the EffectId
//   Report r;  while (rt.poll(r)) { ... }          // at the host's own pace
//   rt.stop();
//
// Time. Effect time comes from the tick count alone (tick n is at n periods of device
// time), never from reading a clock in effect math: the clock only paces the thread. A
// runtime stopped and started again continues its device time from the next tick, so the
// effects, the watchdog and the reports see no gap.
//
// Threads and real-time safety. The loop thread runs RuntimePipeline::tick, which never
// allocates, locks, blocks or throws. The host thread (one thread) calls everything here:
// start(), stop() and the constructor/destructor are not real-time safe (thread creation,
// join, allocation); send(), poll(), the convenience calls, stats() and running() never
// block or allocate. pipeline() gives the loop's state for inspection while stopped.
#pragma once

#include <cstdint>
#include <memory>

#include "feel/runtime/host_link.hpp"
#include "feel/runtime/realtime_loop.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"

namespace feel::runtime {

// Told by the loop's thread after each tick that leaves reports in the queue for the host
// to take, so that whoever takes them need not poll for them (the peripheral's service
// thread sleeps until then: peripheral.cpp). Called on the real-time loop: it must never
// block, lock, allocate or throw.
class ReportSignal {
public:
    virtual void reports_ready() noexcept = 0;

protected:
    ~ReportSignal() = default;
};

// What the loop thread asks of the system (RealtimeLoopOptions, realtime_loop.hpp); the
// loop falls back cleanly where it is refused.
struct DeviceRuntimeOptions {
    bool realtime_priority = true;  // try SCHED_FIFO
    int32_t fifo_priority = 80;     // 1..99
    bool lock_memory = true;        // try mlockall
    ReportSignal* report_signal = nullptr;  // not owned; outlives the runtime's loop
};

struct DeviceRuntimeStats {
    RuntimeCounters pipeline{};  // ticks, commands, reports posted and dropped, reflexes ...
    RealtimeLoopStats loop{};    // the thread's ticks, overruns, missed ticks, jitter (this run)
};

class DeviceRuntime : public HostLink {
public:
    // Builds the pipeline (allocates everything the loop will use). Throws
    // std::invalid_argument for a bad config or backend (RuntimePipeline's constructor).
    DeviceRuntime(const RuntimeConfig& config, std::unique_ptr<RuntimeBackend> backend,
                  const DeviceRuntimeOptions& options = {});
    // Stops the loop if it runs.
    ~DeviceRuntime();
    DeviceRuntime(const DeviceRuntime&) = delete;
    DeviceRuntime& operator=(const DeviceRuntime&) = delete;

    // Starts the loop thread at config().loop_rate_hz; returns once it runs. The first
    // tick comes one period later. Throws std::logic_error if it already runs,
    // std::system_error if no thread can be made.
    void start();
    // Stops the loop after the tick in progress and joins it. Harmless when stopped.
    // Commands still queued stay queued for the next start().
    void stop();
    [[nodiscard]] bool running() const noexcept { return loop_.running(); }

    // Any time, from the host thread.
    [[nodiscard]] DeviceRuntimeStats stats() const noexcept;
    [[nodiscard]] const RuntimeConfig& config() const noexcept { return pipeline_->config(); }
    // What the loop obtained from the system at the last start().
    [[nodiscard]] const RealtimeLoopSetup& setup() const noexcept { return loop_.setup(); }
    // The loop's state: read it only while the runtime is stopped.
    [[nodiscard]] RuntimePipeline& pipeline() noexcept { return *pipeline_; }

private:
    DeviceRuntime(std::unique_ptr<RuntimePipeline> pipeline, const DeviceRuntimeOptions& options);

    std::unique_ptr<RuntimePipeline> pipeline_;
    DeviceRuntimeOptions options_;
    RealtimeLoop loop_;
};

}  // namespace feel::runtime
