// From the Dynamic Struct's integers (§6.6.f, §8.4) to the normalized physical units the
// models simulate in: force units (±10000 = the motor limit), position units (±10000 =
// the travel) and seconds. EngineConfig says what 10000 of each means on the device;
// docs/dynamics.md tabulates the numbers of every profile. In the precision asked for:
// the control laws' is float (issue 14), the default double.
#pragma once

#include <cstdint>

#include "feel/engine.hpp"
#include "feel/units.hpp"

namespace feel::detail {

// value/10000 of `reference`, in T.
template <typename T>
[[nodiscard]] inline T of_full_scale(int32_t value, float reference) noexcept {
    return static_cast<T>(value) * static_cast<T>(reference) / static_cast<T>(kFullScale);
}

// mass 1..10000 → force units per (position unit/s²)
template <typename T = double>
[[nodiscard]] inline T dynamic_mass(const EngineConfig& c, int32_t mass) noexcept {
    return of_full_scale<T>(mass, c.dynamic_mass_ref);
}

// stiffness 1..10000 (KPos, KNeg and what maps to them) → force units per position unit
template <typename T = double>
[[nodiscard]] inline T dynamic_stiffness(const EngineConfig& c, int32_t k) noexcept {
    return of_full_scale<T>(k, c.dynamic_stiffness_ref);
}

// damping 0..10000 (B, Drag) → force units per (position unit/s)
template <typename T = double>
[[nodiscard]] inline T dynamic_damping(const EngineConfig& c, int32_t b) noexcept {
    return of_full_scale<T>(b, c.dynamic_damping_ref);
}

// gravity -10000..10000 → position units/s²
template <typename T = double>
[[nodiscard]] inline T dynamic_gravity(const EngineConfig& c, int32_t g) noexcept {
    return of_full_scale<T>(g, c.gravity_ref);
}

// velocity -10000..10000 (VelInit, intensities) → position units/s: 10000 is velocity_ref,
// the speed of a brisk hand motion on the device.
template <typename T = double>
[[nodiscard]] inline T dynamic_velocity(const EngineConfig& c, int32_t v) noexcept {
    return of_full_scale<T>(v, c.velocity_ref);
}

}  // namespace feel::detail
