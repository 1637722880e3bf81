// The arithmetic the Condition Struct (§6.6.a) shares across spring, damper and inertia:
// one response curve, applied to a position, a velocity or an acceleration.
//
//   force                                 (positive coefficients)
//     ^
//   +neg_saturation -----.
//     |                   `.   slope -neg_coefficient/10000
//     |                     `.
//   0 +-----------------------`=========+=========.--------------------> d
//     |                     -deadband   0   +deadband`.
//     |                                                `.   slope -pos_coefficient/10000
//   -pos_saturation                                      `----------------
//
// with d the input measured from the offset. Inside the deadband (|d| <= deadband) there is
// no force; beyond it the force grows from zero (continuous at the band's edge, as in
// DirectInput's DICONDITION), with the coefficient of the side d is on, and its magnitude
// is capped by that side's saturation. The sign is physical and restoring for positive
// coefficients: a handle past the offset on the + side is pushed toward -, as a spring
// pushes it back, a damper resists the motion and inertia resists the acceleration. A
// negative coefficient pushes away, capped by the same saturation.
//
// The input is in the ±10000 scale of the coefficient's meaning: positions as they are,
// velocities and accelerations scaled so that EngineConfig::velocity_ref and
// acceleration_ref read as 10000. A coefficient of 10000 thus gives full force (10000)
// for a full-scale displacement, velocity or acceleration.
#pragma once

#include "conditions/condition.hpp"
#include "feel/units.hpp"

namespace feel::detail {

// The response of one Condition Struct block to input d measured from the offset.
[[nodiscard]] inline double condition_response(const ConditionBlock& b, double d) noexcept {
    const double band = b.deadband;
    double force = 0.0;
    double cap = 0.0;
    if (d > band) {
        force = -b.pos_coefficient * (d - band) / kFullScale;
        cap = b.pos_saturation;
    } else if (d < -band) {
        force = -b.neg_coefficient * (d + band) / kFullScale;
        cap = b.neg_saturation;
    } else {
        return 0.0;
    }
    if (force > cap) return cap;
    if (force < -cap) return -cap;
    return force;
}

// A velocity in position units/s on the ±10000 scale where velocity_ref reads 10000.
[[nodiscard]] inline double scaled_velocity(const EngineConfig& config, double velocity) noexcept {
    return velocity * kFullScale / config.velocity_ref;
}

// An acceleration in position units/s² on the ±10000 scale where acceleration_ref reads 10000.
[[nodiscard]] inline double scaled_acceleration(const EngineConfig& config, double acceleration) noexcept {
    return acceleration * kFullScale / config.acceleration_ref;
}

// The device axis that the effect's i-th axis (and i-th conditions block) drives.
[[nodiscard]] inline int device_axis(const ConditionContext& c, int i) noexcept {
    return axis_index(c.params->axes[i]);
}

// The unit vector a directional condition (angle_spring, a texture on several axes) lies
// along: the compass direction of its polar angle, u = (sin a, cos a) on x, y, or the
// normalized "from" vector of any other direction form. The engine's direction factors
// push away from that direction (direction.hpp), so u is their negation.
inline void condition_line(const ConditionContext& c, double u[kMaxAxes]) noexcept {
    for (int a = 0; a < kMaxAxes; ++a) u[a] = -static_cast<double>(c.direction[a]);
}

// v · u over the device axes.
[[nodiscard]] inline double along(const double u[kMaxAxes], const float* v) noexcept {
    double s = 0.0;
    for (int a = 0; a < kMaxAxes; ++a) s += u[a] * static_cast<double>(v[a]);
    return s;
}

}  // namespace feel::detail
