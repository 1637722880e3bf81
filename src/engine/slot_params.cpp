// The conversions between the host's EffectParams and a slot's SlotParams (slot_params.hpp).
#include "slot_params.hpp"

#include <cmath>
#include <limits>

#include "conditions/condition.hpp"
#include "envelope.hpp"

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

// Every narrowed field holds every value the validator admits (effect_validation.cpp, the
// ranges of feel/units.hpp): a proof over the whole range, at compile time.
template <class Field>
constexpr bool holds(Range r) noexcept {
    return r.min >= std::numeric_limits<Field>::min() && r.max <= std::numeric_limits<Field>::max();
}
static_assert(holds<int32_t>(range::kDelayUs) && holds<int32_t>(range::kPeriodUs));
static_assert(holds<int16_t>(range::kSignedLevel) && holds<int16_t>(range::kLevel));
static_assert(holds<int16_t>(range::kDynamicMass) && holds<int16_t>(range::kDynamicStiffness) &&
              holds<int16_t>(range::kHalfCycles));
static_assert(holds<uint16_t>(range::kAngle) && holds<uint16_t>(range::kElevation));
static_assert(holds<int16_t>(range::kCartesianComponent));

// The fields each dynamic reads (§8.4), as the validator's tables list them
// (effect_field_rules.hpp: kRecoilRules ... kControlLawRules).
#define FEEL_RECOIL_FIELDS(X) X(blast_direction) X(blast_intensity) X(dynamic_mass) X(blast_resonance) X(blast_decay)
#define FEEL_IMPACT_FIELDS(X) \
    X(impact_direction) X(impact_intensity) X(dynamic_mass) X(elasticity) X(collision_absorption)
#define FEEL_LIQUID_FIELDS(X) X(density) X(settle) X(viscosity)
#define FEEL_INERTIA_FIELDS(X) X(inertia) X(play)
#define FEEL_CENTER_DRIFT_FIELDS(X) X(stiffness) X(drift_resistance)
#define FEEL_SLING_FIELDS(X) X(ball_mass) X(string_length) X(string_compliance) X(ball_damping)
#define FEEL_PADDLE_FIELDS(X) \
    X(ball_mass) X(initial_velocity) X(initial_velocity_direction) X(paddle_compliance) X(paddle_damping) X(gravity)
#define FEEL_CONTROL_LAW_FIELDS(X) \
    X(mass) X(k_pos) X(k_neg) X(b) X(vel_init) X(pos_init) X(half_cycles) X(length) X(drag) X(gravity)

// Copies the fields a dynamic of type t on `axes` axes reads from one form of its block to
// the other (both have DynamicBlock's field names); the others keep to's values.
template <class To, class From>
void copy_dynamic_fields(EffectType t, int axes, const From& from, To& to) noexcept {
#define FEEL_COPY(field) to.field = static_cast<decltype(to.field)>(from.field);
#define FEEL_COPY_LAW(field) \
    to.control_law[i].field = static_cast<decltype(to.control_law[i].field)>(from.control_law[i].field);
    switch (t) {
        case EffectType::dynamic_recoil: FEEL_RECOIL_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_impact: FEEL_IMPACT_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_liquid: FEEL_LIQUID_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_inertia: FEEL_INERTIA_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_center_drift: FEEL_CENTER_DRIFT_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_sling: FEEL_SLING_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_paddle: FEEL_PADDLE_FIELDS(FEEL_COPY) break;
        case EffectType::dynamic_control_law:
            for (int i = 0; i < axes; ++i) {
                FEEL_CONTROL_LAW_FIELDS(FEEL_COPY_LAW)
            }
            break;
        default: break;
    }
    to.interim_reporting = from.interim_reporting;
#undef FEEL_COPY_LAW
#undef FEEL_COPY
}

// A friction's block between its forms (the host's int32 fields, the slot's int16).
template <class To, class From>
To condition_block(const From& from) noexcept {
    To to;
    to.pos_coefficient = static_cast<decltype(to.pos_coefficient)>(from.pos_coefficient);
    to.neg_coefficient = static_cast<decltype(to.neg_coefficient)>(from.neg_coefficient);
    to.offset = static_cast<decltype(to.offset)>(from.offset);
    to.pos_saturation = static_cast<decltype(to.pos_saturation)>(from.pos_saturation);
    to.neg_saturation = static_cast<decltype(to.neg_saturation)>(from.neg_saturation);
    to.deadband = static_cast<decltype(to.deadband)>(from.deadband);
    to.offset_mode = from.offset_mode;
    return to;
}

// The values of a direction its kind reads (effect_validation.cpp checks exactly these).
int direction_values(DirectionKind kind, int axis_count) noexcept {
    switch (kind) {
        case DirectionKind::polar: return 1;
        case DirectionKind::spherical: return 2;
        case DirectionKind::cartesian:
        case DirectionKind::moments: return axis_count < 3 ? axis_count : 3;
        default: return 0;
    }
}

SlotDirection slot_direction(const Direction& d, int axis_count) noexcept {
    SlotDirection s;
    s.kind = d.kind;
    for (int i = 0; i < direction_values(d.kind, axis_count); ++i) {
        s.bits[i] = static_cast<uint16_t>(d.value[i]);  // an angle, or a component's two's complement
    }
    return s;
}

Direction direction_of(const SlotDirection& s, int axis_count) noexcept {
    Direction d;
    d.kind = s.kind;
    for (int i = 0; i < direction_values(s.kind, axis_count); ++i) d.value[i] = s.value(i);
    return d;
}

// A periodic's block between its forms; the period is the only field whose type differs.
template <class To, class From>
To periodic_block(const From& from) noexcept {
    To to;
    to.magnitude = from.magnitude;
    to.offset = from.offset;
    to.period_us = static_cast<decltype(to.period_us)>(from.period_us);
    to.phase = from.phase;
    to.sweep_start_angle = from.sweep_start_angle;
    to.sweep_end_angle = from.sweep_end_angle;
    to.sweep_sense = from.sweep_sense;
    return to;
}

// A force profile's block between its forms; the sample period is the field whose type differs.
template <class To, class From>
To custom_block(const From& from) noexcept {
    To to;
    to.channels = from.channels;
    to.sample_period_us = static_cast<decltype(to.sample_period_us)>(from.sample_period_us);
    to.sample_count = from.sample_count;
    return to;
}

#undef FEEL_CONTROL_LAW_FIELDS
#undef FEEL_PADDLE_FIELDS
#undef FEEL_SLING_FIELDS
#undef FEEL_CENTER_DRIFT_FIELDS
#undef FEEL_INERTIA_FIELDS
#undef FEEL_LIQUID_FIELDS
#undef FEEL_IMPACT_FIELDS
#undef FEEL_RECOIL_FIELDS

}  // namespace

SlotDynamicBlock slot_dynamic_block(const EffectParams& p) noexcept {
    SlotDynamicBlock s;
    copy_dynamic_fields(p.type, p.axis_count, p.dynamic, s);
    return s;
}

SlotParams slot_params(const EffectParams& p, const SlotDynamicBlock* dynamic_block) noexcept {
    SlotParams s;
    // Every value is within its range (validated), so each narrowing keeps it exactly.
    s.type = p.type;
    s.duration_us = static_cast<int32_t>(p.duration_us);
    s.start_delay_us = static_cast<int32_t>(p.start_delay_us);
    s.gain = static_cast<int16_t>(p.gain);
    s.iterations = static_cast<int16_t>(p.iterations);
    s.axis_count = static_cast<int8_t>(p.axis_count);
    for (int i = 0; i < kMaxAxes; ++i) s.axes[i] = p.axes[i];
    s.direction = slot_direction(p.direction, p.axis_count);
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
    // The waves' envelope window, from the header's fields above (kept in each wave's block).
    const SteadyWindow steady = steady_window(s);
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
            for (int i = 0; i < condition_blocks(p); ++i) {
                s.conditions[i] = condition_block<SlotConditionBlock>(p.conditions[i]);
            }
            break;
        case Block::periodic:
            s.periodic = periodic_block<SlotPeriodicBlock>(p.periodic);
            s.periodic.steady = steady;
            prepare_periodic_block(s);  // the header's fields above are set
            break;
        case Block::constant:
            s.constant = {p.constant.magnitude, steady};
            break;
        case Block::ramp: s.ramp = {p.ramp.start, p.ramp.end, steady}; break;
        case Block::custom:
            s.custom = custom_block<SlotCustomBlock>(p.custom);
            s.custom.steady = steady;
            break;
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
    p.direction = direction_of(s.direction, s.axis_count);
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
            for (int i = 0; i < condition_blocks(p); ++i) {
                p.conditions[i] = condition_block<ConditionBlock>(s.conditions[i]);
            }
            break;
        case Block::periodic: p.periodic = periodic_block<PeriodicBlock>(s.periodic); break;
        case Block::constant: p.constant.magnitude = s.constant.magnitude; break;
        case Block::ramp: p.ramp = {s.ramp.start, s.ramp.end}; break;
        case Block::custom: p.custom = custom_block<CustomBlock>(s.custom); break;
        case Block::texture: p.texture = s.texture; break;
        case Block::wall: p.wall = s.wall; break;
        case Block::barrier: p.barrier = s.barrier; break;
        case Block::dynamic: copy_dynamic_fields(s.type, s.axis_count, *s.dynamic, p.dynamic); break;
    }
    return p;
}

}  // namespace feel::detail
