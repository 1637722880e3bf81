// The friction model of friction and texture conditions: a Dahl bristle whose presliding
// stiffness is set by what the device can render passively, and the bump of a texture.
//
// Why a bristle (Dahl 1968) and not a function of velocity. Friction has to do three
// things at once here: resist sliding with a constant force, hold the handle still against
// a push smaller than that force, and turn around without a sharp jerk. A function of
// velocity, sign(v) smoothed as v/v_s near zero (the "smoothed Coulomb" most devices of
// the primer's time used, §3.5), can do the third but not the second (under a steady push
// it creeps at v_s·push/f), and near rest it is a damper of slope f/v_s acting on a
// velocity that must be estimated from quantized positions: on the joystick profile at
// 1 kHz a friction of 10000 chatters with v_s = 1% and 5% of velocity_ref, and at 10%
// lets a push creep 18 mm a second (measured with the simulated device;
// docs/conditions.md). Karnopp's model holds the handle with
// exactly the other forces on it, which a haptic device cannot know: the hand's force is
// not measured. A bristle needs no velocity at all. It is a spring between the handle and
// an anchor that slides: pushed less than f, the handle deflects the spring and stays;
// pushed more, the anchor slips and the force is f. Dahl's law gives the spring a smooth
// knee instead of a corner, per unit of handle travel dx:
//
//     dz = dx·(1 - z·sign(dx)),   z = deflection / presliding distance ∈ [-1, 1]
//     F  = -f·z
//
// (exact for a monotone step: z' = ±1 + (z ∓ 1)·e^(-|dx|/Z), so no step size can overshoot).
// Turning around, the force passes through zero along a spring of stiffness f/Z: no jerk.
// At rest the position does not change and neither does the force: no chatter. A handle
// pushed by less than f holds still, deflected by push/(f/Z).
//
// Presliding stiffness. The bristle is a spring the device renders from sampled positions,
// so it obeys the passivity bound of any virtual spring, K <= 2b/T (Colgate & Schenkel;
// b the device's own damping EngineConfig::device_damping, T the tick). Stiffer, and the
// handle rings or chatters around its stuck position. Softer, and turning around takes
// long. So the stiffness is the bound itself, with two guards:
//   - at least f / kMaxPresliding: the force builds up within 5% of the travel (5 mm on
//     the joystick) even on a device that reports no damping;
//   - at most kMaxForcePerCount / (2·sensor_step): one sensor count never moves the force
//     by more than 2% of full scale (Dahl's slope is at most 2·f/Z, turning around from
//     full deflection), or the handle could buzz between two counts.
// On the joystick at 1 kHz that is 11.2 force units per position unit, 1 N/mm at the
// grip (f = 10000 builds up over 890 units, 4.5 mm).
//
// Microdamping. A bristle is a spring, and a handle stuck on it with little damping of its
// own (the wheel: ζ ≈ 0.01) rings on it for seconds after a push. LuGre (Canudas de Wit et
// al. 1995) adds a damping σ1 on the bristle's rate ż; with σ1 faded out as exp(-(v/v_d)²)
// the model stays passive (Olsson et al. 1998) and the damping cannot jerk a fast reversal.
// Here σ1 = σ0·kBristleDampingTime and v_d = kBristleDampingFade·velocity_ref:
//
//     F_damping = -σ0·τ·ż·exp(-(v/v_d)²),   ż = v·(1 - z·sign(v))   (position units/s)
//
// ż vanishes while sliding (z = ±1 in the direction of motion), so this adds no viscous
// drag to the sliding force. τ = 2 ms damps the presliding ringing of all three device
// profiles at 1 kHz and 10 kHz; 10 ms starts to chatter (docs/conditions.md has the
// measurements).
//
// A bristle is a spring, so a free handle that friction brings to rest would be thrown back
// by the force stored in it; friction_condition.cpp adds the stop guard (stop_guard.hpp)
// that prevents it.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "feel/engine.hpp"
#include "float_exp.hpp"
#include "float_round.hpp"
#include "float_select.hpp"

namespace feel::detail {

// Single precision (issue 14): the model's constants and every computation below are float,
// so that the Cortex-M4F computes it in its FPU (a double operation there is a library call).

// The presliding distance is at most this, position units (5% of the travel).
inline constexpr float kMaxPresliding = 1000.0f;
// One sensor count moves a bristle's force by at most this, force units (2% of full scale).
inline constexpr float kMaxForcePerCount = 200.0f;
// Microdamping: σ1 = σ0 · this, s.
inline constexpr float kBristleDampingTime = 0.002f;
// Microdamping fades out above this fraction of EngineConfig::velocity_ref.
inline constexpr float kBristleDampingFade = 0.1f;

// A Dahl bristle on one line of motion. Zero-initialized it is relaxed and not yet primed;
// the first advance() only records where the handle is.
struct Bristle {
    float deflection = 0.0f;  // z, -1..1: +1 = fully dragged by motion toward +, force -f
    float anchor = 0.0f;      // position at the last advance, position units
    bool primed = false;      // anchor is valid
};

// The square of the speed (in fade speeds) beyond which the microdamping is left out.
inline constexpr float kDampingFadeCutoff = 36.0f;

// What the presliding stiffness K of every bristle of a tick depends on but f: the
// passivity bound 2b/T and the sensor-resolution cap, force units per position unit. One
// rule per tick saves the divisions per block (issue 14: friction's cost per effect).
struct PreslidingRule {
    float passive = 0.0f;  // 2b/T, 0 when there is no tick to judge by
    float cap = 0.0f;      // kMaxForcePerCount / (2·sensor_step)
};

[[nodiscard]] PreslidingRule presliding_rule(const EngineConfig& config, float dt_s) noexcept;

// K = min(max(2b/T, f / kMaxPresliding), cap) for a friction of magnitude f > 0.
// (Comparisons rather than std::fmax/fmin: those are library calls where NaNs must be
// honoured, and nothing here is NaN.)
[[nodiscard]] inline float presliding_stiffness(const PreslidingRule& rule, float f) noexcept {
    float stiffness = f * (1.0f / kMaxPresliding);
    if (rule.passive > stiffness) stiffness = rule.passive;
    return stiffness > rule.cap ? rule.cap : stiffness;
}

// The presliding distance Z, position units, for a friction of magnitude f (force units,
// >= 0) on this device at this tick period (s). 0 for f = 0. dt_s <= 0 uses the guards
// only (no tick to judge passivity by).
[[nodiscard]] float presliding_distance(const EngineConfig& config, float dt_s, float f) noexcept;

// e^-u for the travel u >= 0 of one tick in presliding distances. A tick's travel is a few
// counts and the zone tens to hundreds (docs/stability.md), so u is mostly below 1/4: there
// the Taylor polynomial to u⁶ (truncation within u⁷/5040 < 1.3e-8) is within 1.3e-7 of e^-u
// (2 float ulps, checked on every float in [0, 1/4)), where float_exp is a call
// whose caller must save every live register (issue 14: friction's cost per effect). It is
// evaluated in Estrin's form, the powers u² and u⁴ beside the coefficients, so that its
// chain of dependent operations is 5 long rather than Horner's 12: a tick renders many
// blocks, and each block's force waits on its exponential.
[[nodiscard]] inline float exp_of_travel(float u) noexcept {
    if (u < 0.25f) {
        const float u2 = u * u, u4 = u2 * u2;
        const float low = (1.0f - u) + u2 * (0.5f - u * (1.0f / 6));
        const float high = (1.0f / 24 - u * (1.0f / 120)) + u2 * (1.0f / 720);
        return low + u4 * high;
    }
    return float_exp(-u);
}

// Moves a primed bristle by the handle's travel dx (position units) over a presliding
// distance 1/inverse_presliding (0: none, the bristle flips at once). Returns the new
// deflection z. Single precision (issue 14): z is kept in float anyway, and a step's travel
// is a few counts. kFinite: the caller knows dx and z finite, and so is the new z (e^-u is
// in [0, 1] for any u >= 0, inf included), so the check for a non-finite z is left out.
// kZone: the caller knows inverse_presliding > 0, so that test is left out.
template <bool kFinite = false, bool kZone = false>
[[nodiscard, gnu::always_inline]] inline float move_bristle(Bristle& b, float dx, float inverse_presliding) noexcept {
    float z = b.deflection;
    const bool zone = kZone || inverse_presliding > 0;
    // Fully slid in the direction of travel, the exact update leaves z at ±1 (the common case
    // while sliding): no exponential. dx = 0 (or NaN) leaves z as it is.
    if (dx > 0) {
        if (z == 1.0f) return z;
        z = zone ? 1.0f + (z - 1.0f) * exp_of_travel(dx * inverse_presliding) : 1.0f;
    } else if (dx < 0) {
        if (z == -1.0f) return z;
        z = zone ? -1.0f + (z + 1.0f) * exp_of_travel(-dx * inverse_presliding) : -1.0f;
    }
    if (!kFinite && !std::isfinite(z)) z = 0.0f;  // a non-finite slip or hold: forget rather than output NaN
    b.deflection = z;
    return z;
}

// Moves the bristle with the handle now at `position` (along the bristle's line, position
// units), less `slip` (how far the surface itself moved since the last tick, for a
// friction with a velocity offset), over a presliding distance 1/inverse_presliding
// (inverse_presliding 0: none, the bristle flips at once). Returns the new deflection z.
[[nodiscard]] inline float advance(Bristle& b, float position, float slip, float inverse_presliding) noexcept {
    if (!b.primed || !std::isfinite(position)) {
        if (std::isfinite(position)) {
            b.anchor = position;
            b.primed = true;
        }
        return b.deflection;
    }
    const float dx = position - b.anchor - slip;
    b.anchor = position;
    return move_bristle(b, dx, inverse_presliding);
}

// Sets the bristle to the deflection whose force is `hold` (force units; -c·z with c =
// pos_coefficient for z >= 0, neg_coefficient for z < 0), z kept within ±1. Returns the
// force it now applies. A zero coefficient on hold's side leaves the bristle relaxed.
inline float set_bristle_force(Bristle& bristle, float hold, float pos_coefficient, float neg_coefficient) noexcept {
    const float coefficient = hold <= 0 ? pos_coefficient : neg_coefficient;
    float z = coefficient != 0 ? -hold / coefficient : 0.0f;
    z = z > 1.0f ? 1.0f : (z < -1.0f ? -1.0f : z);
    bristle.deflection = z;
    return -(z >= 0 ? pos_coefficient : neg_coefficient) * z;
}

// Stiction balances the engine's own push at once (issue 16 §1). Called when the handle has
// not moved this tick (its sensed position is the bristle's anchor), so whatever holds it
// holds it against the other effects' force, which went from `before` to `now` (this
// friction's force units). Coulomb's static friction is whatever balances the push, within
// ±f, so a bristle within its zone (stuck) is set at once to hold `now` plus what else it
// held (a hand's push, which the engine cannot see: what it held beyond `before`). The
// handle then never moves into the bristle's presliding zone under an effect's push smaller
// than f (before: it deflected the bristle by push/K, 30 to 409 sensor counts), and when the
// push eases, ends or turns the bristle follows at the same tick, so it never throws the
// handle back (the joystick, friction 6000, a push of 3000 or 5000 held and released: 76 to
// 1403 units back with a bristle alone). A bristle at its limit (`slipping`: |z| = 1 or
// saturated) may be sliding slowly, under a count a tick, with a hand on it: it only lets go
// with an easing push, by as much and never past 0 (the previous pass's rule), so that a
// sliding handle keeps its kinetic friction. A push larger than f is not held. `force` is
// the bristle's force -c·z, `held` what it applied (after its saturation). Needs no mass:
// the engine knows its own effects' forces (ConditionContext::others_force).
inline void hold_with_others(Bristle& bristle, float force, float held, bool slipping, float before, float now,
                             float pos_coefficient, float neg_coefficient) noexcept {
    if (now == before) return;
    if (slipping) {
        const float change = now - before;
        if (!(force * change > 0)) return;  // the push grew: the bristle slides on as it was
        const float ratio = (held - change) / force;
        bristle.deflection *= ratio > 0 ? ratio : 0.0f;
        return;
    }
    const float hold = -(now - held - before);
    // A push larger than f is not held: the handle slides into the bristle as it would
    // without this rule (taking it at once, z = ±1, was tried: the free wheel at 500 Hz, f =
    // 8000, shoved by 10000, then moves within the stop guard's velocity noise and its stop
    // overshoots, 6 units back against a bound of 2.4).
    if (hold > pos_coefficient || -hold > neg_coefficient) return;
    (void)set_bristle_force(bristle, hold, pos_coefficient, neg_coefficient);
}

// The microdamping force of a bristle of presliding stiffness `stiffness` (f/Z, force
// units per position unit) at deflection z, the handle moving at `velocity` (units/s)
// relative to the surface, with 1 / (kBristleDampingFade·velocity_ref) computed once by the
// caller.
[[nodiscard]] inline float bristle_damping(float stiffness, float z, float velocity, float inverse_fade_speed) noexcept {
    if (!(stiffness > 0) || velocity == 0 || !std::isfinite(velocity)) return 0.0f;
    const float rate = velocity * (1.0f - z * (velocity > 0 ? 1.0f : -1.0f));
    if (rate == 0) return 0.0f;  // fully slid along the motion: no bristle rate to damp
    const float r = velocity * inverse_fade_speed;
    const float r2 = r * r;
    // Beyond 6 fade speeds the fade is below 2.4e-16: nothing a force can show.
    if (r2 > kDampingFadeCutoff) return 0.0f;
    return -stiffness * kBristleDampingTime * rate * float_exp(-r2);
}

// The fade exp(-(v/v_d)²) of the microdamping alone, 0 beyond the cutoff: it depends on the
// velocity only, so the engine works it out once per axis for every friction on it (issue 14).
[[nodiscard]] inline float bristle_damping_fade(float velocity, float inverse_fade_speed) noexcept {
    const float r = velocity * inverse_fade_speed;
    const float r2 = r * r;
    return r2 > kDampingFadeCutoff || !std::isfinite(r2) ? 0.0f : float_exp(-r2);
}

// bristle_damping on a device axis from what the engine works out once per axis
// (AxisObservers: the fade, the velocity where the fade is not 0 else 0, and its way, +1 or
// -1), with `damping` = -stiffness·kBristleDampingTime for a stiffness > 0 (worked out once
// per command): the same value, bit for bit, but for the sign of a zero. No branch.
[[nodiscard]] inline float bristle_damping_faded(float damping, float z, float damped_velocity, float way,
                                                 float fade) noexcept {
    return damping * (damped_velocity * (1.0f - z * way)) * fade;
}

// The bump of a texture (§3.6) at coordinate s along its line: bumps are centered on every
// multiple of `spacing` (s = 0 is a bump's top) and `width` wide, a raised cosine
//
//     bump(r) = (1 + cos(2π·r/width)) / 2   for |r| <= width/2,   0 beyond,
//
// r the distance to the nearest center. 1 on top, falling smoothly (zero slope at both
// ends) to 0 at the bump's edges, so the force has no step entering or leaving a bump;
// width = spacing (density 10000) makes the bumps touch: a sinusoidal washboard.
// Single precision (issue 14): (1 + cos 2θ)/2 = cos²θ with θ = π·r/width in [-π/2, π/2],
// where cos is its Taylor polynomial to θ¹² (cos_within_half_pi below): no library call, and the
// same on every platform.
[[nodiscard]] float texture_bump(float s, int32_t spacing, float width) noexcept;

// cos θ for |θ| <= π/2 by its Taylor polynomial to θ¹² (the next term is below
// (π/2)¹⁴/14! = 6.4e-9, a tenth of a float ulp of 1/2), in θ² by Horner's rule.
[[nodiscard]] inline float cos_within_half_pi(float theta) noexcept {
    const float t = theta * theta;
    constexpr float c2 = -1.0f / 2, c4 = 1.0f / 24, c6 = -1.0f / 720, c8 = 1.0f / 40320;
    constexpr float c10 = -1.0f / 3628800, c12 = 1.0f / 479001600;
    return 1.0f + t * (c2 + t * (c4 + t * (c6 + t * (c8 + t * (c10 + t * c12)))));
}

// texture_bump for a spacing (> 0, a whole number of position units), its inverse 1/step
// and width (> 0) kept as floats: the texture's tick, which keeps them (TextureLaw,
// friction_state.hpp). Inline: the texture's tick is its one caller on the board, and on x86
// a call spills the tick's floats.
[[nodiscard]] inline float grating_bump(float s, float step, float inverse_step, float width) noexcept {
    // (Exact: step·round(s/step) is an integer below 2^24 and s a multiple of its ulp there.
    // The index's zero may have either sign: r's zero then does too, which only θ² reads.)
    const float r = s - step * nearest_multiple_index(s, step, inverse_step);
    const float half = width / 2.0f;
#if defined(__OPTIMIZE_SIZE__)
    if (r > half || r < -half) return 0.0f;
    const float c = cos_within_half_pi(std::numbers::pi_v<float> * r / width);
    return c * c;  // (1 + cos 2θ)/2
#else
    // The bump worked out whatever r and selected: a handle dragged across the grating leaves
    // or meets a bump every tick or two, and the jump on it was mispredicted at the end of the
    // division's chain (issue 14, twelfth pass, "The bumps without jumps"). |r| > half is
    // r > half || r < -half, NaN included (both false).
    const float c = cos_within_half_pi(std::numbers::pi_v<float> * r / width);
    return select_if_greater(std::fabs(r), half, 0.0f, c * c);
#endif
}

}  // namespace feel::detail
