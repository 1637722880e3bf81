// feel.h: effects from a parameter struct — feel_effect_params <-> feel::EffectParams,
// feel_create_effect, feel_effect_get_parameters / set_parameters, download and unload.
//
// The C struct mirrors EffectParams field for field, with int32_t in place of the C++
// enumerations. Converting to C++ checks each enumeration's range first (a value that does
// not fit the enum's uint8_t would otherwise wrap into a valid one); every other range is
// the host's to check (validate_effect and the device's capabilities), so a C caller gets
// exactly the messages a C++ caller gets.
#include <span>

#include "capi_internal.hpp"

namespace feel::capi {
namespace {

static_assert(static_cast<int>(EffectType::spring) == FEEL_TYPE_SPRING);
static_assert(static_cast<int>(EffectType::texture) == FEEL_TYPE_TEXTURE);
static_assert(static_cast<int>(EffectType::ramp) == FEEL_TYPE_RAMP);
static_assert(static_cast<int>(EffectType::dynamic_paddle) == FEEL_TYPE_DYNAMIC_PADDLE);
static_assert(kEffectTypeCount == FEEL_TYPE_COUNT);
static_assert(static_cast<int>(DirectionKind::moments) == FEEL_DIRECTION_MOMENTS);
static_assert(static_cast<int>(OffsetMode::relative) == FEEL_OFFSET_RELATIVE);
static_assert(static_cast<int>(TriggerKind::hat) == FEEL_TRIGGER_HAT);
static_assert(static_cast<int>(Axis::rz) == FEEL_AXIS_RZ);
static_assert(effect_field::kDuration == FEEL_FIELD_DURATION);
static_assert(effect_field::kStartDelay == FEEL_FIELD_START_DELAY);
static_assert(effect_field::kGain == FEEL_FIELD_GAIN);
static_assert(effect_field::kIterations == FEEL_FIELD_ITERATIONS);
static_assert(effect_field::kAxes == FEEL_FIELD_AXES);
static_assert(effect_field::kDirection == FEEL_FIELD_DIRECTION);
static_assert(effect_field::kTrigger == FEEL_FIELD_TRIGGER);
static_assert(effect_field::kTriggerRepeat == FEEL_FIELD_TRIGGER_REPEAT);
static_assert(effect_field::kEnvelope == FEEL_FIELD_ENVELOPE);
static_assert(effect_field::kTypeSpecific == FEEL_FIELD_TYPE_SPECIFIC);
static_assert(effect_field::kAll == FEEL_FIELD_ALL);

// A C enumeration's value as the C++ enum E, or std::invalid_argument naming the field and
// its range (guard() turns it into FEEL_ERROR_INVALID_PARAMETER).
template <class E>
E enum_value(const char* function, const std::string& field, int32_t value, int32_t last) {
    if (value < 0 || value > last) {
        out_of_range(function, field.c_str(), value, 0, last);
        throw std::invalid_argument(feel_last_error_message());
    }
    return static_cast<E>(value);
}

template <class E>
int32_t c_enum(E e) noexcept {
    return static_cast<int32_t>(e);
}

std::string indexed(const char* name, int i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

}  // namespace

// ---- C -> C++ -------------------------------------------------------------------------

EffectParams to_cpp(const char* fn, const feel_effect_params& c) {
    EffectParams p;
    p.type = enum_value<EffectType>(fn, "type", c.type, FEEL_TYPE_COUNT - 1);
    p.duration_us = c.duration_us;
    p.start_delay_us = c.start_delay_us;
    p.gain = c.gain;
    p.iterations = c.iterations;
    p.axis_count = c.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) p.axes[i] = enum_value<Axis>(fn, indexed("axes", i), c.axes[i], FEEL_AXIS_RZ);
    p.direction.kind = enum_value<DirectionKind>(fn, "direction.kind", c.direction.kind, FEEL_DIRECTION_MOMENTS);
    for (int i = 0; i < 3; ++i) p.direction.value[i] = c.direction.value[i];
    p.trigger.kind = enum_value<TriggerKind>(fn, "trigger.kind", c.trigger.kind, FEEL_TRIGGER_HAT);
    p.trigger.index = c.trigger.index;
    p.trigger_repeat_interval_us = c.trigger_repeat_interval_us;
    p.has_envelope = c.has_envelope;
    p.envelope = Envelope{c.envelope.impulse_level, c.envelope.settle_time_us, c.envelope.fade_level,
                          c.envelope.fade_time_us};
    for (int i = 0; i < kMaxAxes; ++i) {
        const feel_condition_block& k = c.conditions[i];
        p.conditions[i] = ConditionBlock{
            k.pos_coefficient, k.neg_coefficient, k.offset, k.pos_saturation, k.neg_saturation, k.deadband,
            enum_value<OffsetMode>(fn, indexed("conditions", i) + ".offset_mode", k.offset_mode, FEEL_OFFSET_RELATIVE)};
    }
    const feel_periodic_block& w = c.periodic;
    p.periodic = PeriodicBlock{w.magnitude, w.offset, w.period_us, w.phase, w.sweep_start_angle, w.sweep_end_angle,
                               enum_value<SweepSense>(fn, "periodic.sweep_sense", w.sweep_sense,
                                                      FEEL_SWEEP_COUNTERCLOCKWISE)};
    p.constant.magnitude = c.constant_magnitude;
    p.ramp = RampBlock{c.ramp_start, c.ramp_end};
    p.custom = CustomBlock{c.custom.channels, c.custom.sample_period_us, c.custom.sample_count};
    p.texture = TextureBlock{c.texture.pos_roughness, c.texture.neg_roughness, c.texture.spacing, c.texture.density};
    const feel_wall_block& wall = c.wall;
    p.wall = WallBlock{wall.hardness,
                       enum_value<WallSense>(fn, "wall.sense", wall.sense, FEEL_WALL_SENSE_NEGATIVE),
                       wall.offset,
                       enum_value<OffsetMode>(fn, "wall.offset_mode", wall.offset_mode, FEEL_OFFSET_RELATIVE),
                       wall.angle,
                       wall.surface_friction,
                       wall.surface_texture,
                       wall.clipping};
    const feel_barrier_block& b = c.barrier;
    p.barrier = BarrierBlock{b.pos_hardness,
                             b.neg_hardness,
                             b.thickness,
                             b.offset,
                             b.angle,
                             b.surface_friction,
                             b.surface_texture,
                             enum_value<OffsetMode>(fn, "barrier_offset_mode", c.barrier_offset_mode,
                                                    FEEL_OFFSET_RELATIVE)};
    const feel_dynamic_block& d = c.dynamic;
    DynamicBlock& pd = p.dynamic;
    pd.blast_direction = d.blast_direction;
    pd.blast_intensity = d.blast_intensity;
    pd.blast_resonance = d.blast_resonance;
    pd.blast_decay = d.blast_decay;
    pd.dynamic_mass = d.dynamic_mass;
    pd.impact_direction = d.impact_direction;
    pd.impact_intensity = d.impact_intensity;
    pd.elasticity = d.elasticity;
    pd.collision_absorption = d.collision_absorption;
    pd.density = d.density;
    pd.settle = d.settle;
    pd.viscosity = d.viscosity;
    pd.inertia = d.inertia;
    pd.play = d.play;
    pd.stiffness = d.stiffness;
    pd.drift_resistance = d.drift_resistance;
    pd.ball_mass = d.ball_mass;
    pd.string_length = d.string_length;
    pd.string_compliance = d.string_compliance;
    pd.ball_damping = d.ball_damping;
    pd.initial_velocity = d.initial_velocity;
    pd.initial_velocity_direction = d.initial_velocity_direction;
    pd.paddle_compliance = d.paddle_compliance;
    pd.paddle_damping = d.paddle_damping;
    pd.gravity = d.gravity;
    for (int i = 0; i < kMaxAxes; ++i) {
        const feel_control_law_block& l = d.control_law[i];
        pd.control_law[i] = ControlLawBlock{l.mass,        l.k_pos,  l.k_neg,  l.b,    l.vel_init,
                                            l.pos_init,    l.half_cycles, l.length, l.drag, l.gravity};
    }
    pd.interim_reporting = d.interim_reporting;
    return p;
}

namespace {

// ---- C++ -> C -------------------------------------------------------------------------

feel_effect_params to_c(const EffectParams& p) noexcept {
    feel_effect_params c{};
    c.size = sizeof c;
    c.type = c_enum(p.type);
    c.duration_us = p.duration_us;
    c.start_delay_us = p.start_delay_us;
    c.gain = p.gain;
    c.iterations = p.iterations;
    c.axis_count = p.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) c.axes[i] = c_enum(p.axes[i]);
    c.direction.kind = c_enum(p.direction.kind);
    for (int i = 0; i < 3; ++i) c.direction.value[i] = p.direction.value[i];
    c.trigger = feel_trigger{c_enum(p.trigger.kind), p.trigger.index};
    c.trigger_repeat_interval_us = p.trigger_repeat_interval_us;
    c.has_envelope = p.has_envelope;
    c.envelope = feel_envelope{p.envelope.impulse_level, p.envelope.settle_time_us, p.envelope.fade_level,
                               p.envelope.fade_time_us};
    for (int i = 0; i < kMaxAxes; ++i) {
        const ConditionBlock& k = p.conditions[i];
        c.conditions[i] = feel_condition_block{k.pos_coefficient, k.neg_coefficient, k.offset,           k.pos_saturation,
                                         k.neg_saturation,  k.deadband,        c_enum(k.offset_mode)};
    }
    const PeriodicBlock& w = p.periodic;
    c.periodic = feel_periodic_block{w.magnitude,         w.offset,          w.period_us, w.phase,
                               w.sweep_start_angle, w.sweep_end_angle, c_enum(w.sweep_sense)};
    c.constant_magnitude = p.constant.magnitude;
    c.ramp_start = p.ramp.start;
    c.ramp_end = p.ramp.end;
    c.custom = feel_custom_block{p.custom.channels, p.custom.sample_period_us, p.custom.sample_count};
    c.texture = feel_texture_block{p.texture.pos_roughness, p.texture.neg_roughness, p.texture.spacing, p.texture.density};
    const WallBlock& wall = p.wall;
    c.wall = feel_wall_block{wall.hardness, c_enum(wall.sense),    wall.offset,          c_enum(wall.offset_mode),
                       wall.angle,    wall.surface_friction, wall.surface_texture, wall.clipping};
    const BarrierBlock& b = p.barrier;
    c.barrier = feel_barrier_block{b.pos_hardness, b.neg_hardness, b.thickness, b.offset,
                             b.angle, b.surface_friction, b.surface_texture};
    c.barrier_offset_mode = c_enum(b.offset_mode);
    const DynamicBlock& pd = p.dynamic;
    feel_dynamic_block& d = c.dynamic;
    d.blast_direction = pd.blast_direction;
    d.blast_intensity = pd.blast_intensity;
    d.blast_resonance = pd.blast_resonance;
    d.blast_decay = pd.blast_decay;
    d.dynamic_mass = pd.dynamic_mass;
    d.impact_direction = pd.impact_direction;
    d.impact_intensity = pd.impact_intensity;
    d.elasticity = pd.elasticity;
    d.collision_absorption = pd.collision_absorption;
    d.density = pd.density;
    d.settle = pd.settle;
    d.viscosity = pd.viscosity;
    d.inertia = pd.inertia;
    d.play = pd.play;
    d.stiffness = pd.stiffness;
    d.drift_resistance = pd.drift_resistance;
    d.ball_mass = pd.ball_mass;
    d.string_length = pd.string_length;
    d.string_compliance = pd.string_compliance;
    d.ball_damping = pd.ball_damping;
    d.initial_velocity = pd.initial_velocity;
    d.initial_velocity_direction = pd.initial_velocity_direction;
    d.paddle_compliance = pd.paddle_compliance;
    d.paddle_damping = pd.paddle_damping;
    d.gravity = pd.gravity;
    for (int i = 0; i < kMaxAxes; ++i) {
        const ControlLawBlock& l = pd.control_law[i];
        d.control_law[i] = feel_control_law_block{l.mass,     l.k_pos,       l.k_neg,  l.b,    l.vel_init,
                                            l.pos_init, l.half_cycles, l.length, l.drag, l.gravity};
    }
    d.interim_reporting = pd.interim_reporting;
    return c;
}

}  // namespace

std::span<const int16_t> samples_of(const char* function, const int16_t* samples, int32_t sample_count) {
    if (sample_count < 0 || sample_count > 65535) {
        out_of_range(function, "sample_count", sample_count, 0, 65535);
        throw std::invalid_argument(feel_last_error_message());
    }
    if (sample_count > 0 && !samples) {
        null_argument(function, "samples");
        throw std::invalid_argument(feel_last_error_message());
    }
    return {samples, static_cast<std::size_t>(sample_count)};
}

}  // namespace feel::capi

using namespace feel::capi;

extern "C" {

int feel_effect_params_init(feel_effect_params* params, int32_t type) {
    return guard("feel_effect_params_init", [&] {
        if (const int rc = check_out("feel_effect_params_init", "params", params); rc != FEEL_OK) return rc;
        feel::EffectParams p;
        p.type = enum_value<feel::EffectType>("feel_effect_params_init", "type", type, FEEL_TYPE_COUNT - 1);
        write_out(to_c(p), params);
        return succeed();
    });
}

feel_effect* feel_create_effect(feel_device* device, const feel_effect_params* params, const int16_t* samples,
                                int32_t sample_count) {
    return guard_ptr<feel_effect>("feel_create_effect", [&]() -> feel_effect* {
        if (!device) return no_handle(null_argument("feel_create_effect", "device"));
        feel_effect_params in{};
        if (read_in("feel_create_effect", "params", params, in) != FEEL_OK) return nullptr;
        const feel::EffectParams p = to_cpp("feel_create_effect", in);
        const auto span = samples_of("feel_create_effect", samples, sample_count);
        feel::host::Result<feel::host::Effect> effect = device->device.create_effect(p, span);
        if (!effect) return no_handle(fail(effect.status()));
        return new feel_effect(std::move(effect).value());
    });
}

int feel_effect_get_parameters(const feel_effect* effect, feel_effect_params* out) {
    return guard("feel_effect_get_parameters", [&] {
        if (!effect) return null_argument("feel_effect_get_parameters", "effect");
        if (const int rc = check_out("feel_effect_get_parameters", "out", out); rc != FEEL_OK) return rc;
        if (!effect->effect->valid()) {
            return fail(FEEL_ERROR_INVALID_HANDLE, "feel_effect_get_parameters: the effect is no longer on a device");
        }
        write_out(to_c(effect->effect->parameters()), out);
        return succeed();
    });
}

int feel_effect_set_parameters(feel_effect* effect, const feel_effect_params* params, uint32_t field_mask,
                               bool restart, const int16_t* samples, int32_t sample_count) {
    return guard("feel_effect_set_parameters", [&] {
        if (!effect) return null_argument("feel_effect_set_parameters", "effect");
        feel_effect_params in{};
        if (const int rc = read_in("feel_effect_set_parameters", "params", params, in); rc != FEEL_OK) return rc;
        if ((field_mask & ~static_cast<uint32_t>(FEEL_FIELD_ALL)) != 0) {
            return out_of_range("feel_effect_set_parameters", "field_mask", field_mask, 0, FEEL_FIELD_ALL);
        }
        const feel::EffectParams p = to_cpp("feel_effect_set_parameters", in);
        const auto span = samples_of("feel_effect_set_parameters", samples, sample_count);
        return from_status(effect->effect->set_parameters(p, field_mask, restart, span));
    });
}

int feel_effect_download(feel_effect* effect) {
    return guard("feel_effect_download", [&] {
        if (!effect) return null_argument("feel_effect_download", "effect");
        return from_status(effect->effect->download());
    });
}

int feel_effect_unload(feel_effect* effect) {
    return guard("feel_effect_unload", [&] {
        if (!effect) return null_argument("feel_effect_unload", "effect");
        return from_status(effect->effect->unload());
    });
}

}  // extern "C"
