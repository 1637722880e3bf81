// The conversions between the host's EffectParams and a slot's SlotParams (slot_params.hpp).
#include "slot_params.hpp"

#include <cmath>

#include "conditions/condition.hpp"

namespace feel::detail {
namespace {

// The block a type reads (§6.6), by the member of SlotParams' union that holds it.
enum class Block : uint8_t { curved, conditions, periodic, constant, ramp, custom, texture, wall, barrier, dynamic };

constexpr Block block_of(EffectType t) noexcept {
    switch (t) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::angle_spring: return Block::curved;
        case EffectType::friction: return Block::conditions;
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: return Block::barrier;
        case EffectType::axis_wall:
        case EffectType::angle_wall: return Block::wall;
        case EffectType::texture: return Block::texture;
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop: return Block::constant;
        case EffectType::force_profile: return Block::custom;
        case EffectType::ramp: return Block::ramp;
        default: break;
    }
    return effect_class(t) == EffectClass::dynamic ? Block::dynamic : Block::periodic;  // periodics, sweeps
}

// The condition blocks an effect reads (the validated ones): an angle spring's one, else one
// per axis of the effect.
int condition_blocks(const EffectParams& p) noexcept {
    return p.type == EffectType::angle_spring ? 1 : p.axis_count;
}

// The block a curve was made from (curve_of): the floats of integers within ±10000 are
// exact, and a slope is -coefficient / 10000 rounded twice in float; times 10000, rounded
// once more, it is within 3e-3 of the coefficient, so the nearest integer is the
// coefficient. (Float, not double: the board has no double unit.)
ConditionBlock block_of_curve(const ConditionCurve& c, OffsetMode mode) noexcept {
    constexpr float kScale = static_cast<float>(kFullScale);
    ConditionBlock b;
    b.pos_coefficient = static_cast<int32_t>(std::lround(-c.pos_slope * kScale));
    b.neg_coefficient = static_cast<int32_t>(std::lround(-c.neg_slope * kScale));
    b.offset = static_cast<int32_t>(c.offset);
    b.pos_saturation = static_cast<int32_t>(c.pos_cap);
    b.neg_saturation = static_cast<int32_t>(c.neg_cap);
    b.deadband = static_cast<int32_t>(c.band);
    b.offset_mode = mode;
    return b;
}

}  // namespace

SlotParams slot_params(const EffectParams& p, const DynamicBlock* dynamic_block) noexcept {
    SlotParams s;
    // Every value is within its range (validated), so each narrowing keeps it exactly.
    s.type = p.type;
    s.duration_us = static_cast<int32_t>(p.duration_us);
    s.start_delay_us = p.start_delay_us;
    s.gain = static_cast<int16_t>(p.gain);
    s.iterations = static_cast<int16_t>(p.iterations);
    s.axis_count = static_cast<int8_t>(p.axis_count);
    for (int i = 0; i < kMaxAxes; ++i) s.axes[i] = p.axes[i];
    s.direction = p.direction;
    s.trigger_kind = p.trigger.kind;
    s.trigger_repeat_interval_us = static_cast<int32_t>(p.trigger_repeat_interval_us);
    s.has_envelope = p.has_envelope;
    // An envelope without has_envelope, a trigger index without a trigger: not read, not
    // validated, not kept (they read back as their defaults, as the other types' blocks).
    if (p.trigger.kind != TriggerKind::none) s.trigger_index = static_cast<int8_t>(p.trigger.index);
    if (p.has_envelope) {
        s.envelope.settle_time_us = static_cast<int32_t>(p.envelope.settle_time_us);
        s.envelope.fade_time_us = static_cast<int32_t>(p.envelope.fade_time_us);
        s.envelope.impulse_level = static_cast<int16_t>(p.envelope.impulse_level);
        s.envelope.fade_level = static_cast<int16_t>(p.envelope.fade_level);
    }
    // Assigning a member of the union makes it the live one (the blocks are trivially copyable).
    switch (block_of(p.type)) {
        case Block::curved:
            s.curved = CurvedConditions{};
            for (int i = 0; i < condition_blocks(p); ++i) {
                s.curved.curves[i] = curve_of(p.conditions[i]);
                s.curved.offset_modes[i] = p.conditions[i].offset_mode;
            }
            break;
        case Block::conditions:
            for (int i = 0; i < condition_blocks(p); ++i) s.conditions[i] = p.conditions[i];
            break;
        case Block::periodic: s.periodic = p.periodic; break;
        case Block::constant: s.constant = p.constant; break;
        case Block::ramp: s.ramp = p.ramp; break;
        case Block::custom: s.custom = p.custom; break;
        case Block::texture: s.texture = p.texture; break;
        case Block::wall: s.wall = p.wall; break;
        case Block::barrier: s.barrier = p.barrier; break;
        case Block::dynamic: s.dynamic = dynamic_block; break;
    }
    return s;
}

EffectParams effect_params(const SlotParams& s) noexcept {
    EffectParams p;
    p.type = s.type;
    p.duration_us = s.duration_us;
    p.start_delay_us = s.start_delay_us;
    p.gain = s.gain;
    p.iterations = s.iterations;
    p.axis_count = s.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) p.axes[i] = s.axes[i];
    p.direction = s.direction;
    p.trigger.kind = s.trigger_kind;
    p.trigger.index = s.trigger_index;
    p.trigger_repeat_interval_us = s.trigger_repeat_interval_us;
    p.has_envelope = s.has_envelope;
    p.envelope.settle_time_us = s.envelope.settle_time_us;
    p.envelope.fade_time_us = s.envelope.fade_time_us;
    p.envelope.impulse_level = s.envelope.impulse_level;
    p.envelope.fade_level = s.envelope.fade_level;
    switch (block_of(s.type)) {
        case Block::curved:
            for (int i = 0; i < condition_blocks(p); ++i) {
                p.conditions[i] = block_of_curve(s.curved.curves[i], s.curved.offset_modes[i]);
            }
            break;
        case Block::conditions:
            for (int i = 0; i < condition_blocks(p); ++i) p.conditions[i] = s.conditions[i];
            break;
        case Block::periodic: p.periodic = s.periodic; break;
        case Block::constant: p.constant = s.constant; break;
        case Block::ramp: p.ramp = s.ramp; break;
        case Block::custom: p.custom = s.custom; break;
        case Block::texture: p.texture = s.texture; break;
        case Block::wall: p.wall = s.wall; break;
        case Block::barrier: p.barrier = s.barrier; break;
        case Block::dynamic: p.dynamic = *s.dynamic; break;
    }
    return p;
}

}  // namespace feel::detail
