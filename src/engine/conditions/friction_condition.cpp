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
    if (std::fabs(relative_speed) <= deadband) return 0.0f;  // t <= 0 below, without its division
    const float t = (std::fabs(relative_speed) - deadband) / deadband;
    if (t <= 0) return 0.0f;
    if (t >= 1) return 1.0f;
    return t * t * (3.0f - 2.0f * t);
}

// What every block of a friction shares at tick period dt_s; the blocks' laws are worked
// out again at this period.
void remember_tick(FrictionState& state, const EngineConfig& config, double dt_s) noexcept {
    state.guard_tick = stop_guard_tick(config, dt_s);
    const PreslidingRule rule = presliding_rule(config, dt_s);
    state.passive = static_cast<float>(rule.passive);
    state.cap = static_cast<float>(rule.cap);
    state.inverse_fade_speed = 1.0f / (static_cast<float>(kBristleDampingFade) * config.velocity_ref);
    state.tick_dt_s = dt_s;
    for (FrictionBlock& block : state.block) block.law = FrictionBlockLaw{};
}

// A block's law for its coefficients: presliding_stiffness in float, K = min(max(2b/T,
// f / kMaxPresliding), cap), Z = f/K.
void remember_law(FrictionBlockLaw& law, const FrictionState& state, int32_t pos_coefficient,
                  int32_t neg_coefficient) noexcept {
    constexpr float kMinStiffnessPerForce = static_cast<float>(1.0 / kMaxPresliding);
    law = FrictionBlockLaw{};
    law.pos_coefficient = pos_coefficient;
    law.neg_coefficient = neg_coefficient;
    const float pos = static_cast<float>(pos_coefficient), neg = static_cast<float>(neg_coefficient);
    law.pos = pos;
    law.neg = neg;
    // (Comparisons rather than std::fmax/fmin: those are library calls where NaNs must be
    // honoured, and nothing here is NaN.)
    law.magnitude = std::fabs(pos) > std::fabs(neg) ? std::fabs(pos) : std::fabs(neg);
    if (law.magnitude > 0) {
        const float guarded = law.magnitude * kMinStiffnessPerForce;
        float stiffness = state.passive > guarded ? state.passive : guarded;
        if (stiffness > state.cap) stiffness = state.cap;
        law.stiffness = stiffness;
        law.inverse_presliding = stiffness / law.magnitude;
        law.damping = -stiffness * static_cast<float>(kBristleDampingTime);
    }
    law.limits = guard_limits(law.magnitude, pos, neg);
}

}  // namespace

void friction_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    // Single precision (issue 14); what is per tick or per command rather than per block
    // and tick is worked out once (remember_tick, remember_law), and the context is read
    // once (the state's stores could alias it).
    FrictionState& state = c.state->friction;
    if (state.tick_dt_s != c.dt_s) remember_tick(state, *c.config, c.dt_s);
    const StopGuardTick& guard = state.guard_tick;
    const float dt_s = static_cast<float>(c.dt_s);
    const float velocity_ref = c.config->velocity_ref;
    const float velocity_scale = c.velocity_scale;
    const float output_gain = static_cast<float>(p.gain) / static_cast<float>(kFullScale) * c.device_gain;
    const float* const position_of = c.position;
    const float* const velocity_of = c.velocity;
    const float* const others_force = c.others_force;
    const float* const applied_force = c.applied_force;
    const AxisObservers* const observers = c.observers;
    // The others' force is kept in this friction's units (before its gain and the device's),
    // so that a gain change, which scales the friction too, is not taken for a push easing.
    const bool others_known = others_force != nullptr && output_gain != 0;
    const float inverse_gain = others_known ? 1.0f / output_gain : 0.0f;
    const bool held_before = state.others_known;
    // The stop guard's preconditions that hold for every block of this tick.
    const bool guarding = guard.on && applied_force != nullptr;
    const bool damping_on = dt_s > 0;
    const int blocks = p.axis_count;
    for (int i = 0; i < blocks; ++i) {
        const int a = axis_index(p.axes[i]);
        const SlotConditionBlock& b = p.conditions[i];
        FrictionBlock& block = state.block[i];
        Bristle& bristle = block.bristle;
        FrictionBlockLaw& law = block.law;
        if (law.pos_coefficient != b.pos_coefficient || law.neg_coefficient != b.neg_coefficient) {
            remember_law(law, state, b.pos_coefficient, b.neg_coefficient);
        }
        const float position = position_of[a];
        const float pos = law.pos, neg = law.neg;
        const bool still_surface = b.offset == 0;
        const float surface_speed =
            still_surface ? 0.0f : static_cast<float>(b.offset) * velocity_ref / static_cast<float>(kFullScale);
        // At its first tick the friction has held nothing yet (its state is zeroed at start):
        // it takes the other effects' push at once from there.
        const bool first = !bristle.primed;
        const bool at_rest = (first || position == bristle.anchor) && still_surface;
        float z = advance(bristle, position, surface_speed * dt_s, law.inverse_presliding);
        const float pos_limit = static_cast<float>(b.pos_saturation), neg_limit = static_cast<float>(b.neg_saturation);
        const float others = others_force != nullptr ? others_force[a]
                             : applied_force != nullptr ? applied_force[a] - block.guard.own
                                                        : 0.0f;
        if (others_known) {
            const float pushed = others * inverse_gain;
            // (pushed == block.others: the push did not change, hold_with_others does nothing.)
            if (at_rest && pushed != block.others && (held_before || first) && law.limits.resists) {
                const float bristle_force = -(z >= 0 ? pos : neg) * z;
                const float limit = z >= 0 ? pos_limit : neg_limit;
                const float held = bristle_force > limit ? limit : (bristle_force < -limit ? -limit : bristle_force);
                // (|z| = 1: z = ±1; |force| > limit: held != force, force being finite.)
                const bool slipping = std::fabs(z) == 1.0f || std::fabs(bristle_force) > limit;
                hold_with_others(bristle, bristle_force, held, slipping, block.others, pushed, pos, neg);
                z = bristle.deflection;
            }
            block.others = pushed;
        }
        const bool toward_positive = z >= 0;
        float f = -(toward_positive ? pos : neg) * z;
        const bool on_axis = observers != nullptr && still_surface;
        if (law.inverse_presliding > 0 && damping_on) {
            // The fade depends on the axis' velocity alone: the engine's, once per axis (issue 14).
            f += on_axis ? bristle_damping_faded(law.damping, z, observers->damped_velocity[a],
                                                 observers->damped_way[a], observers->fade[a])
                         : bristle_damping(law.stiffness, z, velocity_of[a] - surface_speed, state.inverse_fade_speed);
        }
        if (b.deadband > 0) {
            f *= deadband_gate((velocity_of[a] - surface_speed) * velocity_scale, static_cast<float>(b.deadband));
        }
        const float limit = toward_positive ? pos_limit : neg_limit;
        f = f > limit ? limit : (f < -limit ? -limit : f);
        if (guarding && still_surface && b.deadband == 0) {
            // A free handle coming to rest gets only what stops it (stop_guard.hpp).
            StopGuard& g = block.guard;
            // The engine's observer of the axis, shared by every friction on it (issue 14).
            const float guarded =
                observers != nullptr
                    ? guard_stop(g, observers->view[a], bristle, guard, position, others, f, law.limits, pos, neg)
                    : guard_stop_on_line(g, bristle, guard, position, applied_force[a], others, f, law.magnitude,
                                         pos, neg);
            const float side = guarded >= 0 ? neg_limit : pos_limit;
            f = guarded > side ? side : (guarded < -side ? -side : guarded);
            remember_output(g, f, output_gain);
        }
        force[a] += f;
    }
    state.others_known = others_known;
}

}  // namespace feel::detail
