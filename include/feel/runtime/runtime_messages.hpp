// feel::runtime — the messages between the host and the device's local processor (§2.2).
//
// The host commands the device with high-level messages and the device answers with
// reports (figure 2-4: the host control loop at ~100 Hz, the local loop at ~1 kHz). Both
// kinds cross a lock-free single-producer/single-consumer queue (spsc_queue.hpp), so both
// are plain, fixed-size, trivially copyable data: no pointer, no heap, nothing to construct
// or destroy. A message is one flat struct with a `kind`; only the fields that kind names
// are read (each field says which kinds use it). That costs some bytes per message (about
// 1.3 KB a command, 0.7 KB a report) and buys messages that can never be misread through
// the wrong member of a union.
//
// Every command carries the host's sequence number and gets exactly one acknowledgement
// report (ReportKind::ack) with the same number: the engine's Error (code, field, value,
// allowed range) or the result (the new EffectId, the pool, the effect's status). The
// device takes a command from its queue only when the report queue has room for the ack,
// so acks are never dropped; a host that stops reading reports stalls its own commands.
//
// Force-profile samples (§6.6.d) are too many for one message, and the loop must not
// allocate to receive them. They travel ahead of their create or update in stage_samples
// commands of up to kSamplesPerCommand samples each, which the device appends to a fixed
// staging buffer (the size of the engine's sample store); the next create or update of a
// force profile takes the staged samples and empties the stage, whatever its outcome.
// HostLink (host_link.hpp) does the chunking.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "feel/axis.hpp"
#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/runtime/safety.hpp"
#include "feel/status.hpp"

namespace feel::runtime {

// ---------------------------------------------------------------------------------------
// Commands: host -> device.

enum class CommandKind : uint8_t {
    keep_alive,        // nothing but "the host is here" (the host-link watchdog, safety.hpp)
    create,            // params (+ staged samples): download an effect (CreateEffect + Download)
    update,            // effect, params, field_mask, restart (+ staged samples): SetParameters
    start,             // effect, iterations, solo: Start
    stop,              // effect: Stop
    destroy,           // effect: free its slot and bytes (Unload)
    status,            // effect: GetEffectStatus; the ack carries the EffectStatus
    set_gain,          // value = device gain 0..10000 (DIPROP_FFGAIN)
    device_control,    // control (SendForceFeedbackCommand, DISFFC_*)
    query_pool,        // the ack carries the PoolInfo
    assign_reflex,     // effect: make its reflex from its own trigger fields (§6.3)
    remove_reflex,     // effect: remove its reflex; the effect stays
    set_idf,           // idf: the player's IDF choice (§1.2.d)
    configure_safety,  // safety: a new SafetyConfig (restarts the monitor: a fade-in follows)
    set_report_rate,   // value = host report rate, Hz, 100..min(1000, loop rate)
    stage_samples,     // sample_offset, sample_count, samples: force-profile samples ahead
    // stream_axis_count, stream_force: one sample of the force the host streams (§2.4,
    // "closing the loop from the host"); the device reconstructs a smooth force from the
    // samples and adds it to the effects' (force_stream.hpp). Sent at up to 1 kHz.
    stream_force,
    // The host is gone (disconnected or detached): the forces fade out as for a silent
    // host (SafetyConfig::host_fade_out_us) and every effect stops. No later command is
    // applied, and the ack comes, only once the fade has ended; with no force on the
    // motors there is nothing to fade and the ack comes at once.
    release_host,
};
inline constexpr int kCommandKindCount = 18;

// DirectInput's DISFFC_* device commands.
enum class DeviceControl : uint8_t {
    actuators_on,   // DISFFC_SETACTUATORSON: forces pass again, faded in (safety.hpp)
    actuators_off,  // DISFFC_SETACTUATORSOFF: no force; effects play on
    stop_all,       // DISFFC_STOPALL: stop every effect; they stay resident
    reset,          // DISFFC_RESET: free every effect and reflex, gain 10000, not paused,
                    // actuators on. The safety state (dead-man, hands-off, fade) is the
                    // hardware's and stays as it is.
    pause,          // DISFFC_PAUSE: every effect clock stands still, no force
    resume,         // DISFFC_CONTINUE
};
inline constexpr int kDeviceControlCount = 6;

// Command::iterations for "the effect's own iteration count" (DirectInput's Start(1, 0)
// plays the effect as downloaded).
inline constexpr int32_t kEffectIterations = 0;
// Samples one stage_samples command carries at most.
inline constexpr int32_t kSamplesPerCommand = 128;

struct Command {
    CommandKind kind = CommandKind::keep_alive;
    uint32_t sequence = 0;        // the host's number for this command, echoed by its ack
    EffectId effect{};            // update, start, stop, destroy, status, assign/remove_reflex
    EffectParams params{};        // create, update
    uint32_t field_mask = 0;      // update: effect_field::k* bits
    bool restart = false;         // update: DIEP_START, (re)start after the update
    // start: 1..255 or kInfiniteIterations for this play only, or kEffectIterations (0)
    // for the effect's own count.
    int32_t iterations = kEffectIterations;
    bool solo = false;            // start: stop every other effect first (DIES_SOLO)
    int32_t value = 0;            // set_gain: 0..10000; set_report_rate: Hz
    DeviceControl control = DeviceControl::stop_all;  // device_control
    IdfSettings idf{};            // set_idf
    SafetyConfig safety{};        // configure_safety
    // stage_samples: this chunk's samples go at [sample_offset, sample_offset +
    // sample_count) of the stage. sample_offset 0 starts a new stage; any other must be the
    // count already staged (chunks in order, none missing). sample_count 1..kSamplesPerCommand.
    int32_t sample_offset = 0;
    int32_t sample_count = 0;
    int16_t samples[kSamplesPerCommand] = {};  // -10000..10000, interleaved by channel
    // stream_force: the device's axis count (must be the device's, 1..kMaxAxes) and the
    // streamed force on each axis in the device's order (x, y, z, rx, ry, rz), normalized
    // -10000..10000, physical sign (+ pushes toward +axis). Entries past the count are 0.
    int32_t stream_axis_count = 0;
    int16_t stream_force[kMaxAxes] = {};
};
static_assert(std::is_trivially_copyable_v<Command>);

// Builders. They only fill fields; nothing is checked until the device applies the command.
[[nodiscard]] inline Command make_keep_alive(uint32_t sequence) noexcept {
    Command c;
    c.kind = CommandKind::keep_alive;
    c.sequence = sequence;
    return c;
}
[[nodiscard]] inline Command make_release_host(uint32_t sequence) noexcept {
    Command c;
    c.kind = CommandKind::release_host;
    c.sequence = sequence;
    return c;
}
[[nodiscard]] inline Command make_create(uint32_t sequence, const EffectParams& params) noexcept {
    Command c;
    c.kind = CommandKind::create;
    c.sequence = sequence;
    c.params = params;
    return c;
}
[[nodiscard]] inline Command make_update(uint32_t sequence, EffectId effect, const EffectParams& params,
                                         uint32_t field_mask, bool restart) noexcept {
    Command c;
    c.kind = CommandKind::update;
    c.sequence = sequence;
    c.effect = effect;
    c.params = params;
    c.field_mask = field_mask;
    c.restart = restart;
    return c;
}
[[nodiscard]] inline Command make_start(uint32_t sequence, EffectId effect, int32_t iterations = kEffectIterations,
                                        bool solo = false) noexcept {
    Command c;
    c.kind = CommandKind::start;
    c.sequence = sequence;
    c.effect = effect;
    c.iterations = iterations;
    c.solo = solo;
    return c;
}
// stop, destroy, status, assign_reflex, remove_reflex: the commands about one effect.
[[nodiscard]] inline Command make_effect_command(CommandKind kind, uint32_t sequence, EffectId effect) noexcept {
    Command c;
    c.kind = kind;
    c.sequence = sequence;
    c.effect = effect;
    return c;
}
// set_gain (gain 0..10000), set_report_rate (Hz).
[[nodiscard]] inline Command make_value_command(CommandKind kind, uint32_t sequence, int32_t value) noexcept {
    Command c;
    c.kind = kind;
    c.sequence = sequence;
    c.value = value;
    return c;
}
[[nodiscard]] inline Command make_device_control(uint32_t sequence, DeviceControl control) noexcept {
    Command c;
    c.kind = CommandKind::device_control;
    c.sequence = sequence;
    c.control = control;
    return c;
}
[[nodiscard]] inline Command make_query_pool(uint32_t sequence) noexcept {
    Command c;
    c.kind = CommandKind::query_pool;
    c.sequence = sequence;
    return c;
}
[[nodiscard]] inline Command make_set_idf(uint32_t sequence, IdfSettings settings) noexcept {
    Command c;
    c.kind = CommandKind::set_idf;
    c.sequence = sequence;
    c.idf = settings;
    return c;
}
[[nodiscard]] inline Command make_configure_safety(uint32_t sequence, const SafetyConfig& config) noexcept {
    Command c;
    c.kind = CommandKind::configure_safety;
    c.sequence = sequence;
    c.safety = config;
    return c;
}

// One streamed force sample, `force` on each of the device's axes in order (±10000,
// physical sign). More than kMaxAxes values cannot be carried: the count is kept as given
// (so the device refuses it by name) and only the first kMaxAxes values are copied.
[[nodiscard]] inline Command make_stream_force(uint32_t sequence, std::span<const int16_t> force) noexcept {
    Command c;
    c.kind = CommandKind::stream_force;
    c.sequence = sequence;
    c.stream_axis_count = static_cast<int32_t>(force.size());
    for (std::size_t a = 0; a < force.size() && a < static_cast<std::size_t>(kMaxAxes); ++a) {
        c.stream_force[a] = force[a];
    }
    return c;
}

// ---------------------------------------------------------------------------------------
// Reports: device -> host.

enum class ReportKind : uint8_t {
    ack,      // one per command: its outcome (Report::ack)
    state,    // at the report rate: positions, buttons, effects, safety (Report::state)
    dynamic,  // a dynamic's interim or final report, forwarded (Report::dynamic)
};

// The state of one effect as the host sees it (DirectInput's DIEGES_*, and more).
enum class ReportedEffectState : uint8_t {
    stopped,   // resident, not playing (never started, stopped, or finished)
    playing,   // started: producing force, or about to at the next tick (also while paused)
    delayed,   // started, inside its start delay
    // Played by the host on the device's behalf (the host-emulation issue: an effect the
    // device cannot hold or render). The device itself never reports it.
    emulated,
};

// What a command did.
struct CommandAck {
    uint32_t sequence = 0;                      // the command's
    CommandKind command = CommandKind::keep_alive;
    Error error{};                              // ok, or what was refused and why
    int64_t t_us = 0;                           // the tick that applied it, µs of device time
    EffectId effect{};                          // create: the new effect; others: the command's
    // create, destroy, query_pool, device_control reset: the pool after the command.
    PoolInfo pool{};
    // start, stop, update, status: the effect's status after the command (state free for
    // a stale handle).
    EffectStatus status{};
    int32_t staged_samples = 0;                 // stage_samples: samples staged after it
};

// One resident effect in a state report.
struct EffectStateEntry {
    EffectId id{};
    ReportedEffectState state = ReportedEffectState::stopped;
};

// The resident effects one state report lists at most; more are spread over pages.
inline constexpr int32_t kEffectsPerReport = 32;

// The device's state, at the host report rate (issue 5, §9).
struct StateReport {
    int64_t t_us = 0;                 // the tick it describes, µs of device time
    uint32_t report_number = 0;       // state reports since the runtime began (all pages share it)
    int32_t axis_count = 0;           // the device's axes, x, y, z, rx, ry, rz in order
    // The position for the host: sensed, with the player's IDF classes filtered out and
    // held at walls with clipping on (§1.2.d, §3.7). Normalized ±10000.
    float position[kMaxAxes] = {};
    // The handle's velocity, the engine's estimate from the sensed position, normalized
    // units/s (IDF filters positions only).
    float velocity[kMaxAxes] = {};
    uint32_t buttons = 0;             // bit i = button i+1 pressed
    uint32_t hats = 0;                // bit h-1 = hat switch h pushed off center
    float force[kMaxAxes] = {};       // what the motors got this tick, normalized ±10000
    SafetyState safety{};             // dead-man, fade, hands-off, host watchdog
    bool paused = false;              // DISFFC_PAUSE in force
    bool actuators_enabled = true;    // DISFFC_SETACTUATORSON/OFF
    int32_t gain = kFullScale;        // device gain, 0..10000
    int32_t playing_effects = 0;      // effects producing force this tick
    int32_t resident_effects = 0;     // effects created and not freed
    // The resident effects in slot order, kEffectsPerReport per page: this page lists
    // entries [page·kEffectsPerReport, page·kEffectsPerReport + effect_count).
    int32_t page = 0;                 // 0..pages-1
    int32_t pages = 1;                // >= 1
    int32_t effect_count = 0;         // entries of effects[] in use
    EffectStateEntry effects[kEffectsPerReport] = {};
    // Reports the device could not post since it began (the queue was full): state
    // reports and dynamics' reports. Acks are never dropped.
    uint64_t dropped_reports = 0;
};

struct Report {
    ReportKind kind = ReportKind::state;
    CommandAck ack{};          // kind ack
    StateReport state{};       // kind state
    DynamicReport dynamic{};   // kind dynamic
};
static_assert(std::is_trivially_copyable_v<Report>);

// Names for messages and logs.
[[nodiscard]] const char* command_kind_name(CommandKind kind) noexcept;
[[nodiscard]] const char* device_control_name(DeviceControl control) noexcept;
[[nodiscard]] const char* reported_effect_state_name(ReportedEffectState state) noexcept;

}  // namespace feel::runtime
