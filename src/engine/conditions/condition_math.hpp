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

// The response of one Condition Struct block (as its curve, condition.hpp) to input d
// measured from the offset, in single precision (issue 14): d and the force are within a
// few times ±10000.
[[nodiscard]] inline float condition_response(const ConditionCurve& b, float d) noexcept {
    const float band = b.band;
    float force = 0.0f;
    float cap = 0.0f;
    if (d > band) {
        force = b.pos_slope * (d - band);
        cap = b.pos_cap;
    } else if (d < -band) {
        force = b.neg_slope * (d + band);
        cap = b.neg_cap;
    } else {
        return 0.0f;
    }
    return force > cap ? cap : (force < -cap ? -cap : force);
}

// A velocity in position units/s on the ±10000 scale where velocity_ref reads 10000, in
// double for friction and texture. (The single-precision conditions multiply by
// ConditionContext::velocity_scale and acceleration_scale, worked out once per tick.)
[[nodiscard]] inline double scaled_velocity(const EngineConfig& config, double velocity) noexcept {
    return velocity * kFullScale / config.velocity_ref;
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
// (The float line on the device's axes, condition_lanes: what along and add_force_along read.)
inline void condition_line(const ConditionContext& c, float u[kMaxAxes]) noexcept {
    for (int a = 0; a < condition_lanes(c); ++a) u[a] = -c.direction[a];
}

// v · u over the device axes.
[[nodiscard]] inline double along(const double u[kMaxAxes], const float* v) noexcept {
    double s = 0.0;
    for (int a = 0; a < kMaxAxes; ++a) s += u[a] * static_cast<double>(v[a]);
    return s;
}

}  // namespace feel::detail
