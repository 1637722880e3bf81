// The device session's host side: each host frame decoded, checked, and either answered at
// once or turned into exactly one runtime command (the design: device_session.cpp).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <variant>

#include "device_session_impl.hpp"
#include "input_reports.hpp"

namespace feel::peripheral {
void DeviceSession::Impl::process_inbox() {
    while (!inbox.empty() && internal.empty() && !fence_in_flight && !pending_full()) {
        if (process(inbox.front()) == Step::blocked) return;
        inbox.pop_front();
    }
}

auto DeviceSession::Impl::status_entry(uint32_t sequence, ReportId command, uint16_t block) -> Pending {
    Pending p;
    p.answer = Answer::status;
    p.status.sequence = sequence;
    p.status.command = command;
    p.status.block = block;
    p.block = block;
    return p;
}

void DeviceSession::Impl::refuse(uint32_t sequence, ReportId command, uint16_t block, const Refusal& why) {
    Pending p = status_entry(sequence, command, block);
    detail::fill_refusal(p.status, why);
    answer_now(std::move(p));
}

void DeviceSession::Impl::refuse_frame(const Frame& f, const Refusal& why) {
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

auto DeviceSession::Impl::from_error(const Error& e) -> Refusal {
    Refusal r;
    r.code = e.code;
    r.field = std::string(e.field, strnlen(e.field, sizeof e.field));
    r.rule = e.rule != nullptr ? e.rule : "";
    r.has_range = e.has_range;
    r.value = e.value;
    r.allowed = e.allowed;
    return r;
}

auto DeviceSession::Impl::process(const Frame& f) -> Step {
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

auto DeviceSession::Impl::process_get_feature(const Frame& f) -> Step {
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

auto DeviceSession::Impl::process_report(const Frame& f, protocol::ReportKind expected) -> Step {
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

detail::Block* DeviceSession::Impl::find_block(ReportId id, uint16_t index, uint32_t sequence) {
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

detail::Block* DeviceSession::Impl::find_committed(ReportId id, uint16_t index, uint32_t sequence) {
    detail::Block* b = find_block(id, index, sequence);
    if (b == nullptr || b->is_committed) return b;
    refuse(sequence, id, index,
           Refusal::of(ErrorCode::invalid_handle, std::string(detail::report_key(id)) + ".block",
                       "block " + std::to_string(index) + " holds a " + std::string(effect_type_name(b->type)) +
                           " effect not downloaded yet: its first Set Effect has not been accepted"));
    return nullptr;
}

auto DeviceSession::Impl::forward(const runtime::Command& command, uint32_t sequence, ReportId id, uint16_t block,
                                  bool effect_status, OnAck on_ack, int32_t value) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::CreateNewEffectReport& r) -> Step {
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
auto DeviceSession::Impl::type_block(const R& r) -> Step {
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

auto DeviceSession::Impl::apply_level(const protocol::SetConstantForceReport& r, detail::Block& b) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::CustomForceDataReport& r) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::SetEffectReport& r) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::DownloadForceSampleReport& r) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::EffectOperationReport& r) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::BlockFreeReport& r) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::DeviceControlReport& r) -> Step {
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

auto DeviceSession::Impl::handle(const protocol::DeviceGainReport& r) -> Step {
    return forward(runtime::make_value_command(runtime::CommandKind::set_gain, 0, r.gain), r.sequence,
                   ReportId::device_gain, 0);
}

auto DeviceSession::Impl::handle(const protocol::ReflexReport& r) -> Step {
    const ReportId id = ReportId::reflex;
    detail::Block* b = find_committed(id, r.block, r.sequence);
    if (b == nullptr) return Step::done;
    const runtime::CommandKind kind =
        r.assign ? runtime::CommandKind::assign_reflex : runtime::CommandKind::remove_reflex;
    return forward(runtime::make_effect_command(kind, 0, b->effect), r.sequence, id, r.block);
}

auto DeviceSession::Impl::handle(const protocol::IdfSettingsReport& r) -> Step {
    return forward(runtime::make_set_idf(0, r.settings), r.sequence, ReportId::idf_settings, 0);
}

auto DeviceSession::Impl::handle(const protocol::ReportRateReport& r) -> Step {
    return forward(runtime::make_value_command(runtime::CommandKind::set_report_rate, 0, r.rate_hz), r.sequence,
                   ReportId::report_rate, 0, false, OnAck::report_rate, r.rate_hz);
}

auto DeviceSession::Impl::handle(const protocol::KeepAliveReport& r) -> Step {
    return forward(runtime::make_keep_alive(0), r.sequence, ReportId::keep_alive, 0);
}

auto DeviceSession::Impl::handle(const protocol::EffectStatusRequestReport& r) -> Step {
    const ReportId id = ReportId::effect_status_request;
    detail::Block* b = find_committed(id, r.block, r.sequence);
    if (b == nullptr) return Step::done;
    return forward(runtime::make_effect_command(runtime::CommandKind::status, 0, b->effect), r.sequence, id,
                   r.block, true);
}

}  // namespace feel::peripheral
