// EffectParams -> HID PID reports. Each field is copied into its wire field; the narrowing
// casts are safe because the parameters passed validate_effect() first.
#include "feel/protocol/effect_reports.hpp"

#include <algorithm>

#include "feel/effect_type.hpp"

namespace feel::protocol {

void set_sequence(AnyReport& report, uint32_t sequence) noexcept {
    std::visit(
        [sequence](auto& r) {
            if constexpr (requires { r.sequence; }) r.sequence = sequence;
        },
        report);
}

uint32_t wire_duration(int64_t us) noexcept {
    return us == kInfiniteUs ? kWireInfinite : static_cast<uint32_t>(us);
}

uint16_t wire_iterations(int32_t iterations) noexcept {
    return iterations == kInfiniteIterations ? kLoopInfinite : static_cast<uint16_t>(iterations);
}

CreateNewEffectReport create_new_effect_report(const EffectParams& params, std::span<const int16_t> samples) {
    CreateNewEffectReport r;
    r.type = params.type;
    r.sample_count = params.type == EffectType::force_profile ? static_cast<uint16_t>(samples.size()) : 0;
    return r;
}

SetEffectReport set_effect_report(const EffectParams& p, uint16_t block) {
    SetEffectReport r;
    r.block = block;
    r.type = p.type;
    r.duration_us = wire_duration(p.duration_us);
    r.start_delay_us = static_cast<uint32_t>(p.start_delay_us);
    r.trigger_repeat_interval_us = static_cast<uint32_t>(p.trigger_repeat_interval_us);
    r.gain = static_cast<uint16_t>(p.gain);
    r.iterations = wire_iterations(p.iterations);
    r.trigger_kind = p.trigger.kind;
    r.trigger_index = p.trigger.kind == TriggerKind::none ? 0 : static_cast<uint8_t>(p.trigger.index);
    r.axis_count = static_cast<uint8_t>(p.axis_count);
    std::copy(std::begin(p.axes), std::end(p.axes), std::begin(r.axes));
    for (int i = 0; i < p.axis_count && i < kMaxAxes; ++i) {
        r.axes_enable = static_cast<uint8_t>(r.axes_enable | (1u << static_cast<int>(p.axes[i])));
    }
    r.direction_kind = p.direction.kind;
    std::copy(std::begin(p.direction.value), std::end(p.direction.value), std::begin(r.direction));
    r.has_envelope = p.has_envelope;
    return r;
}

namespace {

SetConditionReport condition_report(const ConditionBlock& c, uint16_t block, int axis) {
    SetConditionReport r;
    r.block = block;
    r.axis_index = static_cast<uint8_t>(axis);
    r.center_offset = static_cast<int16_t>(c.offset);
    r.pos_coefficient = static_cast<int16_t>(c.pos_coefficient);
    r.neg_coefficient = static_cast<int16_t>(c.neg_coefficient);
    r.pos_saturation = static_cast<uint16_t>(c.pos_saturation);
    r.neg_saturation = static_cast<uint16_t>(c.neg_saturation);
    r.deadband = static_cast<uint16_t>(c.deadband);
    r.offset_mode = c.offset_mode;
    return r;
}

SetPeriodicReport periodic_report(const PeriodicBlock& w, uint16_t block) {
    SetPeriodicReport r;
    r.block = block;
    r.magnitude = static_cast<int16_t>(w.magnitude);
    r.offset = static_cast<int16_t>(w.offset);
    r.phase = static_cast<uint16_t>(w.phase);
    r.period_us = static_cast<uint32_t>(w.period_us);
    return r;
}

void append_custom(std::vector<AnyReport>& out, const EffectParams& p, std::span<const int16_t> samples,
                   uint16_t block) {
    // The samples first, in chunks, offset 0 starting the profile; then the block that
    // names how they are played.
    for (std::size_t offset = 0; offset < samples.size(); offset += kSamplesPerDataReport) {
        CustomForceDataReport d;
        d.block = block;
        d.offset = static_cast<uint16_t>(offset);
        const std::size_t n = std::min<std::size_t>(kSamplesPerDataReport, samples.size() - offset);
        d.count = static_cast<uint8_t>(n);
        std::copy_n(samples.begin() + static_cast<std::ptrdiff_t>(offset), n, d.samples);
        out.emplace_back(d);
    }
    SetCustomForceReport c;
    c.block = block;
    c.channels = static_cast<uint8_t>(p.custom.channels);
    c.sample_period_us = static_cast<uint32_t>(p.custom.sample_period_us);
    c.sample_count = static_cast<uint16_t>(samples.size());
    out.emplace_back(c);
}

void append_type_blocks(std::vector<AnyReport>& out, const EffectParams& p, std::span<const int16_t> samples,
                        uint16_t block) {
    const EffectType t = p.type;
    if (is_periodic(t) || is_sweep(t)) {
        out.emplace_back(periodic_report(p.periodic, block));
        if (is_sweep(t)) {
            SetSweepReport s;
            s.block = block;
            s.start_angle = static_cast<uint16_t>(p.periodic.sweep_start_angle);
            s.end_angle = static_cast<uint16_t>(p.periodic.sweep_end_angle);
            s.sense = p.periodic.sweep_sense;
            out.emplace_back(s);
        }
        return;
    }
    switch (t) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction:
            // With a direction, one block applied along it (§3.1): only axis 0's Set Condition
            // goes, and the device reads the missing ones as that form (docs/protocol.md).
            if (is_directed_condition(p)) {
                out.emplace_back(condition_report(p.conditions[0], block, 0));
                return;
            }
            for (int i = 0; i < p.axis_count; ++i) out.emplace_back(condition_report(p.conditions[i], block, i));
            return;
        case EffectType::angle_spring:  // one condition along its angle
            out.emplace_back(condition_report(p.conditions[0], block, 0));
            return;
        case EffectType::texture: {
            SetTextureReport r;
            r.block = block;
            r.texture = p.texture;
            out.emplace_back(r);
            return;
        }
        case EffectType::axis_wall:
        case EffectType::angle_wall: {
            SetWallReport r;
            r.block = block;
            r.wall = p.wall;
            out.emplace_back(r);
            return;
        }
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: {
            SetBarrierReport r;
            r.block = block;
            r.barrier = p.barrier;
            out.emplace_back(r);
            return;
        }
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop: {
            SetConstantForceReport r;
            r.block = block;
            r.magnitude = static_cast<int16_t>(p.constant.magnitude);
            out.emplace_back(r);
            return;
        }
        case EffectType::ramp: {
            SetRampForceReport r;
            r.block = block;
            r.start = static_cast<int16_t>(p.ramp.start);
            r.end = static_cast<int16_t>(p.ramp.end);
            out.emplace_back(r);
            return;
        }
        case EffectType::force_profile:
            append_custom(out, p, samples, block);
            return;
        default:
            break;
    }
    if (effect_class(t) == EffectClass::dynamic) {
        SetDynamicReport d;
        d.block = block;
        d.dynamic = p.dynamic;
        // The control laws travel in their own reports (one per axis), not in this one.
        std::fill(std::begin(d.dynamic.control_law), std::end(d.dynamic.control_law), ControlLawBlock{});
        out.emplace_back(d);
        if (t == EffectType::dynamic_control_law) {
            for (int i = 0; i < p.axis_count; ++i) {
                SetControlLawReport law;
                law.block = block;
                law.axis_index = static_cast<uint8_t>(i);
                law.law = p.dynamic.control_law[i];
                out.emplace_back(law);
            }
        }
    }
}

}  // namespace

std::vector<AnyReport> parameter_block_reports(const EffectParams& p, std::span<const int16_t> samples,
                                               uint16_t block, bool envelope, bool type_specific) {
    std::vector<AnyReport> out;
    if (envelope && p.has_envelope) {
        SetEnvelopeReport e;
        e.block = block;
        e.impulse_level = static_cast<uint16_t>(p.envelope.impulse_level);
        e.settle_time_us = static_cast<uint32_t>(p.envelope.settle_time_us);
        e.fade_level = static_cast<uint16_t>(p.envelope.fade_level);
        e.fade_time_us = static_cast<uint32_t>(p.envelope.fade_time_us);
        out.emplace_back(e);
    }
    if (type_specific) append_type_blocks(out, p, samples, block);
    return out;
}

}  // namespace feel::protocol
