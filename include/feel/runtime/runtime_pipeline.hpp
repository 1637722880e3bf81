// feel::runtime — one pass of the device's local processor (§2.2), without a thread.
//
// RuntimePipeline is the primer's local processor minus its clock: it owns the engine, the
// reflex table, the safety monitor, the IDF filter, the device backend and the two queues
// to the host, and tick(n) runs tick n of the local control loop:
//
//   1. commands   take the host's commands (at most max_commands_per_tick) from the
//                 command queue, apply each to the engine, and post its ack
//   2. sense      read positions, buttons, hats and the dead-man switch from the backend
//   3. reflexes   start the effects whose trigger buttons were pressed (0 ticks latency)
//   4. render     engine.tick(): every playing effect's force, plus the force the host
//                 streams (force_stream.hpp), scaled by the device gain, clamped
//   5. safety     dead-man, fade-in, hands-off, host watchdog scale the forces; a lost host
//                 stops every effect
//   6. actuate    the motors get the safe forces
//   7. IDF        the reported position: the sensed one minus the displacement of the
//                 player's filtered classes, held at clipping walls
//   8. report     forward the dynamics' interim and final reports, and at the report rate
//                 post the device's state
//
// Time comes from the tick index alone: tick n is at loop_tick_time_us(n, loop_rate_hz).
// The same commands at the same ticks therefore give the same forces and reports, bit for
// bit, whether a RealtimeLoop thread calls tick() (DeviceRuntime, device_runtime.hpp) or a
// test does, tick by tick.
//
// Threads. Construction allocates every buffer (engine slots and sample store, reflex
// table, sample stage, both queues); tick() never allocates, locks, blocks or throws, and
// runs on one thread, the loop's. The host thread owns the other ends of the queues
// (HostLink, host_link.hpp) and may read counters() at any time. Every other accessor
// reads loop-thread state: call it from the loop thread, or while no loop runs.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>

#include "feel/engine.hpp"
#include "feel/runtime/force_stream.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/runtime/realtime_loop.hpp"
#include "feel/runtime/reflexes.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/runtime/safety.hpp"
#include "feel/runtime/spsc_queue.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/status.hpp"

namespace feel::runtime {

// Host report rates, Hz (issue 5, §9). The default sits between the host's ~100 Hz game
// loop (§2.2), which then always finds a report younger than half its frame, and the
// 1 kHz local loop, which would post ten reports per host frame for nothing.
inline constexpr int32_t kMinReportRateHz = 100;
inline constexpr int32_t kMaxReportRateHz = 1000;
inline constexpr int32_t kDefaultReportRateHz = 250;

struct RuntimeConfig {
    // The local loop's rate, whole Hz, kMinLoopRateHz..kMaxLoopRateHz (100..20000).
    int32_t loop_rate_hz = kDefaultLoopRateHz;
    // State reports to the host, Hz, kMinReportRateHz..min(kMaxReportRateHz, loop_rate_hz).
    int32_t report_rate_hz = kDefaultReportRateHz;
    EngineConfig engine{};   // the effect engine; axis_count is the device's
    SafetyConfig safety{};   // axis_count must be the engine's
    IdfConfig idf{};         // axis_count must be the engine's; settings: the player's start choice
    // Command queue, commands, 1..65536.
    int32_t command_capacity = 256;
    // Report queue, reports, up to 1048576. It must hold one tick's acks, one full round of
    // state report pages and one more: at least max_commands_per_tick + state_report_pages(
    // engine.max_effects) + 1. State and dynamics' reports leave max_commands_per_tick
    // places free for acks.
    int32_t report_capacity = 1024;
    // Commands applied per tick at most, 1..1024: bounds the time a burst of commands
    // takes from one tick. The rest wait in the queue for the next ticks.
    int32_t max_commands_per_tick = 32;
    // Whether the device runs trigger-button reflexes itself (§1.2.c). false for an
    // I-FORCE 1.x-class processor (DeviceProfile::local_reflexes): an effect's trigger
    // fields are kept with it but never armed, and assign_reflex / remove_reflex are refused
    // with not_supported; the host emulates reflexes.
    bool local_reflexes = true;
};

// The runtime of a simulated device: engine_config_for, safety_config_for and
// idf_config_for of the profile, its default loop rate and whether it runs reflexes, the
// defaults otherwise.
[[nodiscard]] RuntimeConfig runtime_config_for(const sim::DeviceProfile& profile) noexcept;
// Empty when the configuration is usable; otherwise the first bad field and its range.
// (The engine checks its own fields; see Engine::create's errors.)
[[nodiscard]] Error check_runtime_config(const RuntimeConfig& config) noexcept;
// The report rates a loop rate allows: kMinReportRateHz..min(kMaxReportRateHz, loop_rate_hz).
[[nodiscard]] Range report_rate_range(int32_t loop_rate_hz) noexcept;
// Pages of one round of state reports for a device of max_effects slots, >= 1.
[[nodiscard]] int32_t state_report_pages(int32_t max_effects) noexcept;

// The pipeline's counters since construction. A snapshot; each field is exact, the set is
// not one instant.
struct RuntimeCounters {
    int64_t ticks = 0;                  // ticks run
    int64_t last_tick = -1;             // index of the last tick run, -1 before the first
    int64_t t_us = 0;                   // device time of the last tick, µs
    int64_t rejected_ticks = 0;         // tick() calls whose index did not increase (ignored)
    int64_t commands = 0;               // commands applied, each acked
    int64_t commands_refused = 0;       // of those, acked with an error
    int64_t command_stalls = 0;         // ticks that left commands waiting for room for acks
    int64_t state_reports = 0;          // state report messages posted (pages)
    int64_t dropped_state_reports = 0;  // state report rounds not posted: the queue was full
    int64_t dynamic_reports = 0;        // dynamics' reports forwarded
    // Dynamics' reports lost: the engine's report store overflowed while the report queue
    // was full (Engine::dropped_reports).
    int64_t dropped_dynamic_reports = 0;
    int64_t reflex_starts = 0;          // effects started by reflexes
    int64_t host_losses = 0;            // times the host watchdog tripped
};

class RuntimePipeline {
public:
    // Throws std::invalid_argument naming the bad field and its range when the config
    // (check_runtime_config) or the backend (null, another axis count) does not fit.
    RuntimePipeline(const RuntimeConfig& config, std::unique_ptr<RuntimeBackend> backend);
    ~RuntimePipeline();
    RuntimePipeline(const RuntimePipeline&) = delete;
    RuntimePipeline& operator=(const RuntimePipeline&) = delete;

    // Runs tick `tick_index` (>= 0) at loop_tick_time_us(tick_index, loop_rate_hz). Indexes
    // must increase; they may jump (ticks skipped after an overrun). A call with an index
    // not above the last is ignored and counted (rejected_ticks). Real-time safe.
    void tick(int64_t tick_index) noexcept;
    // The index after the last tick run (0 before the first): where a new loop continues.
    // Any thread (it reads the published counter, not the loop's own state); while a loop
    // runs, a snapshot that may be one tick behind.
    [[nodiscard]] int64_t next_tick_index() const noexcept {
        return counters_.last_tick.load(std::memory_order_acquire) + 1;
    }

    // The queues. The host pushes commands and pops reports (one host thread); the loop
    // does the rest.
    [[nodiscard]] SpscQueue<Command>& commands() noexcept { return commands_; }
    [[nodiscard]] SpscQueue<Report>& reports() noexcept { return reports_; }

    // Any thread.
    [[nodiscard]] RuntimeCounters counters() const noexcept;
    [[nodiscard]] const RuntimeConfig& config() const noexcept { return config_; }

    // Loop-thread state (the loop thread, or any thread while no loop runs).
    [[nodiscard]] const Engine& engine() const noexcept { return engine_; }
    [[nodiscard]] RuntimeBackend& backend() noexcept { return *backend_; }
    [[nodiscard]] const SafetyMonitor& safety() const noexcept { return safety_; }
    [[nodiscard]] const IdfFilter& idf() const noexcept { return idf_; }
    [[nodiscard]] const ReflexTable& reflexes() const noexcept { return reflexes_; }
    [[nodiscard]] const ForceStream& force_stream() const noexcept { return force_stream_; }
    // The streamed force of the last tick, reconstructed, before gain and the sum's clamp.
    [[nodiscard]] const float* streamed_force() const noexcept { return streamed_; }
    [[nodiscard]] const TickInput& last_input() const noexcept { return in_; }    // what was sensed
    [[nodiscard]] const TickOutput& last_output() const noexcept { return out_; }  // the engine's
    [[nodiscard]] const float* motor_force() const noexcept { return applied_; }   // after safety
    [[nodiscard]] const float* reported_position() const noexcept { return reported_; }
    [[nodiscard]] int32_t report_rate_hz() const noexcept { return report_rate_hz_; }
    [[nodiscard]] int32_t staged_samples() const noexcept { return staged_; }
    [[nodiscard]] int32_t resident_effects() const noexcept { return resident_count_; }

private:
    // The counters, written by the loop thread only (a relaxed load and store, no
    // read-modify-write), read by any.
    struct Counters {
        std::atomic<int64_t> ticks{0}, last_tick{-1}, t_us{0}, rejected_ticks{0};
        std::atomic<int64_t> commands{0}, commands_refused{0}, command_stalls{0};
        std::atomic<int64_t> state_reports{0}, dropped_state_reports{0};
        std::atomic<int64_t> dynamic_reports{0}, dropped_dynamic_reports{0};
        std::atomic<int64_t> reflex_starts{0}, host_losses{0};
    };

    // 1. commands (runtime_commands.cpp)
    void drain_commands(int64_t t_us) noexcept;
    Error apply(const Command& c, CommandAck& ack) noexcept;
    Error apply_create(const Command& c, CommandAck& ack) noexcept;
    Error apply_update(const Command& c, CommandAck& ack) noexcept;
    Error apply_start(const Command& c, CommandAck& ack) noexcept;
    Error apply_destroy(const Command& c, CommandAck& ack) noexcept;
    Error apply_device_control(const Command& c, CommandAck& ack) noexcept;
    Error apply_configure_safety(const Command& c) noexcept;
    Error apply_set_report_rate(const Command& c, int64_t t_us) noexcept;
    Error apply_stage_samples(const Command& c, CommandAck& ack) noexcept;
    Error apply_stream_force(const Command& c) noexcept;
    [[nodiscard]] std::span<const int16_t> take_staged_samples() noexcept;
    void track(EffectId id) noexcept;
    void untrack(EffectId id) noexcept;
    void untrack_all() noexcept;

    // 8. reports (host_reports.cpp)
    [[nodiscard]] int64_t report_room() const noexcept;
    void forward_dynamic_reports() noexcept;
    void post_state_report_if_due(int64_t t_us) noexcept;
    void post_state_reports(int64_t t_us) noexcept;
    void restart_report_schedule(int64_t t_us) noexcept;

    static void bump(std::atomic<int64_t>& counter, int64_t by = 1) noexcept {
        counter.store(counter.load(std::memory_order_relaxed) + by, std::memory_order_relaxed);
    }

    RuntimeConfig config_;
    std::unique_ptr<RuntimeBackend> backend_;
    Engine engine_;
    ReflexTable reflexes_;
    SafetyMonitor safety_;
    IdfFilter idf_;
    ForceStream force_stream_;
    SpscQueue<Command> commands_;
    SpscQueue<Report> reports_;

    // Force-profile samples received ahead of their create or update.
    std::unique_ptr<int16_t[]> stage_;
    int32_t stage_capacity_ = 0;   // min(engine max_samples, the largest profile)
    int32_t staged_ = 0;
    // The resident effects by slot (EffectId::index), invalid where the slot is free.
    std::unique_ptr<EffectId[]> resident_;
    int32_t resident_count_ = 0;

    // Loop-thread state. The scratch messages live here, not on the loop's stack.
    TickInput in_{};
    TickOutput out_{};
    EngineActivity activity_{};
    float applied_[kMaxAxes] = {};   // the motors' force since the last actuate()
    float streamed_[kMaxAxes] = {};  // the stream's reconstructed force at the last tick
    float reported_[kMaxAxes] = {};  // the position reported at the last tick
    Command command_{};
    Report report_{};
    DynamicReport dynamic_{};
    bool started_ = false;
    int64_t last_tick_ = -1;
    int64_t host_heard_us_ = 0;      // the last tick that saw a command from the host
    bool releasing_ = false;         // a release_host waits for the host's fade to end
    uint32_t release_sequence_ = 0;  // its sequence, for the ack
    int32_t report_rate_hz_ = kDefaultReportRateHz;
    int64_t report_origin_us_ = 0;   // report k is due at origin + ceil(k·1e6/rate)
    int64_t next_report_ = 0;        // k of the next report due
    uint32_t report_number_ = 0;     // state report rounds posted
    int64_t reflex_fired_seen_ = 0;  // reflexes_.fired() at the last tick
    Counters counters_;
};

}  // namespace feel::runtime
