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

// mass 1..10000 → force units per (position unit/s²)
template <typename T = double>
[[nodiscard]] inline T dynamic_mass(const EngineConfig& c, int32_t mass) noexcept {
    return static_cast<T>(mass) * static_cast<T>(c.dynamic_mass_ref) / static_cast<T>(kFullScale);
}

// stiffness 1..10000 (KPos, KNeg and what maps to them) → force units per position unit
template <typename T = double>
[[nodiscard]] inline T dynamic_stiffness(const EngineConfig& c, int32_t k) noexcept {
    return static_cast<T>(k) * static_cast<T>(c.dynamic_stiffness_ref) / static_cast<T>(kFullScale);
}

// damping 0..10000 (B, Drag) → force units per (position unit/s)
template <typename T = double>
[[nodiscard]] inline T dynamic_damping(const EngineConfig& c, int32_t b) noexcept {
    return static_cast<T>(b) * static_cast<T>(c.dynamic_damping_ref) / static_cast<T>(kFullScale);
}

// gravity -10000..10000 → position units/s²
template <typename T = double>
[[nodiscard]] inline T dynamic_gravity(const EngineConfig& c, int32_t g) noexcept {
    return static_cast<T>(g) * static_cast<T>(c.gravity_ref) / static_cast<T>(kFullScale);
}

// velocity -10000..10000 (VelInit, intensities) → position units/s: 10000 is velocity_ref,
// the speed of a brisk hand motion on the device.
template <typename T = double>
[[nodiscard]] inline T dynamic_velocity(const EngineConfig& c, int32_t v) noexcept {
    return static_cast<T>(v) * static_cast<T>(c.velocity_ref) / static_cast<T>(kFullScale);
}

}  // namespace feel::detail
