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
// Precision. The control laws use it in float (SpringDamperF: issue 14, a Cortex-M4F has a
// single-precision FPU only; docs/dynamics.md, "Precision", says what float costs and why
// it is enough), and so does the paddle's contact (paddle_contact.hpp); the same template in
// double is the tests' reference (no engine code instantiates it). In float the sine and
// cosine are turn_trig.hpp's (the same bits on every platform), the exponentials libm's
// float ones; in double, libm's.
//
// Real-time safe: no allocation, no exceptions, no state.
#pragma once

#include <cstdint>
#include <type_traits>

namespace feel::detail {

template <typename T>
struct BasicSpringDamper {
    T mass = 1;       // > 0 (callers' units: the dynamics use force units per (position unit/s²))
    T stiffness = 0;  // >= 0, force per unit of y; 0 is a free mass
    T damping = 0;    // >= 0, force per unit of ẏ
    T force = 0;      // constant force on the mass over the step, any sign
};

template <typename T>
struct BasicMassState {
    T position = 0;  // y
    T velocity = 0;  // ẏ, per second
};

using SpringDamper = BasicSpringDamper<double>;
using MassState = BasicMassState<double>;
using SpringDamperF = BasicSpringDamper<float>;  // the control laws' and the paddle's
using MassStateF = BasicMassState<float>;

// The scalar of a step's time and level: the state's own (not deduced from the argument, so
// that a literal or a double time with a float law converts instead of failing to match).
template <typename T>
using StepScalar = std::type_identity_t<T>;

// The state after h seconds (h >= 0), exact for constant parameters. Finite inputs give
// finite outputs (an undamped oscillator stays bounded; damping only shrinks the motion).
template <typename T>
[[nodiscard]] BasicMassState<T> tether_step(const BasicSpringDamper<T>& s, BasicMassState<T> x,
                                            StepScalar<T> h) noexcept;

// ω0 = sqrt(k/m), the undamped natural frequency, rad/s. Damping needs no substeps (the step
// is exact however heavily damped); only the oscillation decides how short a piece is.
template <typename T>
[[nodiscard]] T tether_omega(const BasicSpringDamper<T>& s) noexcept;

// Pieces to cut a step of h seconds into so that each has ω0·h_piece <= 1: the smallest n
// with ω0·h/n <= 1, at least 1, at most max_substeps (beyond it the pieces are longer but
// each stays exact; only tether_crossing's guarantee is lost).
template <typename T>
[[nodiscard]] int32_t tether_substeps(const BasicSpringDamper<T>& s, StepScalar<T> h, int32_t max_substeps) noexcept;

// The first time t in (0, h] at which y(t) crosses `level` (y(t) − level changes sign or
// reaches 0 from a nonzero start), for the motion tether_step describes. Returns false
// when y stays on its starting side for the whole step. Requires sqrt(k/m)·h <= π so that
// y has at most one extremum in the step (tether_substeps guarantees it); the extremum is
// located and both halves are searched, so a graze that crosses and comes back is found.
// The starting side is the sign of y(0) − level; a start exactly at the level takes the
// side the motion leaves to (the sign of ẏ(0), else of ÿ(0)), so a contact that begins at
// its surface finds the moment it comes back out, not the moment it began.
// Accuracy: steps to the root of the motion's Taylor parabola within a bracket (bisection
// fallback) close the bracket to 1e-9·h in double, 2^-20·h (1e-6) in float, plus what rounding the motion's evaluation
// does to the root (about eps·amplitude/|slope|: a graze's crossing is less sharp).
template <typename T>
[[nodiscard]] bool tether_crossing(const BasicSpringDamper<T>& s, BasicMassState<T> x, StepScalar<T> level,
                                   StepScalar<T> h, T& t_cross) noexcept;

// The same for a caller that has the state at h already (at_h = tether_step(s, x, h)) and
// needs the state at the crossing (at_cross = tether_step(s, x, t_cross), set when it
// returns true): neither is evaluated again (each evaluation is an exp, a sine and a
// cosine; a piecewise step took about twelve per crossing).
template <typename T>
[[nodiscard]] bool tether_crossing(const BasicSpringDamper<T>& s, BasicMassState<T> x, BasicMassState<T> at_h,
                                   StepScalar<T> level, StepScalar<T> h, T& t_cross,
                                   BasicMassState<T>& at_cross) noexcept;

}  // namespace feel::detail

// The definitions: a template, so that each precision is compiled where it is used. The
// float one, the engine's, once in tether_step.cpp (declared extern here).
#include "dynamics/tether_step_impl.hpp"

namespace feel::detail {

extern template MassStateF tether_step<float>(const SpringDamperF&, MassStateF, float) noexcept;
extern template float tether_omega<float>(const SpringDamperF&) noexcept;
extern template int32_t tether_substeps<float>(const SpringDamperF&, float, int32_t) noexcept;
extern template bool tether_crossing<float>(const SpringDamperF&, MassStateF, float, float, float&) noexcept;
extern template bool tether_crossing<float>(const SpringDamperF&, MassStateF, MassStateF, float, float, float&,
                                            MassStateF&) noexcept;

}  // namespace feel::detail
