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
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "device_session_impl.hpp"
#include "input_reports.hpp"

namespace feel::peripheral {
namespace {

using transport::Frame;
using transport::FrameKind;

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

DeviceSession::Impl::Impl(const runtime::Capabilities& c, const runtime::RuntimeConfig& cfg, runtime::HostLink& l,
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

void DeviceSession::Impl::queue_internal(const runtime::Command& command, OnAck on_ack, bool fence) {
    if (on_ack == OnAck::pool) {
        if (pool_query_queued) return;
        pool_query_queued = true;
    }
    internal.push_back(Internal{command, on_ack, fence});
}

bool DeviceSession::Impl::send(runtime::Command command, uint32_t& sequence) {
    command.sequence = next_sequence;
    if (!link->send(command)) return false;
    sequence = next_sequence++;
    ++counters.runtime_commands;
    return true;
}

void DeviceSession::Impl::send_internal() {
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

void DeviceSession::Impl::push_waiting(Pending p) {
    ++waiting;
    if (p.fence) fence_in_flight = true;
    pending.push_back(std::move(p));
}

void DeviceSession::Impl::drain_runtime(std::vector<Frame>& out) {
    while (link->poll(incoming)) {
        switch (incoming.kind) {
            case runtime::ReportKind::ack: on_ack(incoming.ack); break;
            case runtime::ReportKind::state: on_state(incoming.state, out); break;
            case runtime::ReportKind::dynamic: on_dynamic(incoming.dynamic, out); break;
        }
    }
}

void DeviceSession::Impl::on_ack(const runtime::CommandAck& ack) {
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

void DeviceSession::Impl::apply_ack(Pending& p, const runtime::CommandAck& ack) {
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

void DeviceSession::Impl::roll_back(detail::Block& b) {
    b.shadow = b.committed;
    if (!b.is_committed) b.arrived = detail::Arrivals{};
}

void DeviceSession::Impl::on_state(const runtime::StateReport& s, std::vector<Frame>& out) {
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

void DeviceSession::Impl::emit_round(std::vector<Frame>& out) {
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

bool DeviceSession::Impl::same_flags(const protocol::PidStateReport& a, const protocol::PidStateReport& b) noexcept {
    return a.device_paused == b.device_paused && a.actuators_enabled == b.actuators_enabled &&
           a.safety_switch == b.safety_switch && a.actuator_override == b.actuator_override &&
           a.actuator_power == b.actuator_power;
}

void DeviceSession::Impl::on_dynamic(const DynamicReport& d, std::vector<Frame>& out) {
    const uint16_t block = blocks.block_of(d.effect);
    if (block == 0) return;  // an effect freed since: no block to name
    const int axes = std::clamp(d.axis_count, 0, kMaxAxes);
    int first = 0;
    do {
        out.push_back(input_frame(FrameKind::input_report, detail::dynamic_report(d, block, first)));
        first += protocol::kDynamicAxesPerReport;
    } while (first < axes);
}

void DeviceSession::Impl::emit_answers(std::vector<Frame>& out) {
    while (!pending.empty() && !pending.front().waiting) {
        Pending& p = pending.front();
        if (!p.discard) emit_answer(p, out);
        pending.pop_front();
    }
}

void DeviceSession::Impl::emit_answer(Pending& p, std::vector<Frame>& out) {
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

protocol::PidPoolReport DeviceSession::Impl::pid_pool_report() const {
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

protocol::DeviceInfoReport DeviceSession::Impl::device_info_report() const {
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

void DeviceSession::Impl::host_gone() {
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
