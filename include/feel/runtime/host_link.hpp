// feel::runtime — the host's end of the two queues to the device's local processor.
//
// The host (the game's side, figure 2-4) sends commands and reads reports. HostLink holds
// the producer end of the command queue and the consumer end of the report queue, numbers
// the commands it sends, and splits a force profile's samples into stage_samples commands
// ahead of its create or update (runtime_messages.hpp). DeviceRuntime is a HostLink; a
// test that ticks a RuntimePipeline by hand makes one on the pipeline's queues.
//
// Threads. One host thread uses a HostLink (it is the single producer of commands and the
// single consumer of reports). Nothing here blocks, allocates or locks: a full command
// queue makes a call return std::nullopt (or false) with nothing sent, so the host decides
// whether to retry; the only exception is a force profile with more samples than the
// command queue could ever hold at once (std::invalid_argument).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/runtime/safety.hpp"
#include "feel/runtime/spsc_queue.hpp"

namespace feel::runtime {

class HostLink {
public:
    HostLink(SpscQueue<Command>& commands, SpscQueue<Report>& reports) noexcept
        : commands_(&commands), reports_(&reports) {}

    // Sends a command as it is (its own sequence number). False when the queue is full.
    bool send(const Command& command) noexcept { return commands_->try_push(command); }
    // Takes the oldest report. False when there is none.
    bool poll(Report& report) noexcept { return reports_->try_pop(report); }

    // Convenience: each builds a command, numbers it with next_sequence() and sends it.
    // Returns its sequence number (its ack will carry it), or std::nullopt when the queue
    // has no room; then nothing was sent and no number was used.
    std::optional<uint32_t> keep_alive() noexcept;
    // A force profile's samples go first, in stage_samples commands (numbered too); the
    // returned number is the create's. All of them are sent or none.
    std::optional<uint32_t> create(const EffectParams& params, std::span<const int16_t> samples = {});
    std::optional<uint32_t> update(EffectId effect, const EffectParams& params, uint32_t field_mask,
                                   bool restart = false, std::span<const int16_t> samples = {});
    // Named start_effect and stop_effect, not start and stop: DeviceRuntime, a HostLink,
    // has start() and stop() for its loop.
    std::optional<uint32_t> start_effect(EffectId effect, int32_t iterations = kEffectIterations,
                                         bool solo = false) noexcept;
    std::optional<uint32_t> stop_effect(EffectId effect) noexcept;
    std::optional<uint32_t> destroy(EffectId effect) noexcept;
    std::optional<uint32_t> status(EffectId effect) noexcept;
    std::optional<uint32_t> set_gain(int32_t gain) noexcept;
    std::optional<uint32_t> control(DeviceControl control) noexcept;
    std::optional<uint32_t> query_pool() noexcept;
    std::optional<uint32_t> assign_reflex(EffectId effect) noexcept;
    std::optional<uint32_t> remove_reflex(EffectId effect) noexcept;
    std::optional<uint32_t> set_idf(IdfSettings settings) noexcept;
    std::optional<uint32_t> configure_safety(const SafetyConfig& config) noexcept;
    std::optional<uint32_t> set_report_rate(int32_t hz) noexcept;
    // One sample of a streamed force (§2.4): `force` per device axis, in order, ±10000.
    std::optional<uint32_t> stream_force(std::span<const int16_t> force) noexcept;

    // The number the next convenience call will use (starts at 1, wraps).
    [[nodiscard]] uint32_t next_sequence() const noexcept { return next_sequence_; }
    // Commands a create or update with this many samples takes: one per kSamplesPerCommand
    // samples, plus the command itself.
    [[nodiscard]] static std::size_t commands_for(std::size_t samples) noexcept {
        return (samples + kSamplesPerCommand - 1) / kSamplesPerCommand + 1;
    }

private:
    std::optional<uint32_t> send_numbered(Command command) noexcept;
    std::optional<uint32_t> send_with_samples(Command command, std::span<const int16_t> samples);

    SpscQueue<Command>* commands_;
    SpscQueue<Report>* reports_;
    uint32_t next_sequence_ = 1;
    Command scratch_{};  // a stage_samples command being filled (1.3 KB, not on the stack)
};

}  // namespace feel::runtime
