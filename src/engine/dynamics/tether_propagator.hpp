// One piece of a linear spring-damper as a few float multiply-adds: tether_step's exact
// solution, worked out once for a piece length and applied every tick.
//
// Between events (a crossing of the play's edge, a change of stiffness) a tethered mass is
// a linear system with constant coefficients,
//
//     m·ÿ + c·ẏ + k·y = f        (f constant over the piece)
//
// so its exact motion over a piece of length h is affine in the start state and in f:
//
//     [y(h), ẏ(h)] = Φ·[y0, ẏ0] + Γ·f
//
// Φ (the state-transition matrix, e^{Ah}) and Γ (the response to a unit force from rest)
// depend only on m, c, k and h. They are computed in float (tether_step's closed form, and
// the shears below from their own closed form) when the parameters or the tick length
// change, and each tick costs a handful of float operations instead of an exp, a sin and
// a cos.
//
// Rounding Φ to float would break what the exact step guarantees for an undamped mass:
// det Φ = e^{−c·h/m} is what keeps its energy, and a rounded Φ has det 1 ± 1e-7, which over
// a minute of 1 kHz ticks gains or loses up to 0.6% of the energy. So an oscillating
// (underdamped) piece is stored as Φ = E·M, E = e^{−c·h/2m} and M with det M = 1, and M
// as three shears,
//
//     M = [1 x; 0 1]·[1 0; w 1]·[1 z; 0 1],    w = M21,  x = (M11 − 1)/w,  z = (M22 − 1)/w
//
// each of which has determinant exactly 1 whatever its coefficient rounds to. The rounded
// map is then an exact symplectic map of a system a few 1e-7 away, scaled by E ≤ 1: its
// energy stays within rounding of a conserved value instead of drifting. Overdamped,
// critically damped and free pieces are stored as the plain matrix: they dissipate far
// more per piece than its rounding could add.
//
// The shears come from their closed form, not from M: with θ = ωd·h (ωd² = ω0² − γ²),
// S = sin θ/ωd and q = ωd·tan(θ/2) = (1 − cos θ)/S,
//
//     x = (q − γ)/ω0²,   z = (q + γ)/ω0²,   w = −ω0²·S
//
// (M11 − 1 = cos θ − 1 + γS would lose everything to cancellation in float for a short
// piece; tan(θ/2) is sin θ/(1 + cos θ), or (1 − cos θ)/sin θ past a quarter turn, neither
// of which cancels). Each coefficient is right to a few float ulps, so the map's frequency
// is off the law's by a few 1e-7 of itself, a phase error of that fraction of the angle
// turned (docs/dynamics.md, "Precision").
//
// Real-time safe: no allocation, no state; float only.
#pragma once

#include <cstdint>

#include "dynamics/tether_step.hpp"

namespace feel::detail {

struct TetherPropagator {
    bool sheared = false;  // the three-shear form (an oscillating piece), else the plain matrix
    // sheared: x, w, z of the three shears, and 1 − E; plain: Φ = [c0 c1; c2 c3]
    float c0 = 1, c1 = 0, c2 = 0, c3 = 1;
    float force_y = 0, force_v = 0;  // Γ: the position and velocity after h from rest under f = 1
};

// The piece of length h (> 0) of the system s (its `force` is ignored: f is given at each
// application). Float throughout.
[[nodiscard]] TetherPropagator tether_propagator(const SpringDamperF& s, float h) noexcept;

// Advances (y, v) by the piece under the constant force f.
inline void propagate(const TetherPropagator& p, float f, float& y, float& v) noexcept {
    float y1;
    float v1;
    if (p.sheared) {
        y1 = y + p.c2 * v;
        v1 = v + p.c1 * y1;
        y1 = y1 + p.c0 * v1;
        y1 = y1 - y1 * p.c3;
        v1 = v1 - v1 * p.c3;
    } else {
        y1 = p.c0 * y + p.c1 * v;
        v1 = p.c2 * y + p.c3 * v;
    }
    y = y1 + p.force_y * f;
    v = v1 + p.force_v * f;
}

// The change of (y, v) over the piece from (y, v) under f, as propagate would leave it,
// weighted: mass·Δv + drag·Δy. The piece's map is affine, so this is a fixed linear form
// of y, v and f, on_y·y + on_v·v + on_f·f, whose coefficients depend only on the
// propagator, the mass and the drag: they are worked out with the propagator
// (weighted_change_form, prepare_pieces), and what a tick does is three products and two
// sums, where propagating and then differencing waited for the propagator's five
// dependent operations and then the differences.
struct WeightedChangeForm {
    float on_y = 0, on_v = 0, on_f = 0;
};

// The coefficients are formed so that the near-identity map's 1 never appears: with
// E = 1 − c3, the sheared map's Δv = E·c1·y + (E·c1·c2 − c3)·v and
// Δy = (E·c0·c1 − c3)·y + E·(c2 + c0·(1 + c1·c2))·v; the plain matrix's
// Δv = c2·y + (c3 − 1)·v, Δy = (c0 − 1)·y + c1·v (an overdamped, critical or free piece,
// whose c3 − 1 and c0 − 1 are exact differences of its rounded entries: the same rounding
// propagate leaves in v and y). Rounding: a few ulps of each term, as propagate's result
// differenced.
[[gnu::always_inline]] inline WeightedChangeForm weighted_change_form(const TetherPropagator& p, float mass,
                                                                      float drag) noexcept {
    float dv_y, dv_v, dy_y, dy_v;
    if (p.sheared) {
        const float e = 1.0f - p.c3;
        const float c1c2 = p.c1 * p.c2;
        dv_y = e * p.c1;
        dv_v = e * c1c2 - p.c3;
        dy_y = e * (p.c0 * p.c1) - p.c3;
        dy_v = e * (p.c2 + p.c0 * (1.0f + c1c2));
    } else {
        dv_y = p.c2;
        dv_v = p.c3 - 1.0f;
        dy_y = p.c0 - 1.0f;
        dy_v = p.c1;
    }
    return {mass * dv_y + drag * dy_y, mass * dv_v + drag * dy_v, mass * p.force_v + drag * p.force_y};
}

[[gnu::always_inline]] inline float weighted_change(const WeightedChangeForm& w, float f, float y, float v) noexcept {
    return (w.on_y * y + w.on_v * v) + w.on_f * f;
}

}  // namespace feel::detail
