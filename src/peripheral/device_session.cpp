// The device session: host frames in, runtime commands out, answers and input reports back.
//
// Design. The session is a small state machine between two asynchronous parties: a host
// that may send anything at any time, and a runtime that answers each command one tick or
// more later. Three structures carry it:
//
//   inbox     the host's frames not processed yet (at most kInboxFrames);
//   pending   one entry per processed frame (and per internal command), in the host's
//             order: the answer to send, and for a frame that became a runtime command,
//             the command's sequence and what its ack does to the block table. At most
//             the runtime's command queue capacity entries;
//   blocks    the effect block table (block_table.hpp).
//
// A frame is processed in one step: decoded, checked, and either answered at once (its
// pending entry is complete) or turned into exactly one runtime command (its entry waits
// for the ack). Nothing in the session changes before that command is on the queue, so a
// full queue leaves the frame in the inbox for the next pump() with nothing half-done.
// Answers leave from the head of `pending` only, so they reach the host in its order
// even when an early command waits for the runtime while later reports were judged here.
//
// Fences. A commit (Set Effect), a Block Free of a committed block and a device reset
// change what the table says the engine holds. Each is sent only when no other command is
// in flight, and nothing after it is processed until its ack is back; then the table is
// updated from the ack (the EffectId of a create, the rollback of a refusal). So the table
// and the engine agree at every fence, and the session never guesses at an outcome. The
// other commands are pipelined: a 1 kHz force stream or a burst of starts costs no round
// trips.
//
// Force-profile samples. Custom Force Data reports go straight to the runtime's sample
// stage (one stage_samples command each). The session tracks which block the stage holds
// samples for and how many, and commits a force profile only with its complete samples
// staged; the runtime's create or update takes them (and empties the stage whatever the
// outcome).
#include "feel/peripheral/device_session.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "block_table.hpp"
#include "feel/protocol/codec.hpp"
#include "input_reports.hpp"
#include "report_translation.hpp"

namespace feel::peripheral {
namespace {

using protocol::ReportId;
using transport::Frame;
using transport::FrameKind;
using detail::Refusal;

// What a pending entry sends to the host once complete.
enum class Answer : uint8_t {
    status,            // a CommandStatus
    status_if_refused, // a CommandStatus only for an error (Download Force Sample)
    block_load,        // feature reply: BlockLoad
    pid_pool,          // feature reply: PidPool (after its query_pool ack)
    device_info,       // feature reply: DeviceInfo
    descriptor,        // descriptor reply
    none,              // an internal command: nothing
};

// What the ack of an entry's command does to the session.
enum class OnAck : uint8_t {
    nothing,
    commit_create,  // the block's first commit
    commit_update,  // a later commit
    free_block,     // Block Free of a committed block
    reset,          // device reset: every block freed
    pool,           // query_pool: the pool
    stage,          // stage_samples: a refusal breaks the stage
    report_rate,    // set_report_rate: the new rate
};

struct Pending {
    Answer answer = Answer::status;
    OnAck on_ack = OnAck::nothing;
    bool waiting = false;        // its command's ack has not arrived
    bool fence = false;
    bool discard = false;        // the host that sent it is gone: apply the ack, send nothing
    bool effect_status = false;  // copy the ack's EffectStatus into the answer
    uint32_t runtime_sequence = 0;
    uint16_t block = 0;
    int32_t value = 0;           // report_rate: the rate asked for
    protocol::CommandAnswer status{};
    protocol::BlockLoadReport block_load{};
};

// An internal command waiting for room: the reset after a host left, a pool query.
struct Internal {
    runtime::Command command{};
    OnAck on_ack = OnAck::nothing;
    bool fence = false;
};

// The outcome of processing one frame.
enum class Step : uint8_t { done, blocked };

Frame input_frame(FrameKind kind, const protocol::AnyReport& report) {
    return Frame{kind, protocol::encode(report)};
}

uint32_t clamp_u32(int64_t v) noexcept {
    return static_cast<uint32_t>(std::clamp<int64_t>(v, 0, std::numeric_limits<uint32_t>::max()));
}

uint16_t clamp_u16(int64_t v) noexcept { return static_cast<uint16_t>(std::clamp<int64_t>(v, 0, 65535)); }

}  // namespace

protocol::JoystickLayout joystick_layout(const runtime::Capabilities& caps) noexcept {
    protocol::JoystickLayout layout;
    layout.axis_count = static_cast<uint8_t>(std::clamp(caps.axis_count, 1, kMaxAxes));
    for (int a = 0; a < layout.axis_count; ++a) layout.axes[a] = caps.axes[a].axis;
    layout.button_count = static_cast<uint8_t>(std::clamp(caps.button_count, 0, 32));
    layout.hat_count = static_cast<uint8_t>(std::clamp(caps.hat_count, 0, 4));
    return layout;
}

struct DeviceSession::Impl {
    Impl(const runtime::Capabilities& c, const runtime::RuntimeConfig& cfg, runtime::HostLink& l,
         LoopFiguresProvider f)
        : caps(c), layout(joystick_layout(c)), descriptor(protocol::report_descriptor(layout)),
          config(cfg), link(&l), figures(std::move(f)),
          blocks(c.effect_slots, cfg.engine.max_effects),
          pending_capacity(static_cast<std::size_t>(std::max(cfg.command_capacity, 1))),
          report_rate_hz(cfg.report_rate_hz) {
        pool.total_bytes = c.pool_bytes;
        pool.free_bytes = c.pool_bytes;
        pool.max_effects = cfg.engine.max_effects;
        pool.free_effects = cfg.engine.max_effects;
        pool.max_dynamics = pool.free_dynamics =
            cfg.engine.max_dynamics == 0 ? cfg.engine.max_effects : cfg.engine.max_dynamics;
        pool.max_stateful_conditions = pool.free_stateful_conditions =
            cfg.engine.max_stateful_conditions == 0 ? cfg.engine.max_effects : cfg.engine.max_stateful_conditions;
        pool.total_samples = c.sample_memory;
        pool.free_samples = c.sample_memory;
        round_entries.reserve(static_cast<std::size_t>(cfg.engine.max_effects));
        playing_now.assign(static_cast<std::size_t>(blocks.capacity()) + 1, 0);
        // The engine's exact pool, in place of the estimate above, as soon as it answers.
        queue_internal(runtime::make_query_pool(0), OnAck::pool, false);
    }

    // ---- configuration
    runtime::Capabilities caps;
    protocol::JoystickLayout layout;  // the device's inputs: its Joystick Input and descriptor
    std::vector<uint8_t> descriptor;
    runtime::RuntimeConfig config;
    runtime::HostLink* link;
    LoopFiguresProvider figures;

    // ---- state
    detail::BlockTable blocks;
    std::deque<Frame> inbox;
    std::deque<Pending> pending;
    std::size_t pending_capacity;
    std::deque<Internal> internal;  // at most five: release, reset, report rate, IDF, pool query
    int32_t waiting = 0;            // pending entries whose ack has not arrived
    bool fence_in_flight = false;
    uint32_t next_sequence = 1;
    PoolInfo pool{};
    bool pool_query_queued = false;
    int32_t report_rate_hz;
    protocol::BlockLoadReport last_block_load{0, protocol::BlockLoadStatus::error, 0};
    // The runtime's sample stage, as far as the session's commands made it.
    uint16_t stage_block = 0;
    int32_t staged = 0;
    // The state report round being gathered (its pages), and what the host was told.
    bool round_open = false;
    runtime::StateReport round{};
    std::vector<runtime::EffectStateEntry> round_entries;
    std::vector<uint8_t> playing_now;  // [block]: playing in the round being sent
    bool flags_sent = false;
    protocol::PidStateReport last_flags{};
    SessionCounters counters{};
    runtime::Report incoming{};  // the runtime report being read (1 KB: not on the stack)

    // ------------------------------------------------------------------------------------
    // Internal commands.

    void queue_internal(const runtime::Command& command, OnAck on_ack, bool fence) {
        if (on_ack == OnAck::pool) {
            if (pool_query_queued) return;
            pool_query_queued = true;
        }
        internal.push_back(Internal{command, on_ack, fence});
    }

    bool pending_full() const noexcept { return pending.size() >= pending_capacity; }

    // Sends `command` numbered with the session's counter; false (nothing sent) when the
    // queue is full.
    bool send(runtime::Command command, uint32_t& sequence) {
        command.sequence = next_sequence;
        if (!link->send(command)) return false;
        sequence = next_sequence++;
        ++counters.runtime_commands;
        return true;
    }

    void send_internal() {
        while (!internal.empty() && !pending_full()) {
            Internal& next = internal.front();
            if (next.fence && waiting > 0) return;
            if (fence_in_flight) return;
            uint32_t sequence = 0;
            if (!send(next.command, sequence)) return;
            Pending p;
            p.answer = Answer::none;
            p.on_ack = next.on_ack;
            p.waiting = true;
            p.fence = next.fence;
            p.runtime_sequence = sequence;
            push_waiting(std::move(p));
            internal.pop_front();
        }
    }

    void push_waiting(Pending p) {
        ++waiting;
        if (p.fence) fence_in_flight = true;
        pending.push_back(std::move(p));
    }

    // ------------------------------------------------------------------------------------
    // Runtime reports.

    void drain_runtime(std::vector<Frame>& out) {
        while (link->poll(incoming)) {
            switch (incoming.kind) {
                case runtime::ReportKind::ack: on_ack(incoming.ack); break;
                case runtime::ReportKind::state: on_state(incoming.state, out); break;
                case runtime::ReportKind::dynamic: on_dynamic(incoming.dynamic, out); break;
            }
        }
    }

    void on_ack(const runtime::CommandAck& ack) {
        auto it = std::find_if(pending.begin(), pending.end(), [&](const Pending& p) {
            return p.waiting && p.runtime_sequence == ack.sequence;
        });
        if (it == pending.end()) {
            ++counters.unknown_acks;
            return;
        }
        Pending& p = *it;
        p.waiting = false;
        --waiting;
        if (p.fence) fence_in_flight = false;
        if (!ack.error.ok()) detail::fill_error(p.status, ack.error);
        if (p.effect_status) detail::fill_effect_status(p.status, ack.status);
        apply_ack(p, ack);
    }

    void apply_ack(Pending& p, const runtime::CommandAck& ack) {
        const bool ok = ack.error.ok();
        switch (p.on_ack) {
            case OnAck::nothing: break;
            case OnAck::commit_create: {
                pool = ack.pool;
                detail::Block* b = blocks.find(p.block);
                if (b == nullptr) break;
                if (ok) {
                    blocks.commit(p.block, ack.effect);
                    b->committed = b->shadow;
                    b->host_saw_playing = false;
                } else {
                    roll_back(*b);
                }
                break;
            }
            case OnAck::commit_update: {
                detail::Block* b = blocks.find(p.block);
                if (b == nullptr) break;
                if (ok) {
                    b->committed = b->shadow;
                    // An update moves bytes of the pool; its ack does not carry the pool.
                    queue_internal(runtime::make_query_pool(0), OnAck::pool, false);
                } else {
                    roll_back(*b);
                }
                break;
            }
            case OnAck::free_block:
                // Freed in the engine, or already gone from it (invalid_handle): either way
                // the block no longer names an effect.
                if (ok || ack.error.code == ErrorCode::invalid_handle) blocks.free(p.block);
                pool = ack.pool;
                break;
            case OnAck::reset:
                if (ok) {
                    blocks.clear();
                    stage_block = 0;
                    staged = 0;
                    pool = ack.pool;
                }
                break;
            case OnAck::pool:
                pool_query_queued = false;
                if (ok) pool = ack.pool;
                break;
            case OnAck::stage:
                if (!ok) {
                    stage_block = 0;
                    staged = 0;
                }
                break;
            case OnAck::report_rate:
                if (ok) report_rate_hz = p.value;
                break;
        }
    }

    // A refused commit: the block is as it was before the transaction began.
    static void roll_back(detail::Block& b) {
        b.shadow = b.committed;
        if (!b.is_committed) b.arrived = detail::Arrivals{};
    }

    void on_state(const runtime::StateReport& s, std::vector<Frame>& out) {
        if (s.page == 0) {
            round_open = true;
            round = s;
            round_entries.clear();
        } else if (!round_open || s.report_number != round.report_number) {
            round_open = false;  // a page of a round whose start was not seen
            return;
        }
        const int32_t count = std::clamp(s.effect_count, 0, runtime::kEffectsPerReport);
        for (int32_t i = 0; i < count && round_entries.size() < round_entries.capacity(); ++i) {
            round_entries.push_back(s.effects[i]);
        }
        if (s.page + 1 >= s.pages) {
            round_open = false;
            emit_round(out);
        }
    }

    void emit_round(std::vector<Frame>& out) {
        out.push_back(Frame{FrameKind::input_report, protocol::encode(detail::joystick_input(round), layout)});

        // The resident effects by block; effects no block names (freed since) are left out.
        std::fill(playing_now.begin(), playing_now.end(), uint8_t{0});
        struct Entry {
            uint16_t block;
            runtime::ReportedEffectState state;
        };
        std::vector<Entry> listed;
        listed.reserve(round_entries.size());
        for (const runtime::EffectStateEntry& e : round_entries) {
            const uint16_t block = blocks.block_of(e.id);
            if (block == 0) continue;
            listed.push_back({block, e.state});
            if (detail::is_playing(e.state)) playing_now[block] = 1;
        }
        LoopFigures f;
        if (figures) f = figures();
        if (f.loop_rate_hz == 0) f.loop_rate_hz = config.loop_rate_hz;
        out.push_back(input_frame(FrameKind::input_report, detail::device_status(round, f)));
        protocol::EffectStatesReport status = detail::effect_states(round);
        constexpr std::size_t kPerPage = protocol::kEffectsPerStatusReport;
        constexpr std::size_t kMaxPages = 255;
        const std::size_t pages = std::clamp<std::size_t>((listed.size() + kPerPage - 1) / kPerPage, 1, kMaxPages);
        for (std::size_t page = 0; page < pages; ++page) {
            status.page = static_cast<uint8_t>(page);
            status.pages = static_cast<uint8_t>(pages);
            const std::size_t first = page * kPerPage;
            const std::size_t n = first < listed.size() ? std::min(kPerPage, listed.size() - first) : 0;
            status.effect_count = static_cast<uint8_t>(n);
            for (std::size_t i = 0; i < kPerPage; ++i) {
                status.effect_block[i] = i < n ? listed[first + i].block : uint16_t{0};
                status.effect_state[i] = i < n ? static_cast<uint8_t>(listed[first + i].state) : uint8_t{0};
            }
            out.push_back(input_frame(FrameKind::input_report, status));
        }

        // PID State: the device flags when they change, and each effect whose playing flag did.
        const protocol::PidStateReport flags = detail::pid_state(round, 0, false);
        if (!flags_sent || !same_flags(flags, last_flags)) {
            out.push_back(input_frame(FrameKind::input_report, flags));
            last_flags = flags;
            flags_sent = true;
        }
        for (int32_t index = 1; index <= blocks.capacity(); ++index) {
            detail::Block* b = blocks.find(static_cast<uint32_t>(index));
            if (b == nullptr || !b->is_committed) continue;
            const bool playing = playing_now[static_cast<std::size_t>(index)] != 0;
            if (playing == b->host_saw_playing) continue;
            b->host_saw_playing = playing;
            out.push_back(input_frame(FrameKind::input_report,
                                      detail::pid_state(round, static_cast<uint16_t>(index), playing)));
        }
    }

    static bool same_flags(const protocol::PidStateReport& a, const protocol::PidStateReport& b) noexcept {
        return a.device_paused == b.device_paused && a.actuators_enabled == b.actuators_enabled &&
               a.safety_switch == b.safety_switch && a.actuator_override == b.actuator_override &&
               a.actuator_power == b.actuator_power;
    }

    void on_dynamic(const DynamicReport& d, std::vector<Frame>& out) {
        const uint16_t block = blocks.block_of(d.effect);
        if (block == 0) return;  // an effect freed since: no block to name
        const int axes = std::clamp(d.axis_count, 0, kMaxAxes);
        int first = 0;
        do {
            out.push_back(input_frame(FrameKind::input_report, detail::dynamic_report(d, block, first)));
            first += protocol::kDynamicAxesPerReport;
        } while (first < axes);
    }

    // ------------------------------------------------------------------------------------
    // Answers.

    void emit_answers(std::vector<Frame>& out) {
        while (!pending.empty() && !pending.front().waiting) {
            Pending& p = pending.front();
            if (!p.discard) emit_answer(p, out);
            pending.pop_front();
        }
    }

    void emit_answer(Pending& p, std::vector<Frame>& out) {
        switch (p.answer) {
            case Answer::none: return;
            case Answer::status_if_refused:
                if (p.status.code == ErrorCode::ok) return;
                [[fallthrough]];
            case Answer::status:
                if (p.status.code != ErrorCode::ok) {
                    ++counters.reports_refused;
                    const protocol::ErrorTextParts text = protocol::error_text_parts(p.status);
                    for (std::size_t i = 0; i < text.count; ++i) {
                        out.push_back(input_frame(FrameKind::input_report, text.parts[i]));
                    }
                }
                out.push_back(input_frame(FrameKind::input_report,
                                          static_cast<const protocol::CommandStatusReport&>(p.status)));
                return;
            case Answer::block_load: {
                protocol::BlockLoadReport r = p.block_load;
                r.ram_pool_available = clamp_u32(pool.free_bytes);
                out.push_back(input_frame(FrameKind::feature_reply, r));
                return;
            }
            case Answer::pid_pool:
                out.push_back(input_frame(FrameKind::feature_reply, pid_pool_report()));
                return;
            case Answer::device_info:
                out.push_back(input_frame(FrameKind::feature_reply, device_info_report()));
                return;
            case Answer::descriptor: {
                out.push_back(Frame{FrameKind::descriptor_reply, descriptor});
                return;
            }
        }
    }

    protocol::PidPoolReport pid_pool_report() const {
        protocol::PidPoolReport r;
        r.ram_pool_size = clamp_u32(pool.total_bytes);
        r.simultaneous_effects_max = clamp_u16(blocks.capacity());
        r.device_managed_pool = true;
        r.shared_parameter_blocks = false;
        r.ram_pool_available = clamp_u32(pool.free_bytes);
        r.free_effects = clamp_u16(blocks.capacity() - blocks.allocated());
        r.sample_memory = clamp_u32(pool.total_samples);
        r.free_samples = clamp_u32(pool.free_samples);
        return r;
    }

    protocol::DeviceInfoReport device_info_report() const {
        protocol::DeviceInfoReport r;
        // A usable profile's texts fit the report whole (check_device_profile).
        static_assert(sizeof r.device == sim::kMaxProfileNameBytes + 1);
        static_assert(sizeof r.description == sim::kMaxProfileDescriptionBytes + 1);
        static_assert(sizeof r.firmware_version == sim::kMaxProfileNameBytes + 1);
        detail::copy_text(r.device, sizeof r.device, caps.device);
        detail::copy_text(r.description, sizeof r.description, caps.description);
        r.device_class = static_cast<uint8_t>(caps.device_class);
        r.axis_count = static_cast<uint8_t>(std::clamp(caps.axis_count, 1, kMaxAxes));
        constexpr double kMaxMicro = 2147483647.0;
        for (int a = 0; a < r.axis_count; ++a) {
            const runtime::AxisCapability& axis = caps.axes[a];
            protocol::AxisInfo& w = r.axes[a];
            w.axis = axis.axis;
            w.rotary = axis.kind == sim::AxisKind::rotary ? 1 : 0;
            w.half_travel_micro = static_cast<uint32_t>(std::llround(std::clamp(axis.half_travel * 1e6, 1.0, kMaxMicro)));
            w.max_force_milli = static_cast<uint32_t>(std::llround(std::clamp(axis.max_force * 1e3, 1.0, kMaxMicro)));
            w.sensor_counts = static_cast<uint32_t>(std::clamp(axis.sensor_counts, 2, 1 << 24));
        }
        r.button_count = static_cast<uint8_t>(std::clamp(caps.button_count, 0, 32));
        r.hat_count = static_cast<uint8_t>(std::clamp(caps.hat_count, 0, 4));
        r.dead_man_switch = caps.dead_man_switch;
        r.max_force = static_cast<uint16_t>(std::clamp(caps.max_force_normalized, 0, kFullScale));
        r.supported_types = caps.supported_types;
        r.effect_slots = clamp_u16(caps.effect_slots);
        r.pool_bytes = clamp_u32(caps.pool_bytes);
        r.sample_memory = clamp_u32(caps.sample_memory);
        r.local_reflexes = caps.local_reflexes;
        r.interim_reports = caps.interim_reports;
        // The loop as it runs (a device may run below or above its profile's default).
        r.loop_rate_hz = clamp_u16(config.loop_rate_hz);
        r.max_loop_rate_hz = clamp_u16(caps.max_loop_rate_hz);
        r.interim_report_centihz = clamp_u16(std::llround(static_cast<double>(caps.interim_report_hz) * 100.0));
        r.report_rate_hz = clamp_u16(report_rate_hz);
        detail::copy_text(r.firmware_version, sizeof r.firmware_version, caps.firmware_version);
        r.vendor_revision = static_cast<uint8_t>(runtime::kProtocolVendorRevision);
        return r;
    }

    // ------------------------------------------------------------------------------------
    // Host frames.

    void process_inbox() {
        while (!inbox.empty() && internal.empty() && !fence_in_flight && !pending_full()) {
            if (process(inbox.front()) == Step::blocked) return;
            inbox.pop_front();
        }
    }

    // An answer complete at once.
    void answer_now(Pending p) { pending.push_back(std::move(p)); }

    static Pending status_entry(uint32_t sequence, ReportId command, uint16_t block) {
        Pending p;
        p.answer = Answer::status;
        p.status.sequence = sequence;
        p.status.command = command;
        p.status.block = block;
        p.block = block;
        return p;
    }

    void refuse(uint32_t sequence, ReportId command, uint16_t block, const Refusal& why) {
        Pending p = status_entry(sequence, command, block);
        detail::fill_refusal(p.status, why);
        answer_now(std::move(p));
    }

    void refuse_frame(const Frame& f, const Refusal& why) {
        // The report's sequence when its id names a report that has one and the bytes hold
        // it (the sequence is every host report's first field: bytes 1..4, little-endian).
        uint32_t sequence = 0;
        ReportId command = protocol::kNoReportId;  // when the id byte names no report
        if (!f.payload.empty() && protocol::report_kind(f.payload[0]).has_value()) {
            command = static_cast<ReportId>(f.payload[0]);
            const bool has_sequence = *protocol::report_kind(f.payload[0]) != protocol::ReportKind::input &&
                                      command != ReportId::block_load && command != ReportId::pid_pool &&
                                      command != ReportId::device_info;
            if (has_sequence && f.payload.size() >= 5) {
                sequence = uint32_t{f.payload[1]} | uint32_t{f.payload[2]} << 8 | uint32_t{f.payload[3]} << 16 |
                           uint32_t{f.payload[4]} << 24;
            }
        }
        refuse(sequence, command, 0, why);
    }

    static Refusal from_error(const Error& e) {
        Refusal r;
        r.code = e.code;
        r.field = std::string(e.field, strnlen(e.field, sizeof e.field));
        r.rule = e.rule != nullptr ? e.rule : "";
        r.has_range = e.has_range;
        r.value = e.value;
        r.allowed = e.allowed;
        return r;
    }

    Step process(const Frame& f) {
        switch (f.kind) {
            case FrameKind::output_report: return process_report(f, protocol::ReportKind::output);
            case FrameKind::set_feature: return process_report(f, protocol::ReportKind::feature);
            case FrameKind::get_feature: return process_get_feature(f);
            case FrameKind::get_descriptor:
                if (!f.payload.empty()) {
                    refuse_frame(Frame{}, Refusal::out_of_range("get_descriptor.length",
                                                                static_cast<int64_t>(f.payload.size()), {0, 0}));
                    return Step::done;
                }
                ++counters.reports_decoded;
                {
                    Pending p;
                    p.answer = Answer::descriptor;
                    answer_now(std::move(p));
                }
                return Step::done;
            case FrameKind::input_report:
            case FrameKind::feature_reply:
            case FrameKind::descriptor_reply:
            case FrameKind::busy:
                break;
            case FrameKind::hello:
                // The stream transports take a host's hello (its token) themselves; one
                // that reaches the session came where no secret is asked for.
                refuse_frame(Frame{}, Refusal::of(ErrorCode::invalid_parameter, "frame.kind",
                                                  "a hello frame is for the device's connection, which has no "
                                                  "token to check here"));
                return Step::done;
        }
        refuse_frame(Frame{}, Refusal::of(ErrorCode::invalid_parameter, "frame.kind",
                                          std::string("a ") + std::string(transport::frame_kind_name(f.kind)) +
                                              " frame goes from a device to its host, never to the device"));
        return Step::done;
    }

    Step process_get_feature(const Frame& f) {
        if (f.payload.size() != 1) {
            refuse_frame(Frame{}, Refusal::out_of_range("get_feature.length", static_cast<int64_t>(f.payload.size()),
                                                        {1, 1}));
            return Step::done;
        }
        const uint8_t id = f.payload[0];
        if (id == static_cast<uint8_t>(ReportId::block_load)) {
            ++counters.reports_decoded;
            Pending p;
            p.answer = Answer::block_load;
            p.block_load = last_block_load;
            answer_now(std::move(p));
            return Step::done;
        }
        if (id == static_cast<uint8_t>(ReportId::device_info)) {
            ++counters.reports_decoded;
            Pending p;
            p.answer = Answer::device_info;
            answer_now(std::move(p));
            return Step::done;
        }
        if (id == static_cast<uint8_t>(ReportId::pid_pool)) {
            // The engine's own figures: a query whose ack the reply waits for.
            uint32_t sequence = 0;
            if (!send(runtime::make_query_pool(0), sequence)) return Step::blocked;
            ++counters.reports_decoded;
            Pending p;
            p.answer = Answer::pid_pool;
            p.on_ack = OnAck::pool;
            p.waiting = true;
            p.runtime_sequence = sequence;
            push_waiting(std::move(p));
            return Step::done;
        }
        refuse_frame(f, Refusal::of(ErrorCode::invalid_parameter, "get_feature.report_id",
                                    "report id " + std::to_string(id) +
                                        " is not a feature report to get (allowed: Block Load 0x12, PID Pool "
                                        "0x13, Device Info 0x30)"));
        return Step::done;
    }

    Step process_report(const Frame& f, protocol::ReportKind expected) {
        protocol::AnyReport report;
        if (const Error e = protocol::decode(f.payload, report)) {
            refuse_frame(f, from_error(e));
            return Step::done;
        }
        const ReportId id = protocol::report_id_of(report);
        const protocol::ReportKind kind = *protocol::report_kind(static_cast<uint8_t>(id));
        const bool settable = kind == protocol::ReportKind::feature && id == ReportId::create_new_effect;
        const bool fits = expected == protocol::ReportKind::output ? kind == protocol::ReportKind::output : settable;
        if (!fits) {
            const std::string name(protocol::report_name(id));
            std::string rule;
            if (kind == protocol::ReportKind::input) {
                rule = name + " is an input report: the device sends it, the host does not";
            } else if (kind == protocol::ReportKind::feature && !settable) {
                rule = name + " is a feature report the host gets (get_feature), never sets";
            } else if (kind == protocol::ReportKind::feature) {
                rule = name + " is a feature report: send it with set_feature";
            } else {
                rule = name + " is an output report: send it as an output report";
            }
            refuse_frame(f, Refusal::of(ErrorCode::invalid_parameter, "frame.kind", rule));
            return Step::done;
        }
        const Step step = std::visit([&](const auto& r) { return handle(r); }, report);
        if (step == Step::done) ++counters.reports_decoded;  // a blocked frame comes again
        return step;
    }

    // ---- block lookups

    // The allocated block a report names, or a refusal.
    detail::Block* find_block(ReportId id, uint16_t index, uint32_t sequence) {
        if (!blocks.in_range(index)) {
            refuse(sequence, id, index,
                   Refusal::out_of_range(std::string(detail::report_key(id)) + ".block", index,
                                         {1, blocks.capacity()}));
            return nullptr;
        }
        detail::Block* b = blocks.find(index);
        if (b == nullptr) {
            refuse(sequence, id, index,
                   Refusal::of(ErrorCode::invalid_handle, std::string(detail::report_key(id)) + ".block",
                               "block " + std::to_string(index) +
                                   " is not allocated: Create New Effect allocates one, Block Free and a "
                                   "device reset free it"));
        }
        return b;
    }

    // The committed block a report names (its effect exists in the engine), or a refusal.
    detail::Block* find_committed(ReportId id, uint16_t index, uint32_t sequence) {
        detail::Block* b = find_block(id, index, sequence);
        if (b == nullptr || b->is_committed) return b;
        refuse(sequence, id, index,
               Refusal::of(ErrorCode::invalid_handle, std::string(detail::report_key(id)) + ".block",
                           "block " + std::to_string(index) + " holds a " + std::string(effect_type_name(b->type)) +
                               " effect not downloaded yet: its first Set Effect has not been accepted"));
        return nullptr;
    }

    // A report that becomes one pipelined runtime command, answered by its ack.
    Step forward(const runtime::Command& command, uint32_t sequence, ReportId id, uint16_t block,
                 bool effect_status = false, OnAck on_ack = OnAck::nothing, int32_t value = 0) {
        uint32_t runtime_sequence = 0;
        if (!send(command, runtime_sequence)) return Step::blocked;
        Pending p = status_entry(sequence, id, block);
        p.waiting = true;
        p.runtime_sequence = runtime_sequence;
        p.effect_status = effect_status;
        p.on_ack = on_ack;
        p.value = value;
        push_waiting(std::move(p));
        return Step::done;
    }

    // ---- the reports

    Step handle(const protocol::CreateNewEffectReport& r) {
        const ReportId id = ReportId::create_new_effect;
        last_block_load = protocol::BlockLoadReport{0, protocol::BlockLoadStatus::error, 0};
        if (!caps.supports(r.type)) {
            refuse(r.sequence, id, 0,
                   Refusal::of(ErrorCode::not_supported, "create_new_effect.type",
                               std::string(effect_type_name(r.type)) + " is not among the types this " +
                                   std::string(caps.class_name) + " device plays (Device Info lists them)"));
            return Step::done;
        }
        if (r.type == EffectType::force_profile) {
            if (r.sample_count > caps.sample_memory) {
                Refusal why = Refusal::out_of_range("create_new_effect.sample_count", r.sample_count,
                                                    {0, caps.sample_memory});
                why.code = ErrorCode::device_full;
                refuse(r.sequence, id, 0, why);
                return Step::done;
            }
        } else if (r.sample_count != 0) {
            refuse(r.sequence, id, 0, Refusal::out_of_range("create_new_effect.sample_count", r.sample_count, {0, 0}));
            return Step::done;
        }
        const uint16_t block = blocks.allocate(r.type, r.sample_count);
        if (block == 0) {
            last_block_load.status = protocol::BlockLoadStatus::full;
            refuse(r.sequence, id, 0,
                   Refusal::of(ErrorCode::device_full, "create_new_effect",
                               "every effect block (" + std::to_string(blocks.capacity()) +
                                   ") is in use: free one with Block Free"));
            return Step::done;
        }
        last_block_load = protocol::BlockLoadReport{block, protocol::BlockLoadStatus::success, 0};
        answer_now(status_entry(r.sequence, id, block));
        return Step::done;
    }

    template <class R>
    Step type_block(const R& r) {
        const ReportId id = protocol::report_id_of(protocol::AnyReport{r});
        detail::Block* b = find_block(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        if (auto why = detail::check_type_block_fits(id, b->type, r.block)) {
            refuse(r.sequence, id, r.block, *why);
            return Step::done;
        }
        if (auto why = detail::check_type_block_values(protocol::AnyReport{r}, b->type)) {
            refuse(r.sequence, id, r.block, *why);
            return Step::done;
        }
        if constexpr (std::is_same_v<R, protocol::SetCustomForceReport>) {
            if (r.sample_count > caps.sample_memory) {
                Refusal why = Refusal::out_of_range("set_custom_force.sample_count", r.sample_count,
                                                    {1, caps.sample_memory});
                why.code = ErrorCode::device_full;
                refuse(r.sequence, id, r.block, why);
                return Step::done;
            }
        }
        if constexpr (std::is_same_v<R, protocol::SetConstantForceReport>) {
            // A standard PID device plays a new Constant Force level at once: hid-pidff
            // sends it alone to change a level, and a host streams a force through it
            // (host emulation). So on a committed block with nothing else pending, the
            // level is an update of its own, not part of a transaction.
            if (b->type == EffectType::constant && b->is_committed && b->shadow == b->committed) {
                return apply_level(r, *b);
            }
        }
        detail::apply_type_block(protocol::AnyReport{r}, *b);
        answer_now(status_entry(r.sequence, id, r.block));
        return Step::done;
    }

    Step apply_level(const protocol::SetConstantForceReport& r, detail::Block& b) {
        if (fence_in_flight) return Step::blocked;
        EffectParams next = b.committed;
        next.constant.magnitude = r.magnitude;
        uint32_t runtime_sequence = 0;
        if (!send(runtime::make_update(0, b.effect, next, effect_field::kTypeSpecific, false), runtime_sequence)) {
            return Step::blocked;
        }
        // The engine takes a valid level on a live effect; should the effect have ended
        // meanwhile, the ack's error goes to the host and the next commit sets it anew.
        b.committed = next;
        b.shadow = next;
        Pending p = status_entry(r.sequence, ReportId::set_constant_force, r.block);
        p.waiting = true;
        p.runtime_sequence = runtime_sequence;
        push_waiting(std::move(p));
        return Step::done;
    }

    Step handle(const protocol::SetEnvelopeReport& r) { return type_block(r); }
    Step handle(const protocol::SetConditionReport& r) { return type_block(r); }
    Step handle(const protocol::SetPeriodicReport& r) { return type_block(r); }
    Step handle(const protocol::SetConstantForceReport& r) { return type_block(r); }
    Step handle(const protocol::SetRampForceReport& r) { return type_block(r); }
    Step handle(const protocol::SetCustomForceReport& r) { return type_block(r); }
    Step handle(const protocol::SetTextureReport& r) { return type_block(r); }
    Step handle(const protocol::SetWallReport& r) { return type_block(r); }
    Step handle(const protocol::SetBarrierReport& r) { return type_block(r); }
    Step handle(const protocol::SetSweepReport& r) { return type_block(r); }
    Step handle(const protocol::SetDynamicReport& r) { return type_block(r); }
    Step handle(const protocol::SetControlLawReport& r) { return type_block(r); }

    Step handle(const protocol::CustomForceDataReport& r) {
        const ReportId id = ReportId::custom_force_data;
        detail::Block* b = find_block(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        if (auto why = detail::check_type_block_fits(id, b->type, r.block)) {
            refuse(r.sequence, id, r.block, *why);
            return Step::done;
        }
        // Offset 0 starts the block's samples anew; any other continues them, in order.
        const bool continues = stage_block == r.block;
        const int32_t expected = r.offset == 0 ? 0 : (continues ? staged : 0);
        if (r.offset != expected) {
            Refusal why = Refusal::out_of_range("custom_force_data.offset", r.offset, {0, continues ? staged : 0});
            why.rule = continues ? "samples come in order: the next offset is the count received"
                                 : "the block's samples start at offset 0";
            refuse(r.sequence, id, r.block, why);
            return Step::done;
        }
        if (int64_t{r.offset} + r.count > caps.sample_memory) {
            Refusal why = Refusal::out_of_range("custom_force_data.count", int64_t{r.offset} + r.count,
                                                {1, caps.sample_memory});
            why.code = ErrorCode::device_full;
            why.rule = "the samples would exceed the device's sample memory (value: offset + count)";
            refuse(r.sequence, id, r.block, why);
            return Step::done;
        }
        runtime::Command c;
        c.kind = runtime::CommandKind::stage_samples;
        c.sample_offset = r.offset;
        c.sample_count = r.count;
        std::copy(r.samples, r.samples + r.count, c.samples);
        const Step step = forward(c, r.sequence, id, r.block, false, OnAck::stage);
        if (step == Step::done) {
            stage_block = r.block;
            staged = r.offset + r.count;
        }
        return step;
    }

    Step handle(const protocol::SetEffectReport& r) {
        const ReportId id = ReportId::set_effect;
        detail::Block* b = find_block(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        // Every refusal of a commit rolls the block back to its committed parameters.
        auto refuse_commit = [&](const Refusal& why) {
            roll_back(*b);
            refuse(r.sequence, id, r.block, why);
            return Step::done;
        };
        if (r.type != b->type) {
            return refuse_commit(Refusal::of(
                ErrorCode::invalid_parameter, "set_effect.type",
                "block " + std::to_string(r.block) + " holds a " + std::string(effect_type_name(b->type)) +
                    " effect, and an effect's type never changes: free the block and create a new effect"));
        }
        if (auto why = detail::check_axes_enable(r, caps)) return refuse_commit(*why);
        EffectParams next = b->shadow;
        detail::apply_set_effect(r, next, caps);
        detail::ignore_direction_of_per_axis_conditions(b->type, b->arrived.conditions, next);
        // PID's rule: an effect has an envelope when a Set Envelope arrived for its block
        // (Set Effect's vendor no_envelope can only take it away).
        next.has_envelope = next.has_envelope && b->arrived.envelope;
        if (!b->is_committed) {
            if (auto why = detail::check_blocks_complete(*b, next, r.block)) return refuse_commit(*why);
        }
        if (auto why = detail::check_conditions_within_axes(r, b->type, b->arrived.conditions, next)) {
            return refuse_commit(*why);
        }
        uint32_t mask = b->is_committed ? detail::changed_fields(b->committed, next) : effect_field::kAll;
        bool takes_stage = false;
        if (b->type == EffectType::force_profile) {
            const bool has_samples = stage_block == r.block && staged > 0;
            if (has_samples && staged != next.custom.sample_count) {
                Refusal why = Refusal::out_of_range("custom_force_data", staged,
                                                    {next.custom.sample_count, next.custom.sample_count});
                why.rule = "the samples received must be Set Custom Force's sample_count (value: received)";
                return refuse_commit(why);
            }
            if (!b->is_committed && !has_samples) {
                return refuse_commit(Refusal::of(
                    ErrorCode::invalid_parameter, "custom_force_data",
                    "block " + std::to_string(r.block) + "'s force profile needs its " +
                        std::to_string(next.custom.sample_count) +
                        " samples in Custom Force Data reports (from offset 0) before its first Set Effect"));
            }
            if (b->is_committed && !has_samples && (mask & effect_field::kTypeSpecific) != 0) {
                return refuse_commit(Refusal::of(
                    ErrorCode::invalid_parameter, "custom_force_data",
                    "a force profile's new Set Custom Force comes with its samples: send them in Custom Force "
                    "Data reports from offset 0 before Set Effect"));
            }
            if (has_samples) mask |= effect_field::kTypeSpecific;
            takes_stage = has_samples;
        }
        if (b->is_committed && mask == 0) {
            // Nothing changed: nothing to send.
            b->shadow = next;
            answer_now(status_entry(r.sequence, id, r.block));
            return Step::done;
        }
        if (waiting > 0) return Step::blocked;  // a fence waits for every command in flight
        const runtime::Command c = b->is_committed ? runtime::make_update(0, b->effect, next, mask, false)
                                                   : runtime::make_create(0, next);
        uint32_t runtime_sequence = 0;
        if (!send(c, runtime_sequence)) return Step::blocked;
        b->shadow = next;
        if (takes_stage) {  // the runtime's create or update empties the stage
            stage_block = 0;
            staged = 0;
        }
        Pending p = status_entry(r.sequence, id, r.block);
        p.waiting = true;
        p.fence = true;
        p.runtime_sequence = runtime_sequence;
        p.on_ack = b->is_committed ? OnAck::commit_update : OnAck::commit_create;
        p.effect_status = b->is_committed;
        push_waiting(std::move(p));
        return Step::done;
    }

    Step handle(const protocol::DownloadForceSampleReport& r) {
        const std::span<const int16_t> force(r.force, std::min<std::size_t>(r.axis_count, kMaxAxes));
        uint32_t runtime_sequence = 0;
        if (!send(runtime::make_stream_force(0, force), runtime_sequence)) return Step::blocked;
        Pending p = status_entry(r.sequence, ReportId::download_force_sample, 0);
        p.answer = Answer::status_if_refused;
        p.waiting = true;
        p.runtime_sequence = runtime_sequence;
        push_waiting(std::move(p));
        return Step::done;
    }

    Step handle(const protocol::EffectOperationReport& r) {
        const ReportId id = ReportId::effect_operation;
        detail::Block* b = find_committed(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        switch (r.operation) {
            case protocol::EffectOperation::start:
            case protocol::EffectOperation::start_solo:
                return forward(runtime::make_start(0, b->effect, detail::iterations_of_loop_count(r.loop_count),
                                                   r.operation == protocol::EffectOperation::start_solo),
                               r.sequence, id, r.block, true);
            case protocol::EffectOperation::stop:
                return forward(runtime::make_effect_command(runtime::CommandKind::stop, 0, b->effect), r.sequence,
                               id, r.block, true);
        }
        refuse(r.sequence, id, r.block,
               Refusal::out_of_range("effect_operation.operation", static_cast<int64_t>(r.operation), {1, 3}));
        return Step::done;
    }

    Step handle(const protocol::BlockFreeReport& r) {
        const ReportId id = ReportId::block_free;
        detail::Block* b = find_block(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        if (!b->is_committed) {
            // Never reached the engine: freeing it is the session's alone.
            if (stage_block == r.block) {
                stage_block = 0;
                staged = 0;
            }
            blocks.free(r.block);
            answer_now(status_entry(r.sequence, id, r.block));
            return Step::done;
        }
        if (waiting > 0) return Step::blocked;
        uint32_t runtime_sequence = 0;
        if (!send(runtime::make_effect_command(runtime::CommandKind::destroy, 0, b->effect), runtime_sequence)) {
            return Step::blocked;
        }
        Pending p = status_entry(r.sequence, id, r.block);
        p.waiting = true;
        p.fence = true;
        p.runtime_sequence = runtime_sequence;
        p.on_ack = OnAck::free_block;
        push_waiting(std::move(p));
        return Step::done;
    }

    Step handle(const protocol::DeviceControlReport& r) {
        const ReportId id = ReportId::device_control;
        const std::optional<runtime::DeviceControl> control = detail::runtime_control(r.control);
        if (!control) {
            refuse(r.sequence, id, 0, Refusal::out_of_range("device_control.control", static_cast<int64_t>(r.control),
                                                            {1, 6}));
            return Step::done;
        }
        if (*control != runtime::DeviceControl::reset) {
            return forward(runtime::make_device_control(0, *control), r.sequence, id, 0);
        }
        if (waiting > 0) return Step::blocked;
        uint32_t runtime_sequence = 0;
        if (!send(runtime::make_device_control(0, *control), runtime_sequence)) return Step::blocked;
        Pending p = status_entry(r.sequence, id, 0);
        p.waiting = true;
        p.fence = true;
        p.runtime_sequence = runtime_sequence;
        p.on_ack = OnAck::reset;
        push_waiting(std::move(p));
        return Step::done;
    }

    Step handle(const protocol::DeviceGainReport& r) {
        return forward(runtime::make_value_command(runtime::CommandKind::set_gain, 0, r.gain), r.sequence,
                       ReportId::device_gain, 0);
    }

    Step handle(const protocol::ReflexReport& r) {
        const ReportId id = ReportId::reflex;
        detail::Block* b = find_committed(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        const runtime::CommandKind kind =
            r.assign ? runtime::CommandKind::assign_reflex : runtime::CommandKind::remove_reflex;
        return forward(runtime::make_effect_command(kind, 0, b->effect), r.sequence, id, r.block);
    }

    Step handle(const protocol::IdfSettingsReport& r) {
        return forward(runtime::make_set_idf(0, r.settings), r.sequence, ReportId::idf_settings, 0);
    }

    Step handle(const protocol::ReportRateReport& r) {
        return forward(runtime::make_value_command(runtime::CommandKind::set_report_rate, 0, r.rate_hz), r.sequence,
                       ReportId::report_rate, 0, false, OnAck::report_rate, r.rate_hz);
    }

    Step handle(const protocol::KeepAliveReport& r) {
        return forward(runtime::make_keep_alive(0), r.sequence, ReportId::keep_alive, 0);
    }

    Step handle(const protocol::EffectStatusRequestReport& r) {
        const ReportId id = ReportId::effect_status_request;
        detail::Block* b = find_committed(id, r.block, r.sequence);
        if (b == nullptr) return Step::done;
        return forward(runtime::make_effect_command(runtime::CommandKind::status, 0, b->effect), r.sequence, id,
                       r.block, true);
    }

    // Feature gets and input reports never arrive here (process_report refuses them by
    // kind first); these keep the visit total.
    Step handle(const protocol::BlockLoadReport&) { return Step::done; }
    Step handle(const protocol::PidPoolReport&) { return Step::done; }
    Step handle(const protocol::DeviceInfoReport&) { return Step::done; }
    Step handle(const protocol::JoystickInputReport&) { return Step::done; }
    Step handle(const protocol::PidStateReport&) { return Step::done; }
    Step handle(const protocol::CommandStatusReport&) { return Step::done; }
    Step handle(const protocol::DeviceStatusReport&) { return Step::done; }
    Step handle(const protocol::DynamicReportReport&) { return Step::done; }
    Step handle(const protocol::CommandErrorTextReport&) { return Step::done; }
    Step handle(const protocol::EffectStatesReport&) { return Step::done; }

    // ------------------------------------------------------------------------------------

    void host_gone() {
        ++counters.host_resets;
        inbox.clear();
        for (Pending& p : pending) p.discard = true;
        // Drop internal commands not sent yet but a pool query; the reset comes first.
        const bool pool_query = pool_query_queued;
        internal.clear();
        pool_query_queued = false;
        // Fade the forces out (the ack comes when the fade has ended), then free everything.
        queue_internal(runtime::make_release_host(0), OnAck::nothing, true);
        queue_internal(runtime::make_device_control(0, runtime::DeviceControl::reset), OnAck::reset, true);
        queue_internal(runtime::make_value_command(runtime::CommandKind::set_report_rate, 0, config.report_rate_hz),
                       OnAck::nothing, false);
        queue_internal(runtime::make_set_idf(0, config.idf.settings), OnAck::nothing, false);
        if (pool_query) queue_internal(runtime::make_query_pool(0), OnAck::pool, false);
        report_rate_hz = config.report_rate_hz;
        last_block_load = protocol::BlockLoadReport{0, protocol::BlockLoadStatus::error, 0};
        round_open = false;
        flags_sent = false;
    }
};

DeviceSession::DeviceSession(const runtime::Capabilities& caps, const runtime::RuntimeConfig& config,
                             runtime::HostLink& link, LoopFiguresProvider loop_figures) {
    if (caps.effect_slots < 1 || caps.effect_slots > config.engine.max_effects) {
        throw std::invalid_argument("device session: the capabilities' effect_slots = " +
                                    std::to_string(caps.effect_slots) + " is out of range (allowed 1.." +
                                    std::to_string(config.engine.max_effects) + ", the engine's max_effects)");
    }
    impl_ = std::make_unique<Impl>(caps, config, link, std::move(loop_figures));
}

DeviceSession::~DeviceSession() = default;

bool DeviceSession::offer(transport::Frame frame) {
    if (!accepting()) return false;
    impl_->inbox.push_back(std::move(frame));
    ++impl_->counters.frames_received;
    return true;
}

bool DeviceSession::accepting() const noexcept { return impl_->inbox.size() < kInboxFrames; }

void DeviceSession::pump(std::vector<transport::Frame>& out) {
    const std::size_t before = out.size();
    Impl& m = *impl_;
    m.drain_runtime(out);
    m.send_internal();
    m.process_inbox();
    m.emit_answers(out);
    m.counters.frames_sent += out.size() - before;
}

void DeviceSession::host_gone() { impl_->host_gone(); }

bool DeviceSession::idle() const noexcept {
    return impl_->inbox.empty() && impl_->pending.empty() && impl_->internal.empty();
}

int32_t DeviceSession::in_flight() const noexcept { return impl_->waiting; }

int32_t DeviceSession::block_capacity() const noexcept { return impl_->blocks.capacity(); }
int32_t DeviceSession::allocated_blocks() const noexcept { return impl_->blocks.allocated(); }
int32_t DeviceSession::committed_blocks() const noexcept { return impl_->blocks.committed(); }

std::optional<BlockView> DeviceSession::block(uint16_t index) const {
    const detail::Block* b = impl_->blocks.find(index);
    if (b == nullptr) return std::nullopt;
    BlockView v;
    v.block = index;
    v.type = b->type;
    v.committed = b->is_committed;
    v.effect = b->effect;
    v.committed_params = b->committed;
    v.shadow = b->shadow;
    return v;
}

PoolInfo DeviceSession::pool() const noexcept { return impl_->pool; }

const SessionCounters& DeviceSession::counters() const noexcept { return impl_->counters; }

}  // namespace feel::peripheral
