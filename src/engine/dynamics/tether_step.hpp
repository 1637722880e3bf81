// The exact step of a mass on a linear spring-damper: the building block of every dynamic.
//
//     m·ÿ + c·ẏ + k·y = f          m > 0, c >= 0, k >= 0, f constant over the step
//
// y is whatever coordinate the caller chooses; the dynamics use the stretch of the tether,
// the mass's position relative to the handle. A handle moving at a constant velocity w over
// the step, a tether damper c_t on the relative velocity and an ambient drag d on the
// mass's absolute velocity all fit this form: with y = x − handle and ẏ = v − w,
//
//     m·ÿ = −k·y − c_t·ẏ − d·(ẏ + w) + g     ⇒     c = c_t + d,   f = g − d·w
//
// The solution is the closed form of the damped oscillator (the matrix exponential of the
// 2×2 system with its constant forcing), so a step of any length is exact: an undamped
// oscillator keeps its energy to rounding, and no stiffness, damping or step length can
// make it blow up. The under-, critically and over-damped cases are one formula, written
// so that nothing cancels catastrophically:
//
//     k > 0:  z = y − f/k,  γ = c/2m,  ω0² = k/m,  Δ = ω0² − γ²
//             C(h) = cos √Δh  or cosh √−Δh,   S(h) = sin √Δh / √Δ  or  sinh √−Δh / √−Δ
//             (Taylor series in Δh² near critical damping), E = e^{−γh}
//             z(h) = E·[(C + γS)·z0 + S·ż0],   ż(h) = E·[(C − γS)·ż0 − ω0²·S·z0]
//             heavily overdamped, E·cosh and E·sinh are formed from e^{−(γ∓β)h}
//             (β = √−Δ, γ − β = ω0²/(γ + β)) so neither overflows nor cancels;
//     k = 0:  a free mass with damping, through expm1 and its series for small c·h/m.
//
// What this does not do is the piecewise part of a model (a one-sided contact, different
// stiffnesses either side, a deadband): those are the caller's, by splitting the step at
// the crossing tether_crossing() finds. Keeping each piece short (tether_substeps: ω·h ≤ 1)
// guarantees a crossing cannot be stepped over unseen.
//
// Real-time safe: no allocation, no exceptions, no state; double precision throughout.
#pragma once

#include <cstdint>

namespace feel::detail {

struct SpringDamper {
    double mass = 1;       // > 0 (callers' units: the dynamics use force units per (position unit/s²))
    double stiffness = 0;  // >= 0, force per unit of y; 0 is a free mass
    double damping = 0;    // >= 0, force per unit of ẏ
    double force = 0;      // constant force on the mass over the step, any sign
};

struct MassState {
    double position = 0;  // y
    double velocity = 0;  // ẏ, per second
};

// The state after h seconds (h >= 0), exact for constant parameters. Finite inputs give
// finite outputs (an undamped oscillator stays bounded; damping only shrinks the motion).
[[nodiscard]] MassState tether_step(const SpringDamper& s, MassState x, double h) noexcept;

// ω0 = sqrt(k/m), the undamped natural frequency, rad/s. Damping needs no substeps (the step
// is exact however heavily damped); only the oscillation decides how short a piece is.
[[nodiscard]] double tether_omega(const SpringDamper& s) noexcept;

// Pieces to cut a step of h seconds into so that each has ω0·h_piece <= 1: the smallest n
// with ω0·h/n <= 1, at least 1, at most max_substeps (beyond it the pieces are longer but
// each stays exact; only tether_crossing's guarantee is lost).
[[nodiscard]] int32_t tether_substeps(const SpringDamper& s, double h, int32_t max_substeps) noexcept;

// The first time t in (0, h] at which y(t) crosses `level` (y(t) − level changes sign or
// reaches 0 from a nonzero start), for the motion tether_step describes. Returns false
// when y stays on its starting side for the whole step. Requires sqrt(k/m)·h <= π so that
// y has at most one extremum in the step (tether_substeps guarantees it); the extremum is
// located and both halves are searched, so a graze that crosses and comes back is found.
// The starting side is the sign of y(0) − level; a start exactly at the level takes the
// side the motion leaves to (the sign of ẏ(0), else of ÿ(0)), so a contact that begins at
// its surface finds the moment it comes back out, not the moment it began.
// Accuracy: |t − t_true| <= 1e-9·h (Newton's method within a bracket, bisection fallback).
[[nodiscard]] bool tether_crossing(const SpringDamper& s, MassState x, double level, double h,
                                   double& t_cross) noexcept;

// The same for a caller that has the state at h already (at_h = tether_step(s, x, h)) and
// needs the state at the crossing (at_cross = tether_step(s, x, t_cross), set when it
// returns true): neither is evaluated again (each evaluation is an exp, a sine and a
// cosine in double; a piecewise step took about twelve per crossing).
[[nodiscard]] bool tether_crossing(const SpringDamper& s, MassState x, MassState at_h, double level, double h,
                                   double& t_cross, MassState& at_cross) noexcept;

}  // namespace feel::detail
