// feel::host — DeviceCore: one open device's connection, its I/O thread and its state.
//
// Design. The host talks to a device over one transport::Connection (sim:, unix:, tcp:).
// Two kinds of thread use it:
//
//  * the caller's thread (a game's), through Device and Effect. Its calls are serialized
//    by `call_mu`, so that a multi-report transaction (Create New Effect, Block Load, the
//    type's blocks, Set Effect) is never interleaved with another caller's. A call sends
//    its reports and waits on `cv` for the answer the I/O thread files for it: the
//    CommandStatus with the report's sequence number, or the feature/descriptor reply;
//  * the I/O thread, the only reader of the connection. It files answers for waiting
//    callers, keeps the latest input state, tracks which effects play, calls the
//    subscribers of dynamics' reports, sends a keep-alive after 100 ms of silence (the
//    device's host watchdog trips after 1 s, safety.hpp) and runs host emulation: on a
//    device without local reflexes it starts trigger effects itself on the press edges it
//    sees in the joystick reports (§1.2.c).
//
// Both threads send, so sends go through `send_mu` (a Connection allows one sender and
// one receiver at a time). The I/O thread never takes `call_mu` and never waits for an
// answer: what it sends (keep-alives, emulated starts) is fire-and-forget, and their
// CommandStatus answers find no waiter and are dropped, except a refused force-stream
// sample, which is kept for the next stream_force() call.
//
// Lock order: call_mu, then mu; dispatch_mu is taken alone (by the I/O thread while it
// calls subscribers, and by subscribe/unsubscribe). Nothing is called back with mu held.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "feel/host/device.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "feel/protocol/reports.hpp"
#include "feel/transport/transport.hpp"

namespace feel::host::emulation {
class HostEmulation;
}

namespace feel::host {

using Clock = std::chrono::steady_clock;

// What the host keeps of one effect it created (Effect points at it).
struct EffectRecord {
    uint64_t key = 0;                 // the core's name for it, never reused
    // The type, apart from params: it never changes, so Effect::type() reads it on any thread
    // without mu while a CommandQueue's thread rewrites params (ThreadSanitizer's finding).
    EffectType type = EffectType::constant;
    EffectParams params{};            // as the game gave them (trigger included)
    std::vector<int16_t> samples;     // force_profile only
    uint16_t block = 0;               // the device's block while downloaded, else 0
    // Why it is not downloaded (unload, device reset, close), for invalid_handle messages.
    std::string not_downloaded_reason = "the effect is not downloaded (call download())";
    bool closed = false;              // its device was closed: every call is invalid_handle

    // Host emulation of the trigger (§1.2.c), on a device without local reflexes. Guarded
    // by DeviceCore::mu; read and written by the I/O thread.
    bool emulate_trigger = false;     // the device got it without its trigger; the host plays it
    bool trigger_down = false;        // the trigger's state at the last joystick report
    bool host_started = false;        // the current play was started by the emulation
    Clock::time_point next_repeat{};  // when a held trigger restarts it next
    uint64_t emulated_starts = 0;     // starts the emulation sent

    // What the device last said of it (PidState, DeviceStatus pages). Guarded by mu.
    bool device_playing = false;

    // Host rendering (§1.2.c, emulation/host_emulation.hpp): the device does not play this
    // type, so the host's engine does. Fixed at creation, like `type`.
    bool host_rendered = false;
    EffectId host_id{};               // the host engine's effect while resident; guarded by mu
};

struct Subscriber {
    uint64_t effect_key = 0;  // 0: every effect of the device
    DynamicCallback callback;
};

struct InputQueue;

struct DeviceCore {
    DeviceCore(std::unique_ptr<transport::Connection> connection, std::string address, OpenOptions options);
    ~DeviceCore();
    DeviceCore(const DeviceCore&) = delete;
    DeviceCore& operator=(const DeviceCore&) = delete;

    // Starts the I/O thread (once, after construction).
    void start();
    // Frees the effects (when `free_effects` and still connected), closes the connection,
    // joins the I/O thread, invalidates every Effect. Harmless twice.
    void close(bool free_effects);

    // --- round trips (the caller holds call_mu) --------------------------------------------

    // Sends an output report (or a feature report set) numbered with a fresh sequence and
    // waits for its CommandStatus. The Status is the transport's or the timeout's; the
    // device's own refusal is in the returned report (map it with command_status()).
    Result<protocol::CommandAnswer> transact(protocol::AnyReport report, transport::FrameKind kind);
    // Like transact(), then maps the device's refusal to a Status prefixed with `what`.
    Status command(protocol::AnyReport report, const std::string& what,
                   transport::FrameKind kind = transport::FrameKind::output_report);
    // GET_REPORT(Feature) of one report id; the decoded reply.
    Result<protocol::AnyReport> get_feature(protocol::ReportId id);
    // GET_DESCRIPTOR(Report).
    Result<std::vector<uint8_t>> get_descriptor();
    // Sends without waiting for the answer (keep-alive, emulated starts, force samples).
    Status send_unanswered(protocol::AnyReport report);

    // --- state --------------------------------------------------------------------------

    [[nodiscard]] bool is_connected() const;
    // What a disconnection's reason says when the device refused this host as busy (open()
    // retries those for OpenOptions::busy_wait).
    static constexpr std::string_view kBusyReason = "is in use by another host";
    // disconnected, naming why (the peer closed, busy, close()).
    [[nodiscard]] Status disconnected_status(const std::string& what) const;
    [[nodiscard]] std::chrono::milliseconds timeout() const noexcept { return options.timeout; }

    // Records.
    std::shared_ptr<EffectRecord> add_record(EffectParams params, std::vector<int16_t> samples);
    void remove_record(uint64_t key);
    // The block is downloaded: file it and arm the emulation (trigger state as it is now,
    // so a trigger held at arming is not a press).
    void set_downloaded(EffectRecord& record, uint16_t block, bool emulate_trigger);
    // The block is gone: forget it.
    void set_not_downloaded(EffectRecord& record, std::string reason);

    uint64_t subscribe(uint64_t effect_key, DynamicCallback callback);
    void unsubscribe(uint64_t id) noexcept;
    // Per-report input subscribers (input_queue.cpp): forget one (takes mu).
    void unsubscribe_input(const InputQueue* queue) noexcept;

    // --- for CommandQueue (command_queue.cpp), which runs an Effect's calls later ----------

    // What an Effect refers to (both empty for an empty Effect).
    static std::shared_ptr<DeviceCore> core_of(const Effect& effect) { return effect.core_; }
    static std::shared_ptr<EffectRecord> record_of(const Effect& effect) { return effect.record_; }
    // Runs f(Effect&) on a borrowed Effect made of (core, record): it is the game's effect
    // for the call, and lets go of both afterwards without unloading anything.
    template <class F>
    static auto with_effect(std::shared_ptr<DeviceCore> core, std::shared_ptr<EffectRecord> record, F&& f) {
        Effect borrowed;
        borrowed.core_ = std::move(core);
        borrowed.record_ = std::move(record);
        struct Release {
            Effect& e;
            ~Release() {
                e.core_.reset();
                e.record_.reset();
            }
        } release{borrowed};
        return f(borrowed);
    }

    // --- fixed at open ---------------------------------------------------------------------
    const std::string address;
    const OpenOptions options;
    DeviceCaps caps{};
    std::vector<uint8_t> descriptor;

    // --- synchronization -------------------------------------------------------------------
    std::mutex call_mu;              // one caller transaction at a time
    std::mutex send_mu;              // one sender at a time
    mutable std::mutex mu;           // everything below that the I/O thread touches
    protocol::JoystickLayout joystick;  // the device's Joystick Input, read from its descriptor
    std::condition_variable cv;      // answers, input rounds, disconnection
    std::recursive_mutex dispatch_mu;  // subscribers (held while calling them)

    // Guarded by mu.
    bool connected = true;
    bool closed = false;
    bool busy = false;               // the device said `busy` before it closed
    std::string disconnect_reason;
    std::unordered_map<uint32_t, std::optional<protocol::CommandAnswer>*> waiting;
    int expected_feature = -1;       // the report id a get_feature waits for, -1 none
    std::optional<std::vector<uint8_t>> feature_reply;
    std::optional<protocol::CommandAnswer> feature_refusal;  // a get the device refused
    bool descriptor_wanted = false;
    std::optional<std::vector<uint8_t>> descriptor_reply;
    InputState input{};
    uint64_t input_rounds = 0;       // complete state rounds (joystick + last status page)
    std::vector<std::shared_ptr<InputQueue>> input_queues;  // subscribe_input's, each round goes to all
    // The state round being gathered. The device sends a round as Joystick Input, Device
    // Status, then Effect States pages carrying the status's report number
    // (docs/protocol.md); a round is published only when all three came in that order, so
    // a frame lost before it (or a joystick that did not decode before the layout was
    // known) cannot pair one tick's status with the next tick's joystick for good.
    bool round_has_joystick = false;   // this round's Joystick Input came
    bool round_has_status = false;     // its Device Status came after it
    uint32_t round_report_number = 0;  // that status's report number
    std::map<uint64_t, std::shared_ptr<EffectRecord>> records;
    std::unordered_map<uint16_t, uint64_t> by_block;
    uint64_t next_key = 1;
    std::optional<Status> stream_error;  // a refused force sample, for the next call
    uint64_t unexpected_frames = 0;      // frames that were not the protocol (ignored)
    std::string last_protocol_problem;
    // The host-rendered effects (emulation/host_emulation.hpp), made at the first one.
    std::shared_ptr<emulation::HostEmulation> emulation;

    // A dynamic's event to its subscribers: those of effect `key` (0: none known) and those of
    // every effect. Device-rendered (on_dynamic) and host-rendered (host emulation) alike.
    void dispatch_dynamic(uint64_t key, const DynamicEvent& event);

    // Guarded by dispatch_mu.
    std::map<uint64_t, Subscriber> subscribers;
    uint64_t next_subscriber = 1;

    // The I/O thread's alone (no lock): a refusal's text until its CommandStatus, and a
    // dynamic's report arriving in several DynamicReports (more than four axes) until its
    // last part.
    protocol::CommandAnswerJoiner error_text;
    std::optional<protocol::DynamicReportReport> dynamic_first_part;

private:
    void run() noexcept;                        // the I/O thread
    void handle(const transport::Frame& frame);
    void on_command_status(const protocol::CommandStatusReport& status);
    void on_joystick(const protocol::JoystickInputReport& report);
    void on_device_status(const protocol::DeviceStatusReport& report);
    void on_effect_states(const protocol::EffectStatesReport& report);
    void on_pid_state(const protocol::PidStateReport& report);
    void on_dynamic(const protocol::DynamicReportReport& report);
    // Emulated starts due now (press edges are found in on_joystick): held triggers whose
    // repeat interval ran out. Appends their blocks. Caller holds mu.
    void collect_repeats(Clock::time_point now, std::vector<uint16_t>& blocks);
    void send_emulated_starts(const std::vector<uint16_t>& blocks);
    void mark_disconnected(const std::string& reason);
    // A round is complete: `input` goes to every input subscriber. Caller holds mu.
    void publish_input_round() noexcept;
    void note_protocol_problem(std::string what);
    Status send_frame(transport::Frame frame);
    uint32_t next_sequence() noexcept;

    std::unique_ptr<transport::Connection> connection_;
    std::thread io_;
    std::atomic<bool> stopping_{false};
    std::atomic<uint32_t> sequence_{1};
    std::atomic<int64_t> last_send_ns_{0};  // Clock time of the last frame sent
};

}  // namespace feel::host
