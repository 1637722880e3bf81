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
// back. And a handle that the other effects push while it stands still is held by static
// friction that balances their push at once, within ±f (hold_with_others below): it does
// not move into the presliding zone, and when the push eases or ends the friction follows
// it at the same tick, so it never throws the handle back either; this needs no mass. A negative
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
float deadband_gate(float relative_speed, float deadband) noexcept {
    if (!(deadband > 0)) return 1.0f;
    const float t = (std::fabs(relative_speed) - deadband) / deadband;
    if (t <= 0) return 0.0f;
    if (t >= 1) return 1.0f;
    return t * t * (3.0f - 2.0f * t);
}

// What every block of a friction shares at tick period dt_s.
void remember_tick(FrictionState& state, const EngineConfig& config, double dt_s) noexcept {
    state.guard_tick = stop_guard_tick(config, dt_s);
    const PreslidingRule rule = presliding_rule(config, dt_s);
    state.passive = static_cast<float>(rule.passive);
    state.cap = static_cast<float>(rule.cap);
    state.inverse_fade_speed = 1.0f / (static_cast<float>(kBristleDampingFade) * config.velocity_ref);
    state.tick_dt_s = dt_s;
}

}  // namespace

void friction_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    const EngineConfig& config = *c.config;
    // Single precision (issue 14); what is per tick rather than per block is computed once.
    FrictionState& state = c.state->friction;
    if (state.tick_dt_s != c.dt_s) remember_tick(state, config, c.dt_s);
    const StopGuardTick& guard = state.guard_tick;
    const float passive = state.passive, cap = state.cap, inverse_fade_speed = state.inverse_fade_speed;
    const float velocity_ref = config.velocity_ref;
    const float dt_s = static_cast<float>(c.dt_s);
    constexpr float kMinStiffnessPerForce = static_cast<float>(1.0 / kMaxPresliding);
    const float output_gain = static_cast<float>(p.gain) / static_cast<float>(kFullScale) * c.device_gain;
    // The others' force is kept in this friction's units (before its gain and the device's),
    // so that a gain change, which scales the friction too, is not taken for a push easing.
    const bool others_known = c.others_force != nullptr && output_gain != 0;
    const float inverse_gain = others_known ? 1.0f / output_gain : 0.0f;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = device_axis(c, i);
        const ConditionBlock& b = p.conditions[i];
        Bristle& bristle = state.bristle[i];
        const float position = c.position[a];
        const float pos = static_cast<float>(b.pos_coefficient), neg = static_cast<float>(b.neg_coefficient);
        // (Comparisons rather than std::fmax/fmin: those are library calls where NaNs must
        // be honoured, and nothing here is NaN.)
        const float magnitude = std::fabs(pos) > std::fabs(neg) ? std::fabs(pos) : std::fabs(neg);
        // presliding_stiffness in float: K = min(max(2b/T, f / kMaxPresliding), cap), Z = f/K.
        float stiffness = 0.0f, inverse_presliding = 0.0f;
        if (magnitude > 0) {
            const float guarded = magnitude * kMinStiffnessPerForce;
            stiffness = passive > guarded ? passive : guarded;
            if (stiffness > cap) stiffness = cap;
            inverse_presliding = stiffness / magnitude;
        }
        const float surface_speed =
            b.offset == 0 ? 0.0f : static_cast<float>(b.offset) * velocity_ref / static_cast<float>(kFullScale);
        // At its first tick the friction has held nothing yet (its state is zeroed at start):
        // it takes the other effects' push at once from there.
        const bool first = !bristle.primed;
        const bool at_rest = (first || position == bristle.anchor) && b.offset == 0;
        float z = advance(bristle, position, surface_speed * dt_s, inverse_presliding);
        const float pos_limit = static_cast<float>(b.pos_saturation), neg_limit = static_cast<float>(b.neg_saturation);
        const float others = c.others_force != nullptr ? c.others_force[a] : c.applied_force != nullptr
                                                                    ? c.applied_force[a] - state.guard[i].own
                                                                    : 0.0f;
        if (others_known) {
            const float pushed = others * inverse_gain;
            if (at_rest && (state.others_known || first) && pos >= 0 && neg >= 0) {
                const float bristle_force = -(z >= 0 ? pos : neg) * z;
                const float limit = z >= 0 ? pos_limit : neg_limit;
                const float held = bristle_force > limit ? limit : (bristle_force < -limit ? -limit : bristle_force);
                const bool slipping = z == 1.0f || z == -1.0f || held != bristle_force;
                hold_with_others(bristle, bristle_force, held, slipping, state.others[i], pushed, pos, neg);
                z = bristle.deflection;
            }
            state.others[i] = pushed;
        }
        const float relative_velocity = c.velocity[a] - surface_speed;
        const bool toward_positive = z >= 0;
        float f = -(toward_positive ? pos : neg) * z;
        if (inverse_presliding > 0 && dt_s > 0) {
            // The fade depends on the axis' velocity alone: the engine's, once per axis (issue 14).
            f += c.observers != nullptr && b.offset == 0
                     ? bristle_damping_faded(stiffness, z, relative_velocity, c.observers->fade[a])
                     : bristle_damping(stiffness, z, relative_velocity, inverse_fade_speed);
        }
        if (b.deadband > 0) {
            f *= deadband_gate(relative_velocity * c.velocity_scale, static_cast<float>(b.deadband));
        }
        const float limit = toward_positive ? pos_limit : neg_limit;
        f = f > limit ? limit : (f < -limit ? -limit : f);
        if (guard.on && c.applied_force != nullptr && b.offset == 0 && b.deadband == 0) {
            // A free handle coming to rest gets only what stops it (stop_guard.hpp).
            StopGuard& g = state.guard[i];
            // The engine's observer of the axis, shared by every friction on it (issue 14).
            const float guarded = c.observers != nullptr
                                      ? guard_stop(g, c.observers->axis[a], c.observers->observed[a], bristle, guard,
                                                   position, others, f, magnitude, pos, neg)
                                      : guard_stop_on_line(g, bristle, guard, position, c.applied_force[a], others,
                                                           f, magnitude, pos, neg);
            const float side = guarded >= 0 ? static_cast<float>(b.neg_saturation) : pos_limit;
            f = guarded > side ? side : (guarded < -side ? -side : guarded);
            remember_output(g, f, output_gain);
        }
        force[a] += f;
    }
    state.others_known = others_known;
}

}  // namespace feel::detail
