// feel — the primer's master set of effect types (§6.4) plus `constant`.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace feel {

// Order matters only inside this file: the table in effect_type.cpp follows it.
enum class EffectType : uint8_t {
    // Spatial Conditions (§6.4.a)
    spring, damper, inertia, friction, angle_spring,
    axis_barrier, angle_barrier, axis_wall, angle_wall, texture,
    // Temporal Waves (§6.4.b), plus `constant`: a vector force with a duration
    vector_force, constant, smart_pop,
    sine, square, triangle, saw_up, saw_down,
    sweep_sine, sweep_square, sweep_triangle, sweep_saw_up, sweep_saw_down,
    force_profile, ramp,
    // Dynamic Sensations (§6.4.c)
    dynamic_recoil, dynamic_impact, dynamic_liquid, dynamic_inertia,
    dynamic_center_drift, dynamic_control_law, dynamic_sling, dynamic_paddle,
};
inline constexpr int kEffectTypeCount = 33;

enum class EffectClass : uint8_t { condition, wave, dynamic };

// The periodic source of a periodic or sweep wave (§4.2).
enum class Waveform : uint8_t { sine, square, triangle, saw_up, saw_down };

// The snake_case name used in sensation files, e.g. "saw_up".
[[nodiscard]] std::string_view effect_type_name(EffectType t) noexcept;
[[nodiscard]] std::optional<EffectType> effect_type_from_name(std::string_view name) noexcept;

[[nodiscard]] EffectClass effect_class(EffectType t) noexcept;
// §6.4: which types accept an envelope ("Envelope Support").
[[nodiscard]] bool supports_envelope(EffectType t) noexcept;
[[nodiscard]] bool is_periodic(EffectType t) noexcept;  // sine..saw_down
[[nodiscard]] bool is_sweep(EffectType t) noexcept;     // sweep_sine..sweep_saw_down
// The source of a periodic or sweep type; only meaningful when is_periodic or is_sweep.
[[nodiscard]] Waveform waveform_of(EffectType t) noexcept;

}  // namespace feel
