// The PID transactions of effect_download.hpp.
#include "effect_download.hpp"

#include <algorithm>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/effect_reports.hpp"
#include "host_errors.hpp"

namespace feel::host {

using transport::FrameKind;

bool host_emulates_trigger(const DeviceCaps& caps, const EffectParams& params) noexcept {
    return params.trigger.kind != TriggerKind::none && !caps.local_reflexes;
}

EffectParams device_params(const DeviceCaps& caps, const EffectParams& params) noexcept {
    EffectParams p = params;
    if (host_emulates_trigger(caps, params)) {
        p.trigger = Trigger{};
        p.trigger_repeat_interval_us = 0;
    }
    return p;
}

EffectParams merge_parameters(const EffectParams& current, const EffectParams& changes, uint32_t mask) noexcept {
    using namespace effect_field;
    EffectParams m = current;
    if (mask & kDuration) m.duration_us = changes.duration_us;
    if (mask & kStartDelay) m.start_delay_us = changes.start_delay_us;
    if (mask & kGain) m.gain = changes.gain;
    if (mask & kIterations) m.iterations = changes.iterations;
    if (mask & kAxes) {
        m.axis_count = changes.axis_count;
        std::copy(std::begin(changes.axes), std::end(changes.axes), std::begin(m.axes));
    }
    if (mask & kDirection) m.direction = changes.direction;
    if (mask & kTrigger) m.trigger = changes.trigger;
    if (mask & kTriggerRepeat) m.trigger_repeat_interval_us = changes.trigger_repeat_interval_us;
    if (mask & kEnvelope) {
        m.has_envelope = changes.has_envelope;
        m.envelope = changes.envelope;
    }
    if (mask & kTypeSpecific) {
        std::copy(std::begin(changes.conditions), std::end(changes.conditions), std::begin(m.conditions));
        m.periodic = changes.periodic;
        m.constant = changes.constant;
        m.ramp = changes.ramp;
        m.custom = changes.custom;
        m.texture = changes.texture;
        m.wall = changes.wall;
        m.barrier = changes.barrier;
        m.dynamic = changes.dynamic;
    }
    return m;
}

namespace {

void free_block(DeviceCore& core, uint16_t block) {
    protocol::BlockFreeReport f;
    f.block = block;
    (void)core.transact(f, FrameKind::output_report);
}

}  // namespace

Status download_effect(DeviceCore& core, EffectRecord& record, const std::string& what) {
    const EffectParams params = device_params(core.caps, record.params);
    const bool emulate = host_emulates_trigger(core.caps, record.params);

    if (Status s = core.command(protocol::create_new_effect_report(params, record.samples), what, FrameKind::set_feature);
        !s.ok()) {
        return s;
    }
    Result<protocol::AnyReport> load = core.get_feature(protocol::ReportId::block_load);
    if (!load) {
        Status s = load.status();
        s.message = what + ": " + s.message;
        return s;
    }
    const auto& block_load = std::get<protocol::BlockLoadReport>(load.value());
    switch (block_load.status) {
        case protocol::BlockLoadStatus::success:
            break;
        case protocol::BlockLoadStatus::full:
            return Status::failure(ErrorKind::device_full,
                                   what + ": the device has no room for another effect (Block Load Full; " +
                                       std::to_string(block_load.ram_pool_available) +
                                       " bytes of effect memory free)",
                                   Error::of(ErrorCode::device_full, "effect", "no free effect block"));
        case protocol::BlockLoadStatus::error:
            return Status::failure(ErrorKind::protocol,
                                   what + ": the device answered Block Load Error to an accepted Create New Effect");
    }
    const uint16_t block = block_load.block;
    if (block == 0) {
        return Status::failure(ErrorKind::protocol, what + ": the device's Block Load names block 0");
    }

    for (protocol::AnyReport& report : protocol::parameter_block_reports(params, record.samples, block, true, true)) {
        if (Status s = core.command(std::move(report), what); !s.ok()) {
            free_block(core, block);
            return s;
        }
    }
    if (Status s = core.command(protocol::set_effect_report(params, block), what); !s.ok()) {
        free_block(core, block);
        return s;
    }
    if (params.trigger.kind != TriggerKind::none && core.caps.local_reflexes) {
        protocol::ReflexReport reflex;
        reflex.block = block;
        reflex.assign = true;
        if (Status s = core.command(reflex, what); !s.ok()) {
            free_block(core, block);
            return s;
        }
    }
    core.set_downloaded(record, block, emulate);
    return Status::success();
}

Status update_effect(DeviceCore& core, EffectRecord& record, const EffectParams& merged,
                     std::span<const int16_t> samples, uint32_t mask, bool restart, const std::string& what) {
    using namespace effect_field;
    const uint16_t block = record.block;
    const EffectParams params = device_params(core.caps, merged);
    const bool emulate = host_emulates_trigger(core.caps, merged);

    for (protocol::AnyReport& report : protocol::parameter_block_reports(params, samples, block, (mask & kEnvelope) != 0,
                                                               (mask & kTypeSpecific) != 0)) {
        if (Status s = core.command(std::move(report), what); !s.ok()) return s;
    }
    // Set Effect carries the whole Effect Structure; the device applies what differs.
    if (Status s = core.command(protocol::set_effect_report(params, block), what); !s.ok()) return s;
    const bool trigger_changed = (mask & (kTrigger | kTriggerRepeat)) != 0;
    if (trigger_changed && core.caps.local_reflexes && params.trigger.kind != TriggerKind::none) {
        protocol::ReflexReport reflex;
        reflex.block = block;
        reflex.assign = true;
        if (Status s = core.command(reflex, what); !s.ok()) return s;
    }
    {
        std::lock_guard lock(core.mu);
        record.params = merged;
        if (merged.type == EffectType::force_profile && (mask & kTypeSpecific)) {
            record.samples.assign(samples.begin(), samples.end());
        }
        if (trigger_changed || emulate != record.emulate_trigger) {
            record.emulate_trigger = emulate;
            record.trigger_down = false;
            if (emulate) {
                const Trigger& t = merged.trigger;
                const uint32_t bits = t.kind == TriggerKind::hat ? core.input.hats : core.input.buttons;
                record.trigger_down = ((bits >> (t.index - 1)) & 1u) != 0;
            }
            record.next_repeat = Clock::now() + std::chrono::microseconds(merged.trigger_repeat_interval_us);
        }
    }
    if (restart) {
        protocol::EffectOperationReport op;
        op.block = block;
        op.operation = protocol::EffectOperation::start;
        op.loop_count = protocol::kLoopEffectOwn;
        if (Status s = core.command(op, what); !s.ok()) return s;
        std::lock_guard lock(core.mu);
        record.host_started = false;
    }
    return Status::success();
}

}  // namespace feel::host
