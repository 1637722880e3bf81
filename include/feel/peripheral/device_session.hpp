// feel::peripheral — the device's side of the protocol: host reports in, runtime commands
// out, runtime reports back as HID input reports (docs/peripheral.md).
//
// A DeviceSession is the "USB side" of a feel device's local processor, without a thread.
// The caller (the Peripheral's service thread, a test, the fuzzer) hands it the frames the
// host sent (offer), and calls pump() to let it work: pump() reads the runtime's reports
// off the HostLink, applies the acks, turns queued frames into runtime commands, and
// appends the frames for the host (answers, feature replies, input reports) to `out`.
//
// Effect blocks. Effects are named by their PID Effect Block Index, 1..effect_slots. Each
// block holds the EffectParams being assembled from the host's type blocks (the shadow),
// which type blocks have arrived, whether the effect exists in the engine (committed) and
// its runtime EffectId. Create New Effect allocates a block; the first accepted Set Effect
// creates the effect in the runtime, later ones update it with the fields that changed; a
// refused Set Effect leaves the committed effect as it was and rolls the shadow back to it.
// Block Free and a device reset free blocks.
//
// Answers. Every output report and feature set gets exactly one CommandStatus input report
// with its sequence (Download Force Sample only when refused), in the order the host sent
// them; feature gets and the descriptor get their reply in that same order. A report the
// session can judge alone (a bad block, a type block that does not fit the block's type)
// is answered without touching the runtime; the others are answered when the runtime's
// ack arrives, with the engine's Error (field, value, range).
//
// Ordering and fences. Commands that change the block table (Set Effect, Block Free,
// device reset) are fences: one is sent only when no command is in flight, and nothing
// after it is processed until its ack is back, so the table always matches the engine.
// The other commands (start, stop, gain, force samples ...) are pipelined.
//
// Bounded memory. The inbox holds kInboxFrames frames and the answers in flight at most
// the runtime's command queue capacity: beyond that offer() refuses (the caller stops
// reading its transport, which pushes back on the host) and pump() leaves frames queued.
// A hostile host can fill these and nothing else.
//
// Threads: none inside. One thread uses a session and its HostLink (the link's single
// producer and single consumer). Exceptions: offer() and pump() throw what allocation
// throws (std::bad_alloc), and std::invalid_argument from protocol::encode() only if the
// session made a report outside its wire ranges (a bug; the fuzzer looks for it). Nothing
// here is real-time code.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "feel/engine.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/reports.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/transport/transport.hpp"

namespace feel::peripheral {

// The joystick inputs a device with these capabilities reports (its axes in order, its
// buttons and hats): the layout of its Joystick Input and of its descriptor's joystick
// part (protocol::report_descriptor(layout)).
[[nodiscard]] protocol::JoystickLayout joystick_layout(const runtime::Capabilities& caps) noexcept;

// The local loop's figures a DeviceStatus report carries, from whoever runs the loop
// (DeviceRuntime::stats() for a Peripheral). Without a provider the session reports the
// configured rate and zeros.
struct LoopFigures {
    int32_t loop_rate_hz = 0;             // nominal, Hz
    int64_t overruns = 0;                 // loop overruns since the device started
    int64_t measured_rate_millihz = 0;    // ticks per second over the last second, mHz
};
using LoopFiguresProvider = std::function<LoopFigures()>;

// Frames the session holds before it refuses more (offer() returns false).
inline constexpr std::size_t kInboxFrames = 64;

// What one block holds, for tests and tools.
struct BlockView {
    uint16_t block = 0;                   // 1..effect_slots
    EffectType type = EffectType::constant;
    bool committed = false;               // exists in the engine
    EffectId effect{};                    // valid when committed
    EffectParams committed_params{};      // what the engine has (when committed)
    EffectParams shadow{};                // what the next Set Effect would commit
};

struct SessionCounters {
    uint64_t frames_received = 0;     // frames offered and taken
    uint64_t reports_decoded = 0;     // host reports that decoded, and valid feature gets and descriptor gets
    uint64_t reports_refused = 0;     // host frames answered with an error status
    uint64_t frames_sent = 0;         // frames appended to pump()'s out
    uint64_t runtime_commands = 0;    // commands sent to the runtime
    uint64_t unknown_acks = 0;        // acks of no command of this session (ignored)
    uint64_t host_resets = 0;         // host_gone() calls
};

class DeviceSession {
public:
    // `caps` and `config` describe the device behind `link` (capabilities_for(profile),
    // the runtime's RuntimeConfig); the session keeps copies. `link` must outlive the
    // session. Throws std::invalid_argument when caps and config disagree on the slots.
    DeviceSession(const runtime::Capabilities& caps, const runtime::RuntimeConfig& config,
                  runtime::HostLink& link, LoopFiguresProvider loop_figures = {});
    ~DeviceSession();
    DeviceSession(const DeviceSession&) = delete;
    DeviceSession& operator=(const DeviceSession&) = delete;

    // Takes a frame from the host. False (frame not taken) while the inbox is full: call
    // pump() and offer it again.
    bool offer(transport::Frame frame);
    [[nodiscard]] bool accepting() const noexcept;

    // Reads the runtime's reports, applies acks, processes queued frames as far as the
    // fences and the command queue allow, and appends what goes to the host to `out`.
    void pump(std::vector<transport::Frame>& out);

    // The host went away (disconnected, replaced): its queued frames and unsent answers
    // are dropped, and the device is reset (every effect stopped and freed, gain, report
    // rate and IDF back to their start values) as soon as the commands in flight are
    // acked, so that the next host finds a clean device. pump() carries it out.
    void host_gone();

    // Nothing queued, nothing in flight, no answer waiting.
    [[nodiscard]] bool idle() const noexcept;
    // Commands sent to the runtime whose acks have not arrived.
    [[nodiscard]] int32_t in_flight() const noexcept;

    // The block table.
    [[nodiscard]] int32_t block_capacity() const noexcept;
    [[nodiscard]] int32_t allocated_blocks() const noexcept;
    [[nodiscard]] int32_t committed_blocks() const noexcept;
    [[nodiscard]] std::optional<BlockView> block(uint16_t index) const;
    // The effect memory as the last runtime ack that carried it said.
    [[nodiscard]] PoolInfo pool() const noexcept;

    [[nodiscard]] const SessionCounters& counters() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace feel::peripheral
