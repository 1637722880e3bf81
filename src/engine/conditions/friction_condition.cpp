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
// around, the force passes through zero along the presliding spring. A free handle coming
// to rest gets, at the last tick, only the force that stops it, and the bristle is then
// anchored where it stopped (stop_guard.hpp): the bristle's stored force never throws it
// back. A negative
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
    // Single precision (issue 14): the forces are within ±10000 and a bristle's state is
    // float; what is per tick rather than per block is computed once here.
    const PreslidingRule rule = presliding_rule(config, c.dt_s);
    const float passive = static_cast<float>(rule.passive), cap = static_cast<float>(rule.cap);
    const float velocity_ref = config.velocity_ref;
    const float inverse_fade_speed = 1.0f / (static_cast<float>(kBristleDampingFade) * velocity_ref);
    const float dt_s = static_cast<float>(c.dt_s);
    constexpr float kMinStiffnessPerForce = static_cast<float>(1.0 / kMaxPresliding);
    FrictionState& state = c.state->friction;
    if (state.guard_tick_dt_s != c.dt_s) {
        state.guard_tick = stop_guard_tick(config, c.dt_s);
        state.guard_tick_dt_s = c.dt_s;
    }
    const StopGuardTick& guard = state.guard_tick;
    const float output_gain = static_cast<float>(p.gain) / static_cast<float>(kFullScale) * c.device_gain;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = device_axis(c, i);
        const ConditionBlock& b = p.conditions[i];
        const float pos = static_cast<float>(b.pos_coefficient), neg = static_cast<float>(b.neg_coefficient);
        // (Comparisons rather than std::fmax/fmin: those are library calls where NaNs must
        // be honoured, and nothing here is NaN.)
        const float magnitude = std::fabs(pos) > std::fabs(neg) ? std::fabs(pos) : std::fabs(neg);
        // presliding_stiffness in float: K = min(max(2b/T, f / kMaxPresliding), cap).
        float stiffness = 0.0f, presliding = 0.0f;
        if (magnitude > 0) {
            const float guarded = magnitude * kMinStiffnessPerForce;
            stiffness = passive > guarded ? passive : guarded;
            if (stiffness > cap) stiffness = cap;
            presliding = magnitude / stiffness;
        }
        const float surface_speed =
            b.offset == 0 ? 0.0f : static_cast<float>(b.offset) * velocity_ref / static_cast<float>(kFullScale);
        const float z = advance(c.state->friction.bristle[i], c.position[a], surface_speed * dt_s, presliding);
        const float relative_velocity = c.velocity[a] - surface_speed;
        const bool toward_positive = z >= 0;
        float f = -(toward_positive ? pos : neg) * z;
        if (presliding > 0 && dt_s > 0) f += bristle_damping(stiffness, z, relative_velocity, inverse_fade_speed);
        if (b.deadband > 0) {
            f *= static_cast<float>(deadband_gate(scaled_velocity(config, relative_velocity), b.deadband));
        }
        const float limit = static_cast<float>(toward_positive ? b.pos_saturation : b.neg_saturation);
        f = f > limit ? limit : (f < -limit ? -limit : f);
        if (guard.on && c.applied_force != nullptr && b.offset == 0 && b.deadband == 0) {
            // A free handle coming to rest gets only what stops it (stop_guard.hpp).
            StopGuard& g = c.state->friction.guard[i];
            const float guarded = guard_stop(g, c.state->friction.bristle[i], guard, c.position[a],
                                             c.applied_force[a], f, magnitude, pos, neg);
            const float side = static_cast<float>(guarded >= 0 ? b.neg_saturation : b.pos_saturation);
            f = guarded > side ? side : (guarded < -side ? -side : guarded);
            remember_output(g, f, output_gain);
        }
        force[a] += static_cast<double>(f);
    }
}

}  // namespace feel::detail
