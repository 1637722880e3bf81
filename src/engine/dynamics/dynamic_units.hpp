// From the Dynamic Struct's integers (§6.6.f, §8.4) to the normalized physical units the
// models simulate in: force units (±10000 = the motor limit), position units (±10000 =
// the travel) and seconds. EngineConfig says what 10000 of each means on the device;
// docs/dynamics.md tabulates the numbers of every profile.
#pragma once

#include <cstdint>

#include "feel/engine.hpp"
#include "feel/units.hpp"

namespace feel::detail {

// mass 1..10000 → force units per (position unit/s²)
[[nodiscard]] inline double dynamic_mass(const EngineConfig& c, int32_t mass) noexcept {
    return mass * static_cast<double>(c.dynamic_mass_ref) / kFullScale;
}

// stiffness 1..10000 (KPos, KNeg and what maps to them) → force units per position unit
[[nodiscard]] inline double dynamic_stiffness(const EngineConfig& c, int32_t k) noexcept {
    return k * static_cast<double>(c.dynamic_stiffness_ref) / kFullScale;
}

// damping 0..10000 (B, Drag) → force units per (position unit/s)
[[nodiscard]] inline double dynamic_damping(const EngineConfig& c, int32_t b) noexcept {
    return b * static_cast<double>(c.dynamic_damping_ref) / kFullScale;
}

// gravity -10000..10000 → position units/s²
[[nodiscard]] inline double dynamic_gravity(const EngineConfig& c, int32_t g) noexcept {
    return g * static_cast<double>(c.gravity_ref) / kFullScale;
}

// velocity -10000..10000 (VelInit, intensities) → position units/s: 10000 is velocity_ref,
// the speed of a brisk hand motion on the device.
[[nodiscard]] inline double dynamic_velocity(const EngineConfig& c, int32_t v) noexcept {
    return v * static_cast<double>(c.velocity_ref) / kFullScale;
}

}  // namespace feel::detail
