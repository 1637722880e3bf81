// Texture (§3.6, §6.6.j): a grating of bumps that resist the motion across them.
//
//   s     = the handle's coordinate along the texture's line: its axis, or for a texture
//           on several axes the unit vector u of its direction (u = (sin a, cos a) for a
//           polar angle a; the §7.5 washboard on x, y at polar 0 runs along y)
//   w     = spacing · density / 10000, the bump width
//   z     = a Dahl bristle along s (friction_model.hpp): +1 moving toward +s, -1 toward -s,
//           a smooth turn-around between
//   F_s   = -R·bump(s)·z + microdamping,  R = pos_roughness while z >= 0, neg_roughness
//           while z < 0 (the bristle's microdamping scaled by the bump, friction_model.hpp)
//   F     = F_s along the line (on each axis a, F_s·u_a)
//
// A texture is friction, so it holds and lets go as friction does (issue 16 §1): a handle
// that the other effects push while it stands on a bump is held with their push, within
// the bump's roughness, and let go with it (hold_with_others, friction_model.hpp). A free
// handle coasting to rest on a bump is let go as friction lets it go, by friction's stop
// guard (stop_guard.hpp) on the texture's line with the bump's local strength R·bump(s) and
// its own observer of that line. What makes the guard safe here is its quick-stop test (the
// handle slid faster than 2 counts per 3 ms no longer ago than the force alone could have
// stopped it): a free stop meets it; a hand dragging the handle under a count a tick, whose
// slow travel the observer's prediction cannot refute within a count, does not (without it
// the guard cut the force on bump tops near a slow turn: docs/conditions.md, "Limits").
//
// The primer calls a texture "a spatially varying resistance" (§3.1) whose intensity can
// differ with the direction of travel (§3.6): here every bump is a patch of friction of
// strength R·bump(s). Dragged across the grating the handle meets a resistance that rises
// and falls once per spacing, felt as a rattle whose pitch follows the speed; at rest it
// holds still. Because the force always opposes the motion it only dissipates: a texture
// cannot make the handle unstable however fine its spacing, which a conservative washboard
// (a force pushing the handle into the gaps) of useful depth could, being a spring far
// stiffer than the device's passivity bound.
//
// The bump is a raised cosine, 1 on its top (s a multiple of spacing) and 0 beyond w/2:
//
//   bump                       spacing
//     1 |     _               <------->     _
//       |    / \                           / \            density 3000: w = 0.3 spacing
//       |   /   \                         /   \          (s = 0 is a bump's top)
//     0 +--'-----'-------------------------'-----'------- s
//       -w/2  0  w/2                  spacing
#include <cstring>

#include "conditions/condition_math.hpp"

namespace feel::detail {

namespace {

// Keeping the law costs about 130 bytes of Thumb code: a build for size (the Cortex-M4F
// firmware, whose flash is at its goal) works it out every tick instead, as it leaves out
// friction's lean way, which gives the same force.
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool kKeepTextureLaw = false;
#else
inline constexpr bool kKeepTextureLaw = true;
#endif

// The texture's law for its block at tick period dt_s: what its tick used to work out every
// tick, once (issue 14, twelfth pass).
TextureLaw texture_law_for(const EngineConfig& config, float dt_s, const TextureBlock& t) noexcept {
    TextureLaw law;
    law.key[0] = t.pos_roughness;
    law.key[1] = t.neg_roughness;
    law.key[2] = t.spacing;
    law.key[3] = t.density;
    law.pos = static_cast<float>(t.pos_roughness);
    law.neg = static_cast<float>(t.neg_roughness);
    law.roughness = law.pos > law.neg ? law.pos : law.neg;
    law.presliding = presliding_distance(config, dt_s, law.roughness);
    law.inverse_presliding = law.presliding > 0 ? 1.0f / law.presliding : 0.0f;
    law.spacing = static_cast<float>(t.spacing);
#if defined(__OPTIMIZE_SIZE__)
    law.inverse_spacing = 0.0f;  // (unread: the board divides)
#else
    law.inverse_spacing = 1.0f / law.spacing;
#endif
    law.width = static_cast<float>(t.spacing) * static_cast<float>(t.density) / static_cast<float>(kFullScale);
    law.bumps = t.spacing > 0 && law.width > 0;
    return law;
}

// Whether the law was worked out for this block.
bool texture_law_is_for(const TextureLaw& law, const TextureBlock& t) noexcept {
    static_assert(sizeof(TextureBlock) == sizeof(law.key));
    return std::memcmp(law.key, &t, sizeof law.key) == 0;
}

}  // namespace

void texture_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    const TextureBlock& t = p.texture;
    FrictionState& state = c.state->friction;
    float u[kMaxAxes] = {};
    if (p.axis_count == 1) {
        u[device_axis(c, 0)] = 1.0f;
    } else {
        condition_line(c, u);
    }
    const float s = along(c, u, c.position);
    FrictionBlock& block = state.block[0];
    // What is per tick length rather than per tick is kept with friction's, under its key:
    // the stop guard's gains and the microdamping's 1/fade speed (friction_condition.cpp);
    // and what is per block too, the texture's law. (The law is read only once the tick
    // length matched: a fresh state's never does, so the law then holds the texture's.)
    TextureLaw this_tick;
    const bool new_tick_length = state.tick_dt != c.dt_s;
    const bool renew = !kKeepTextureLaw || new_tick_length || !texture_law_is_for(block.texture, t);
    if (renew) {
        if (new_tick_length) {
            state.guard_tick = stop_guard_tick(*c.config, c.dt_s);
            state.inverse_fade_speed = 1.0f / (kBristleDampingFade * c.config->velocity_ref);
            state.tick_dt = c.dt_s;
        }
        this_tick = texture_law_for(*c.config, c.dt_s, t);
        if (kKeepTextureLaw) block.texture = this_tick;  // (the block's union holds the texture's law from here on)
    }
    const TextureLaw& law = renew ? this_tick : block.texture;
    const float pos = law.pos, neg = law.neg;
    const float roughness = law.roughness;
    const float presliding = law.presliding;
    Bristle& bristle = block.bristle;
    const bool first = !bristle.primed;  // nothing held yet: take the others' push from here
    const bool at_rest = first || s == bristle.anchor;
    float z = advance(bristle, s, 0.0f, law.inverse_presliding);
    const float bump = law.bumps ? grating_bump(s, law.spacing, law.inverse_spacing, law.width) : 0.0f;
    const float output_gain = static_cast<float>(p.gain) / static_cast<float>(kFullScale) * c.device_gain;
    // The others' force along the line, and in this texture's units, as for friction
    // (friction_condition.cpp).
    const float others_along = c.others_force != nullptr ? along(c, u, c.others_force) : 0.0f;
    const bool others_known = c.others_force != nullptr && output_gain != 0;
    const float pushed = others_known ? others_along / output_gain : 0.0f;
    if (others_known) {
        if (at_rest && (state.others_known || first)) {
            const float held = -(z >= 0 ? pos : neg) * bump * z;
            if (bump > 0) {
                hold_with_others(bristle, held, held, z == 1.0f || z == -1.0f, block.others, pushed, pos * bump,
                                 neg * bump);
            }
            z = bristle.deflection;
        }
        block.others = pushed;
    }
    state.others_known = others_known;
    float f = -(z >= 0 ? pos : neg) * bump * z;
    if (presliding > 0 && c.dt_s > 0) {
        const float stiffness = roughness * bump / presliding;
#if defined(__OPTIMIZE_SIZE__)
        f += bristle_damping(stiffness, z, along(c, u, c.velocity), state.inverse_fade_speed);
#else
        // Off a bump the stiffness is 0 and the damping 0: that test flips with the bump's
        // edge, so the damping is worked out with a stiffness > 0 (its value is linear in
        // it: the first factor) and selected, the same float (issue 14, twelfth pass).
        const float some_stiffness = select_if_greater(stiffness, 0.0f, stiffness, 1.0f);
        const float damping = bristle_damping(some_stiffness, z, along(c, u, c.velocity), state.inverse_fade_speed);
        f += select_if_greater(stiffness, 0.0f, damping, 0.0f);
#endif
    }
    const float limit = roughness * bump;
    // The guard's switch first: limit > 0 flips with the bump's edge, the switch never.
    if (c.applied_force != nullptr && state.guard_tick.on) {
        if (limit > 0) {
            const float applied = along(c, u, c.applied_force);
            const float others = c.others_force != nullptr ? others_along : applied - block.guard.own;
            StopGuard& g = block.guard;
            f = guard_stop_on_line(g, bristle, state.guard_tick, s, applied, others, f, limit, pos * bump, neg * bump);
            f = f > limit ? limit : (f < -limit ? -limit : f);
            remember_output(g, f, output_gain);
        }
    }
    add_force_along(c, u, f, force);
}

}  // namespace feel::detail
