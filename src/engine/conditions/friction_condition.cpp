// Friction (§3.5): a rubbing resistance of constant magnitude against the motion, with a
// smooth turn-around and a true stick, rendered by a Dahl bristle per axis
// (friction_model.hpp explains the model and why).
//
//   z_i = bristle of block i, advanced by the handle's travel on device axis a
//   F_a = -f·z_i + microdamping,  f = pos_coefficient while z_i >= 0 (sliding toward +),
//                                     neg_coefficient while z_i < 0,
//         capped by the saturation of that side
//
// While sliding, z = ±1 and the force is ∓f, exactly the primer's Figure 3-9. Turning
// around, the force passes through zero along the presliding spring. A negative
// coefficient pushes the handle along its motion instead: an energy source, allowed
// because the primer's range allows it.
//
// The offset is a velocity (scaled as for the damper): the surface the handle rubs on moves
// at that speed, so the friction drags the handle along with it, like a conveyor belt, and
// holds it moving at the offset speed. The deadband is a band of velocity relative to the
// surface in which friction is not active: the force fades in (smoothstep) between one and
// two deadbands, so leaving the band has no jerk. Mind that this gives friction back a
// dependence on the estimated velocity, with a slope f/deadband at the band's edge; keep it
// 0 unless a free zone around rest is wanted.
#include <cmath>

#include "conditions/condition_math.hpp"

namespace feel::detail {

namespace {

// 0 inside the deadband, 1 beyond twice the deadband, a smoothstep between.
double deadband_gate(double relative_speed, double deadband) noexcept {
    if (!(deadband > 0)) return 1.0;
    double t = (std::fabs(relative_speed) - deadband) / deadband;
    if (t <= 0) return 0.0;
    if (t >= 1) return 1.0;
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

void friction_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept {
    const EffectParams& p = *c.params;
    const EngineConfig& config = *c.config;
    const PreslidingRule rule = presliding_rule(config, c.dt_s);
    const double velocity_ref = static_cast<double>(config.velocity_ref);
    const double inverse_fade_speed = 1.0 / (kBristleDampingFade * velocity_ref);
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = device_axis(c, i);
        const ConditionBlock& b = p.conditions[i];
        const double magnitude = std::fmax(std::abs(b.pos_coefficient), std::abs(b.neg_coefficient));
        const double stiffness = magnitude > 0 ? presliding_stiffness(rule, magnitude) : 0.0;
        const double presliding = magnitude > 0 ? magnitude / stiffness : 0.0;
        const double surface_speed = b.offset * velocity_ref / kFullScale;
        const double z = advance(c.state->friction.bristle[i], c.position[a], surface_speed * c.dt_s, presliding);
        const double relative_velocity = c.velocity[a] - surface_speed;
        const bool toward_positive = z >= 0;
        double f = -(toward_positive ? b.pos_coefficient : b.neg_coefficient) * z;
        if (presliding > 0 && c.dt_s > 0) f += bristle_damping(stiffness, z, relative_velocity, inverse_fade_speed);
        if (b.deadband > 0) f *= deadband_gate(scaled_velocity(config, relative_velocity), b.deadband);
        const double cap = toward_positive ? b.pos_saturation : b.neg_saturation;
        force[a] += f > cap ? cap : (f < -cap ? -cap : f);
    }
}

}  // namespace feel::detail
