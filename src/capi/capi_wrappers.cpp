// feel.h: the §8 wrapper functions on a device. Each builds the effect with
// feel::iforce (which throws std::invalid_argument naming the wrapper, the parameter and
// its range), creates and downloads it, and returns it stopped.
#include "capi_internal.hpp"
#include "feel/iforce.hpp"

namespace feel::capi {
namespace {

namespace fi = feel::iforce;

// Builds with `build` (may throw std::invalid_argument) and creates the effect on the device.
template <class Build>
feel_effect* create(const char* function, feel_device* device, Build&& build) noexcept {
    return guard_ptr<feel_effect>(function, [&]() -> feel_effect* {
        if (!device) return no_handle(null_argument(function, "device"));
        const EffectParams params = build();  // a bad argument throws: guard() reports it
        host::Result<host::Effect> effect = device->device.create_effect(params);
        if (!effect) return no_handle(fail(effect.status()));
        return new feel_effect(std::move(effect).value());
    });
}

// The C enumerations, checked before they become C++ enums (a value that does not fit the
// enum's uint8_t would otherwise wrap around into a valid one).
Waveform waveform(const char* function, int32_t value) {
    if (value < FEEL_WAVEFORM_SINE || value > FEEL_WAVEFORM_SAW_DOWN) {
        out_of_range(function, "waveform", value, FEEL_WAVEFORM_SINE, FEEL_WAVEFORM_SAW_DOWN);
        throw std::invalid_argument(feel_last_error_message());
    }
    return static_cast<Waveform>(value);
}

WallSense wall_sense(const char* function, int32_t value) {
    if (value != FEEL_WALL_SENSE_POSITIVE && value != FEEL_WALL_SENSE_NEGATIVE) {
        out_of_range(function, "sense", value, FEEL_WALL_SENSE_POSITIVE, FEEL_WALL_SENSE_NEGATIVE);
        throw std::invalid_argument(feel_last_error_message());
    }
    return static_cast<WallSense>(value);
}

SweepSense sweep_sense(const char* function, int32_t value) {
    if (value != FEEL_SWEEP_CLOCKWISE && value != FEEL_SWEEP_COUNTERCLOCKWISE) {
        out_of_range(function, "sense", value, FEEL_SWEEP_CLOCKWISE, FEEL_SWEEP_COUNTERCLOCKWISE);
        throw std::invalid_argument(feel_last_error_message());
    }
    return static_cast<SweepSense>(value);
}

Trigger trigger(const char* function, feel_trigger t) {
    if (t.kind < FEEL_TRIGGER_NONE || t.kind > FEEL_TRIGGER_HAT) {
        out_of_range(function, "trigger.kind", t.kind, FEEL_TRIGGER_NONE, FEEL_TRIGGER_HAT);
        throw std::invalid_argument(feel_last_error_message());
    }
    return Trigger{static_cast<TriggerKind>(t.kind), t.index};
}

Axis axis(const char* function, int32_t value) {
    if (value < FEEL_AXIS_X || value > FEEL_AXIS_RZ) {
        out_of_range(function, "axis", value, FEEL_AXIS_X, FEEL_AXIS_RZ);
        throw std::invalid_argument(feel_last_error_message());
    }
    return static_cast<Axis>(value);
}

static_assert(static_cast<int>(Waveform::sine) == FEEL_WAVEFORM_SINE);
static_assert(static_cast<int>(Waveform::saw_down) == FEEL_WAVEFORM_SAW_DOWN);
static_assert(static_cast<int>(WallSense::negative) == FEEL_WALL_SENSE_NEGATIVE);
static_assert(static_cast<int>(SweepSense::counterclockwise) == FEEL_SWEEP_COUNTERCLOCKWISE);
static_assert(static_cast<int>(TriggerKind::hat) == FEEL_TRIGGER_HAT);
static_assert(static_cast<int>(Axis::rz) == FEEL_AXIS_RZ);
static_assert(static_cast<int>(EffectType::spring) == FEEL_TYPE_SPRING);
static_assert(static_cast<int>(EffectType::texture) == FEEL_TYPE_TEXTURE);
static_assert(static_cast<int>(EffectType::vector_force) == FEEL_TYPE_VECTOR_FORCE);
static_assert(static_cast<int>(EffectType::saw_down) == FEEL_TYPE_SAW_DOWN);
static_assert(static_cast<int>(EffectType::sweep_saw_down) == FEEL_TYPE_SWEEP_SAW_DOWN);
static_assert(static_cast<int>(EffectType::ramp) == FEEL_TYPE_RAMP);
static_assert(static_cast<int>(EffectType::dynamic_recoil) == FEEL_TYPE_DYNAMIC_RECOIL);
static_assert(static_cast<int>(EffectType::dynamic_control_law) == FEEL_TYPE_DYNAMIC_CONTROL_LAW);
static_assert(static_cast<int>(EffectType::dynamic_paddle) == FEEL_TYPE_DYNAMIC_PADDLE);
static_assert(kEffectTypeCount == FEEL_TYPE_COUNT);

}  // namespace
}  // namespace feel::capi

using namespace feel::capi;
namespace fi = feel::iforce;

extern "C" {

// --- §8.2 conditions ------------------------------------------------------------------------

feel_effect* feel_x_spring(feel_device* d, int32_t k_pos, int32_t k_neg, int32_t offset, int32_t pos_saturation,
                           int32_t neg_saturation, int32_t deadband) {
    return create("feel_x_spring", d,
                  [&] { return fi::x_spring(k_pos, k_neg, offset, pos_saturation, neg_saturation, deadband); });
}

feel_effect* feel_y_spring(feel_device* d, int32_t k_pos, int32_t k_neg, int32_t offset, int32_t pos_saturation,
                           int32_t neg_saturation, int32_t deadband) {
    return create("feel_y_spring", d,
                  [&] { return fi::y_spring(k_pos, k_neg, offset, pos_saturation, neg_saturation, deadband); });
}

feel_effect* feel_spring(feel_device* d, int32_t x_k_pos, int32_t x_k_neg, int32_t x_offset, int32_t x_pos_saturation,
                         int32_t x_neg_saturation, int32_t x_deadband, int32_t y_k_pos, int32_t y_k_neg,
                         int32_t y_offset, int32_t y_pos_saturation, int32_t y_neg_saturation, int32_t y_deadband) {
    return create("feel_spring", d, [&] {
        return fi::spring(x_k_pos, x_k_neg, x_offset, x_pos_saturation, x_neg_saturation, x_deadband, y_k_pos, y_k_neg,
                          y_offset, y_pos_saturation, y_neg_saturation, y_deadband);
    });
}

feel_effect* feel_angle_spring(feel_device* d, int32_t k_pos, int32_t k_neg, int32_t offset, int32_t pos_saturation,
                               int32_t neg_saturation, int32_t deadband, int32_t angle) {
    return create("feel_angle_spring", d, [&] {
        return fi::angle_spring(k_pos, k_neg, offset, pos_saturation, neg_saturation, deadband, angle);
    });
}

feel_effect* feel_center_spring(feel_device* d, int32_t k, int32_t saturation, int32_t deadband) {
    return create("feel_center_spring", d, [&] { return fi::center_spring(k, saturation, deadband); });
}

feel_effect* feel_spring_at_current_location(feel_device* d, int32_t k, int32_t saturation, int32_t deadband) {
    return create("feel_spring_at_current_location", d,
                  [&] { return fi::spring_at_current_location(k, saturation, deadband); });
}

feel_effect* feel_x_damper(feel_device* d, int32_t b_pos, int32_t b_neg, int32_t offset, int32_t pos_saturation,
                           int32_t neg_saturation, int32_t deadband) {
    return create("feel_x_damper", d,
                  [&] { return fi::x_damper(b_pos, b_neg, offset, pos_saturation, neg_saturation, deadband); });
}

feel_effect* feel_y_damper(feel_device* d, int32_t b_pos, int32_t b_neg, int32_t offset, int32_t pos_saturation,
                           int32_t neg_saturation, int32_t deadband) {
    return create("feel_y_damper", d,
                  [&] { return fi::y_damper(b_pos, b_neg, offset, pos_saturation, neg_saturation, deadband); });
}

feel_effect* feel_damper(feel_device* d, int32_t x_b_pos, int32_t x_b_neg, int32_t x_offset, int32_t x_pos_saturation,
                         int32_t x_neg_saturation, int32_t x_deadband, int32_t y_b_pos, int32_t y_b_neg,
                         int32_t y_offset, int32_t y_pos_saturation, int32_t y_neg_saturation, int32_t y_deadband) {
    return create("feel_damper", d, [&] {
        return fi::damper(x_b_pos, x_b_neg, x_offset, x_pos_saturation, x_neg_saturation, x_deadband, y_b_pos, y_b_neg,
                          y_offset, y_pos_saturation, y_neg_saturation, y_deadband);
    });
}

feel_effect* feel_x_inertia(feel_device* d, int32_t mass, int32_t saturation) {
    return create("feel_x_inertia", d, [&] { return fi::x_inertia(mass, saturation); });
}

feel_effect* feel_y_inertia(feel_device* d, int32_t mass, int32_t saturation) {
    return create("feel_y_inertia", d, [&] { return fi::y_inertia(mass, saturation); });
}

feel_effect* feel_inertia(feel_device* d, int32_t mass, int32_t saturation) {
    return create("feel_inertia", d, [&] { return fi::inertia(mass, saturation); });
}

feel_effect* feel_friction(feel_device* d, int32_t f) {
    return create("feel_friction", d, [&] { return fi::friction(f); });
}

feel_effect* feel_x_friction(feel_device* d, int32_t f_pos, int32_t f_neg) {
    return create("feel_x_friction", d, [&] { return fi::x_friction(f_pos, f_neg); });
}

feel_effect* feel_y_friction(feel_device* d, int32_t f_pos, int32_t f_neg) {
    return create("feel_y_friction", d, [&] { return fi::y_friction(f_pos, f_neg); });
}

feel_effect* feel_texture(feel_device* d, int32_t roughness, int32_t spacing, int32_t density, int32_t angle) {
    return create("feel_texture", d, [&] { return fi::texture(roughness, spacing, density, angle); });
}

feel_effect* feel_x_texture(feel_device* d, int32_t roughness, int32_t spacing, int32_t density) {
    return create("feel_x_texture", d, [&] { return fi::x_texture(roughness, spacing, density); });
}

feel_effect* feel_x_texture_pos_neg(feel_device* d, int32_t pos_roughness, int32_t neg_roughness, int32_t spacing,
                                    int32_t density) {
    return create("feel_x_texture_pos_neg", d,
                  [&] { return fi::x_texture(pos_roughness, neg_roughness, spacing, density); });
}

feel_effect* feel_y_texture(feel_device* d, int32_t pos_roughness, int32_t neg_roughness, int32_t spacing,
                            int32_t density) {
    return create("feel_y_texture", d, [&] { return fi::y_texture(pos_roughness, neg_roughness, spacing, density); });
}

feel_effect* feel_wall(feel_device* d, int32_t hardness, int32_t sense, int32_t offset, int32_t angle) {
    return create("feel_wall", d,
                  [&] { return fi::wall(hardness, wall_sense("feel_wall", sense), offset, angle); });
}

feel_effect* feel_horizontal_wall(feel_device* d, int32_t hardness, int32_t sense, int32_t offset,
                                  int32_t surface_friction, int32_t surface_texture, bool clipping) {
    return create("feel_horizontal_wall", d, [&] {
        return fi::horizontal_wall(hardness, wall_sense("feel_horizontal_wall", sense), offset, surface_friction,
                                   surface_texture, clipping);
    });
}

feel_effect* feel_vertical_wall(feel_device* d, int32_t hardness, int32_t sense, int32_t offset,
                                int32_t surface_friction, int32_t surface_texture, bool clipping) {
    return create("feel_vertical_wall", d, [&] {
        return fi::vertical_wall(hardness, wall_sense("feel_vertical_wall", sense), offset, surface_friction,
                                 surface_texture, clipping);
    });
}

feel_effect* feel_barrier(feel_device* d, int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                          int32_t offset, int32_t angle) {
    return create("feel_barrier", d,
                  [&] { return fi::barrier(pos_hardness, neg_hardness, thickness, offset, angle); });
}

feel_effect* feel_horizontal_barrier(feel_device* d, int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                                     int32_t offset, int32_t surface_friction, int32_t surface_texture) {
    return create("feel_horizontal_barrier", d, [&] {
        return fi::horizontal_barrier(pos_hardness, neg_hardness, thickness, offset, surface_friction,
                                      surface_texture);
    });
}

feel_effect* feel_vertical_barrier(feel_device* d, int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                                   int32_t offset, int32_t surface_friction, int32_t surface_texture) {
    return create("feel_vertical_barrier", d, [&] {
        return fi::vertical_barrier(pos_hardness, neg_hardness, thickness, offset, surface_friction, surface_texture);
    });
}

// --- §8.3 waves -----------------------------------------------------------------------------

feel_effect* feel_vector_force(feel_device* d, int32_t magnitude, int64_t duration_us, int32_t direction) {
    return create("feel_vector_force", d, [&] { return fi::vector_force(magnitude, duration_us, direction); });
}

feel_effect* feel_constant_force(feel_device* d, int32_t magnitude, int64_t duration_us, int32_t direction) {
    return create("feel_constant_force", d, [&] { return fi::constant_force(magnitude, duration_us, direction); });
}

feel_effect* feel_constant_force_trigger(feel_device* d, int32_t magnitude, int64_t duration_us, int32_t direction,
                                         feel_trigger t, int64_t trigger_repeat_interval_us) {
    return create("feel_constant_force_trigger", d, [&] {
        return fi::constant_force_trigger(magnitude, duration_us, direction, trigger("feel_constant_force_trigger", t),
                                          trigger_repeat_interval_us);
    });
}

feel_effect* feel_envelope_constant(feel_device* d, int32_t magnitude, int64_t duration_us, int32_t direction,
                                    int32_t impulse_level, int64_t settle_time_us, int32_t fade_level,
                                    int64_t fade_time_us, feel_trigger t, int64_t trigger_repeat_interval_us) {
    return create("feel_envelope_constant", d, [&] {
        return fi::envelope_constant(magnitude, duration_us, direction, impulse_level, settle_time_us, fade_level,
                                     fade_time_us, trigger("feel_envelope_constant", t), trigger_repeat_interval_us);
    });
}

feel_effect* feel_ramp(feel_device* d, int32_t start, int32_t end, int64_t duration_us, int32_t direction,
                       feel_trigger t, int64_t trigger_repeat_interval_us) {
    return create("feel_ramp", d, [&] {
        return fi::ramp(start, end, duration_us, direction, trigger("feel_ramp", t), trigger_repeat_interval_us);
    });
}

feel_effect* feel_ramp_envelope(feel_device* d, int32_t start, int32_t end, int64_t duration_us, int32_t direction,
                                int32_t impulse_level, int64_t settle_time_us, int32_t fade_level, int64_t fade_time_us,
                                feel_trigger t, int64_t trigger_repeat_interval_us) {
    return create("feel_ramp_envelope", d, [&] {
        return fi::ramp_envelope(start, end, duration_us, direction, impulse_level, settle_time_us, fade_level,
                                 fade_time_us, trigger("feel_ramp_envelope", t), trigger_repeat_interval_us);
    });
}

feel_effect* feel_periodic(feel_device* d, int32_t wave, int32_t magnitude, int32_t offset, int32_t phase,
                           int64_t period_us, int64_t duration_us, int32_t angle, feel_trigger t,
                           int64_t trigger_repeat_interval_us) {
    return create("feel_periodic", d, [&] {
        return fi::periodic(waveform("feel_periodic", wave), magnitude, offset, phase, period_us, duration_us, angle,
                            trigger("feel_periodic", t), trigger_repeat_interval_us);
    });
}

feel_effect* feel_envelope_periodic(feel_device* d, int32_t wave, int32_t magnitude, int32_t offset, int32_t phase,
                                    int64_t period_us, int64_t duration_us, int32_t angle, int32_t impulse_level,
                                    int64_t settle_time_us, int32_t fade_level, int64_t fade_time_us, feel_trigger t,
                                    int64_t trigger_repeat_interval_us) {
    return create("feel_envelope_periodic", d, [&] {
        return fi::envelope_periodic(waveform("feel_envelope_periodic", wave), magnitude, offset, phase, period_us,
                                     duration_us, angle, impulse_level, settle_time_us, fade_level, fade_time_us,
                                     trigger("feel_envelope_periodic", t), trigger_repeat_interval_us);
    });
}

feel_effect* feel_delayed_periodic(feel_device* d, int64_t pause_us, int32_t wave, int32_t magnitude, int32_t offset,
                                   int32_t phase, int64_t period_us, int64_t duration_us, int32_t angle,
                                   feel_trigger t, int64_t trigger_repeat_interval_us) {
    return create("feel_delayed_periodic", d, [&] {
        return fi::delayed_periodic(pause_us, waveform("feel_delayed_periodic", wave), magnitude, offset, phase,
                                    period_us, duration_us, angle, trigger("feel_delayed_periodic", t),
                                    trigger_repeat_interval_us);
    });
}

feel_effect* feel_sweep_periodic(feel_device* d, int32_t start_angle, int32_t stop_angle, int32_t sense, int32_t wave,
                                 int32_t magnitude, int32_t offset, int64_t period_us, int32_t phase,
                                 int64_t duration_us) {
    return create("feel_sweep_periodic", d, [&] {
        return fi::sweep_periodic(start_angle, stop_angle, sweep_sense("feel_sweep_periodic", sense),
                                  waveform("feel_sweep_periodic", wave), magnitude, offset, period_us, phase,
                                  duration_us);
    });
}

// --- §8.4 dynamics --------------------------------------------------------------------------

feel_effect* feel_dynamic_recoil(feel_device* d, int32_t blast_direction, int32_t blast_intensity,
                                 int32_t dynamic_mass, int32_t blast_resonance, int32_t blast_decay) {
    return create("feel_dynamic_recoil", d, [&] {
        return fi::dynamic_recoil(blast_direction, blast_intensity, dynamic_mass, blast_resonance, blast_decay);
    });
}

feel_effect* feel_dynamic_impact(feel_device* d, int32_t impact_direction, int32_t impact_intensity,
                                 int32_t dynamic_mass, int32_t elasticity, int32_t collision_absorption) {
    return create("feel_dynamic_impact", d, [&] {
        return fi::dynamic_impact(impact_direction, impact_intensity, dynamic_mass, elasticity, collision_absorption);
    });
}

feel_effect* feel_dynamic_liquid(feel_device* d, int32_t density, int32_t settle, int32_t viscosity) {
    return create("feel_dynamic_liquid", d, [&] { return fi::dynamic_liquid(density, settle, viscosity); });
}

feel_effect* feel_dynamic_inertia(feel_device* d, int32_t inertia, int32_t play) {
    return create("feel_dynamic_inertia", d, [&] { return fi::dynamic_inertia(inertia, play); });
}

feel_effect* feel_dynamic_center_drift(feel_device* d, int32_t stiffness, int32_t drift_resistance) {
    return create("feel_dynamic_center_drift", d, [&] { return fi::dynamic_center_drift(stiffness, drift_resistance); });
}

feel_effect* feel_dynamic_sling(feel_device* d, int32_t ball_mass, int32_t string_length, int32_t string_compliance,
                                int32_t ball_damping, bool interim_reporting) {
    return create("feel_dynamic_sling", d, [&] {
        return fi::dynamic_sling(ball_mass, string_length, string_compliance, ball_damping, interim_reporting);
    });
}

feel_effect* feel_dynamic_paddle(feel_device* d, int32_t ball_mass, int32_t initial_velocity,
                                 int32_t initial_velocity_direction, int32_t paddle_compliance, int32_t paddle_damping,
                                 int32_t gravity, bool interim_reporting) {
    return create("feel_dynamic_paddle", d, [&] {
        return fi::dynamic_paddle(ball_mass, initial_velocity, initial_velocity_direction, paddle_compliance,
                                  paddle_damping, gravity, interim_reporting);
    });
}

feel_effect* feel_dynamic_control_law(feel_device* d, int32_t mass, int32_t k_pos, int32_t k_neg, int32_t b,
                                      int32_t vel_init, int32_t pos_init, int32_t half_cycles, int32_t length,
                                      int32_t drag, int32_t gravity, bool interim_reporting, int32_t on_axis) {
    return create("feel_dynamic_control_law", d, [&] {
        return fi::dynamic_control_law(mass, k_pos, k_neg, b, vel_init, pos_init, half_cycles, length, drag, gravity,
                                       interim_reporting, axis("feel_dynamic_control_law", on_axis));
    });
}

}  // extern "C"
