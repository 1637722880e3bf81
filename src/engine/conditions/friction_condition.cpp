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
#include <cstddef>
#include <cstring>

#include "conditions/condition_math.hpp"

namespace feel::detail {

namespace {

// 0 inside the deadband, 1 beyond twice the deadband, a smoothstep between.
float deadband_gate(float relative_speed, float deadband) noexcept {
    if (!(deadband > 0)) return 1.0f;
    if (std::fabs(relative_speed) <= deadband) return 0.0f;  // t <= 0 below, without its division
    const float beyond = std::fabs(relative_speed) - deadband;
    // t >= 1 below, without its division: a quotient of beyond >= deadband > 0 rounds to 1 or
    // more (a moving handle is mostly past twice the band).
    if (beyond >= deadband) return 1.0f;
    const float t = beyond / deadband;
    if (t <= 0) return 0.0f;
    if (t >= 1) return 1.0f;
    return t * t * (3.0f - 2.0f * t);
}

// What every block of a friction shares at tick period dt_s; the blocks' laws are worked
// out again at this period.
void remember_tick(FrictionState& state, const EngineConfig& config, float dt_s) noexcept {
    state.guard_tick = stop_guard_tick(config, dt_s);
    state.inverse_fade_speed = 1.0f / (kBristleDampingFade * config.velocity_ref);
    state.tick_dt = dt_s;
    for (FrictionBlock& block : state.block) block.law = FrictionBlockLaw{};
    if constexpr (kFrictionLeanWay) state.laws_current = false;
}

// A block's law is keyed by the slot's block's six 16-bit values, its first 12 bytes.
static_assert(offsetof(SlotConditionBlock, pos_coefficient) == 0 && offsetof(SlotConditionBlock, neg_coefficient) == 2 &&
              offsetof(SlotConditionBlock, offset) == 4 && offsetof(SlotConditionBlock, pos_saturation) == 6 &&
              offsetof(SlotConditionBlock, neg_saturation) == 8 && offsetof(SlotConditionBlock, deadband) == 10 &&
              sizeof(FrictionBlockLaw::key) == 12);

// Whether the law was worked out for this block: two loads and one test.
[[gnu::always_inline]] inline bool law_is_for(const FrictionBlockLaw& law, const SlotConditionBlock& b) noexcept {
    uint64_t low = 0, kept_low = 0;
    uint32_t high = 0;
    std::memcpy(&low, &b, sizeof low);
    std::memcpy(&high, reinterpret_cast<const unsigned char*>(&b) + sizeof low, sizeof high);
    std::memcpy(&kept_low, law.key, sizeof kept_low);
    return ((low ^ kept_low) | (high ^ law.key[2])) == 0;
}

// A block's law for its values at tick period dt_s: K = min(max(2b/T, f / kMaxPresliding),
// cap), Z = f/K (presliding_stiffness), in float.
[[gnu::cold]] void remember_law(FrictionBlockLaw& law, const EngineConfig& config, float dt_s,
                                               const SlotConditionBlock& b) noexcept {
    law = FrictionBlockLaw{};
    std::memcpy(law.key, &b, sizeof law.key);
    const float pos = static_cast<float>(b.pos_coefficient), neg = static_cast<float>(b.neg_coefficient);
    law.pos = pos;
    law.neg = neg;
    law.pos_limit = static_cast<float>(b.pos_saturation);
    law.neg_limit = static_cast<float>(b.neg_saturation);
    // (Comparisons rather than std::fmax: a library call where NaNs must be honoured.)
    const float magnitude = std::fabs(pos) > std::fabs(neg) ? std::fabs(pos) : std::fabs(neg);
    if (magnitude > 0) {
        const float stiffness = presliding_stiffness(presliding_rule(config, dt_s), magnitude);
        law.stiffness = stiffness;
        law.inverse_presliding = stiffness / magnitude;
        law.damping = -stiffness * kBristleDampingTime;
    }
    law.limits = guard_limits(magnitude, pos, neg);
    law.symmetric = kFrictionLeanWay && b.pos_coefficient == b.neg_coefficient && b.pos_saturation == b.neg_saturation;
    law.eligible = b.offset == 0 && b.deadband == 0 && law.limits.resists && law.inverse_presliding > 0;
}

// Static friction on a block at rest whose others' push changed to `pushed` (hold_with_others,
// friction_model.hpp), its bristle at deflection z. Returns the new deflection.
[[gnu::always_inline]] inline float hold_at_rest(FrictionBlock& block, float z, float pushed, float pos, float neg,
                                                 float pos_limit, float neg_limit) noexcept {
    const float bristle_force = -(z >= 0 ? pos : neg) * z;
    const float limit = z >= 0 ? pos_limit : neg_limit;
    const float held = bristle_force > limit ? limit : (bristle_force < -limit ? -limit : bristle_force);
    // (|z| = 1: z = ±1; |force| > limit: held != force, force being finite.)
    const bool slipping = std::fabs(z) == 1.0f || std::fabs(bristle_force) > limit;
    hold_with_others(block.bristle, bristle_force, held, slipping, block.others, pushed, pos, neg);
    return block.bristle.deflection;
}

// What every block of one friction shares at a tick: the context's values, read once (the
// state's stores could alias it).
struct EffectTick {
    const ConditionContext* context = nullptr;
    float dt_s = 0.0f;
    float output_gain = 0.0f;   // the effect's gain times the device's
    float inverse_gain = 0.0f;  // 1/output_gain where the others' force is known, else 0
    bool others_known = false;  // the others' force is known and the gain not 0
    bool held_before = false;   // it was known at the last tick too
    bool guarding = false;      // the stop guard is on and the engine's last force known
};

// One block of any friction: a velocity offset, a deadband, negative coefficients, a line
// that is not a device axis, the first tick. Returns the block's force.
[[gnu::always_inline]] inline float render_block(const EffectTick& e, FrictionState& state, const SlotConditionBlock& b,
                                     FrictionBlock& block, int a) noexcept {
    const ConditionContext& c = *e.context;
    const StopGuardTick& guard = state.guard_tick;
    Bristle& bristle = block.bristle;
    const FrictionBlockLaw& law = block.law;
    const float dt_s = e.dt_s;
    const float position = c.position[a];
    const float pos = law.pos, neg = law.neg;
    const bool still_surface = b.offset == 0;
    const float surface_speed =
        still_surface ? 0.0f : static_cast<float>(b.offset) * c.config->velocity_ref / static_cast<float>(kFullScale);
    // At its first tick the friction has held nothing yet (its state is zeroed at start):
    // it takes the other effects' push at once from there.
    const bool first = !bristle.primed;
    const bool at_rest = (first || position == bristle.anchor) && still_surface;
    float z = advance(bristle, position, surface_speed * dt_s, law.inverse_presliding);
    const float pos_limit = law.pos_limit, neg_limit = law.neg_limit;
    const float others = c.others_force != nullptr    ? c.others_force[a]
                         : c.applied_force != nullptr ? c.applied_force[a] - block.guard.own
                                                      : 0.0f;
    if (e.others_known) {
        const float pushed = others * e.inverse_gain;
        // (pushed == block.others: the push did not change, hold_with_others does nothing.)
        if (at_rest && pushed != block.others && (e.held_before || first) && law.limits.resists) {
            z = hold_at_rest(block, z, pushed, pos, neg, pos_limit, neg_limit);
        }
        block.others = pushed;
    }
    const bool toward_positive = z >= 0;
    float f = -(toward_positive ? pos : neg) * z;
    const AxisObservers* const observers = c.observers;
    const bool on_axis = observers != nullptr && still_surface;
    if (law.inverse_presliding > 0 && dt_s > 0) {
        // The fade depends on the axis' velocity alone: the engine's, once per axis (issue 14).
        f += on_axis ? bristle_damping_faded(law.damping, z, observers->damped_velocity[a], observers->damped_way[a],
                                             observers->fade[a])
                     : bristle_damping(law.stiffness, z, c.velocity[a] - surface_speed, state.inverse_fade_speed);
    }
    if (b.deadband > 0) {
        f *= deadband_gate((c.velocity[a] - surface_speed) * c.velocity_scale, static_cast<float>(b.deadband));
    }
    const float limit = toward_positive ? pos_limit : neg_limit;
    f = f > limit ? limit : (f < -limit ? -limit : f);
    if (e.guarding && still_surface && b.deadband == 0) {
        // A free handle coming to rest gets only what stops it (stop_guard.hpp).
        StopGuard& g = block.guard;
        // The engine's observer of the axis, shared by every friction on it (issue 14).
        const float guarded =
            observers != nullptr
                ? guard_stop(g, observers->view[a], bristle, guard, position, others, f, law.limits, pos, neg)
                : guard_stop_on_line(g, bristle, guard, position, c.applied_force[a], others, f, law.limits.f, pos,
                                     neg);
        const float side = guarded >= 0 ? neg_limit : pos_limit;
        f = guarded > side ? side : (guarded < -side ? -side : guarded);
        remember_output(g, f, e.output_gain);
    }
    return f;
}

// The same out of line, for the lean loop's rare other block (the first tick, a NaN): the
// lean loop keeps its registers. (The tick's values by value: the lean loop need not keep
// them in memory for it.)
[[gnu::noinline]] float render_block_out_of_line(const EffectTick e, FrictionState& state, const SlotConditionBlock& b,
                                                 FrictionBlock& block, int a) noexcept {
    const float f = render_block(e, state, b, block, a);
    block.law.lean = block.law.eligible && block.bristle.primed;  // (primed at its first tick)
    return f;
}

// The block's law, worked out again when its block changed.
[[gnu::always_inline]] inline void keep_law(FrictionBlock& block, const ConditionContext& c, const FrictionState& state,
                                            const SlotConditionBlock& b) noexcept {
    FrictionBlockLaw& law = block.law;
    if (!law_is_for(law, b)) {
        remember_law(law, *c.config, state.tick_dt, b);
        law.lean = law.eligible && block.bristle.primed;
    }
}

// The lean way's blocks of one friction (friction_condition below). kSymmetric: every block's
// law has equal coefficients and equal saturations on both sides (laws_symmetric), the common
// friction (the primer's one coefficient): the choices of a side then give the same floats
// and are left out (issue 14, fifteenth pass). x86 only (kFrictionLeanWay).
template <bool kSymmetric>
[[gnu::always_inline]] inline void render_lean_blocks(const ConditionContext& c, const EffectTick& e,
                                                      FrictionState& state, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    const int blocks = p.axis_count;
    // (The context's arrays once: the blocks' byte stores could alias the context.)
    const float* const positions = c.position;
    const float* const others_force = c.others_force;
    const AxisObservers& observers = *c.observers;
    for (int i = 0; i < blocks; ++i) {
        const int a = axis_index(p.axes[i]);
        const SlotConditionBlock& b = p.conditions[i];
        FrictionBlock& block = state.block[i];
        FrictionBlockLaw& law = block.law;
        Bristle& bristle = block.bristle;
        const float position = positions[a];
        // (advance with no slip: x - 0 is x. The anchor is always finite, so dx + z is
        // finite only where the position and the deflection are.)
        const float dx = position - bristle.anchor;
        // (law.lean: the block eligible and its bristle primed.)
        if (!law.lean || !std::isfinite(dx + bristle.deflection)) {
            force[a] += render_block_out_of_line(e, state, b, block, a);
            continue;
        }
        // The lean way: render_block's steps with what it tests known (a still surface, no
        // deadband, a resisting friction with a presliding zone, the bristle primed, the
        // position and the deflection finite, the observers, the others' force and the guard
        // there), bit for bit the same force.
        const bool at_rest = position == bristle.anchor;
        bristle.anchor = position;
        float z = move_bristle<true, true>(bristle, dx, law.inverse_presliding);
        const float others = others_force[a];
        const float pushed = others * e.inverse_gain;
        // (Symmetric: the same floats on both sides, so the sides' selections below fold.)
        const float pos = law.pos, neg = kSymmetric ? law.pos : law.neg;
        const float pos_limit = law.pos_limit, neg_limit = kSymmetric ? law.pos_limit : law.neg_limit;
        if (at_rest && pushed != block.others && e.held_before) {
            z = hold_at_rest(block, z, pushed, pos, neg, pos_limit, neg_limit);
        }
        block.others = pushed;
        const bool toward_positive = z >= 0;
        float f = -(toward_positive ? pos : neg) * z + bristle_damping_faded(law.damping, z, observers.damped_velocity[a],
                                                                            observers.damped_way[a], observers.fade[a]);
        const float limit = toward_positive ? pos_limit : neg_limit;
        f = f > limit ? limit : (f < -limit ? -limit : f);
        StopGuard& g = block.guard;
        // (The view read in place: its fields are floats and a byte read once, which the
        // guard's stores to g cannot change, so each is loaded once and only where needed.)
        const float guarded =
            guard_stop(g, observers.view[a], bristle, state.guard_tick, position, others, f, law.limits, pos, neg);
        const float side = guarded >= 0 ? neg_limit : pos_limit;
        f = guarded > side ? side : (guarded < -side ? -side : guarded);
        remember_output(g, f, e.output_gain);
        force[a] += f;
    }
}

}  // namespace

void friction_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    // Single precision (issue 14); what is per tick or per command rather than per block
    // and tick is worked out once (remember_tick, remember_law).
    FrictionState& state = c.state->friction;
    const float dt_s = c.dt_s;
    if (state.tick_dt != dt_s) remember_tick(state, *c.config, dt_s);
    EffectTick e;
    e.context = &c;
    e.dt_s = dt_s;
    e.output_gain = static_cast<float>(p.gain) / static_cast<float>(kFullScale) * c.device_gain;
    // The others' force is kept in this friction's units (before its gain and the device's),
    // so that a gain change, which scales the friction too, is not taken for a push easing.
    e.others_known = c.others_force != nullptr && e.output_gain != 0;
    e.inverse_gain = e.others_known ? 1.0f / e.output_gain : 0.0f;
    e.held_before = state.others_known;
    // The stop guard's preconditions that hold for every block of this tick.
    e.guarding = state.guard_tick.on && c.applied_force != nullptr;
    // The common friction (issue 14, friction's fifth pass): on the device's axes, with the
    // engine's observers, the others' force known, the guard on and a tick to damp over.
    // Its blocks take the lean way below unless one of them needs more (render_block).
    // (The guard on implies a tick to damp over: stop_guard_tick.)
    const bool lean = kFrictionLeanWay && c.observers != nullptr && e.others_known && e.guarding;
    const int blocks = p.axis_count;
    if (!lean) {
        // A friction with a direction, or without the guard (no device_mass): every block
        // the general way, inline.
        for (int i = 0; i < blocks; ++i) {
            const int a = axis_index(p.axes[i]);
            const SlotConditionBlock& b = p.conditions[i];
            FrictionBlock& block = state.block[i];
            keep_law(block, c, state, b);
            force[a] += render_block(e, state, b, block, a);
        }
        state.others_known = e.others_known;
        return;
    }
    // The blocks' laws checked once an effect (issue 14, fifteenth pass): they change only
    // with the tick period and the parameters, which clear laws_current.
    if (!state.laws_current) {
        bool symmetric = true;
        for (int i = 0; i < blocks; ++i) {
            keep_law(state.block[i], c, state, p.conditions[i]);
            symmetric = symmetric && state.block[i].law.symmetric;
        }
        state.laws_symmetric = symmetric;
        state.laws_current = true;
    }
    if (state.laws_symmetric) {
        render_lean_blocks<true>(c, e, state, force);
    } else {
        render_lean_blocks<false>(c, e, state, force);
    }
    state.others_known = e.others_known;
}

}  // namespace feel::detail
