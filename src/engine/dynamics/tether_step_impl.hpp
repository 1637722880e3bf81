// The definitions of tether_step.hpp's templates (the formulas and why they are written
// this way are there). Included by tether_step.hpp only.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "float_exp.hpp"
#include "turn_trig.hpp"

namespace feel::detail {

namespace tether_step_impl {

// The functions the closed form needs, in the precision of its scalar. In float the sine
// and cosine are turn_trig.hpp's, of + and × only: the same bits on x86 and on the
// Cortex-M4F, and no libm sinf with its argument reduction for angles up to 10^38 in the
// board's flash. An angle is a float of some ulp, so beyond 2^22 turns it holds whole or
// half turns only; the fraction of a turn is taken exactly first (sin_turns wants |p| < 2^22).
// From 2^23 on a float is a whole number (of turns: the fraction is 0), and below it the
// whole turns fit an int32: no conversion to int64, whose routine on the Cortex-M4F
// (__aeabi_f2lz) computes in soft-float double.
inline float turns_of(float radians) noexcept {
    constexpr float kTurnsPerRadian = 0.159154943091895335769f;  // 1/2π
    const float p = radians * kTurnsPerRadian;
    if (std::fabs(p) < 0x1p22f) return p;
    if (!(std::fabs(p) < 0x1p23f)) return p == p ? 0.0f : p;  // whole turns, or NaN
    return p - static_cast<float>(static_cast<int32_t>(p));
}
inline float sin_of(float x) noexcept {
    const float p = turns_of(x);
    return p == p ? sin_turns(p) : p;
}
inline float cos_of(float x) noexcept {
    const float p = turns_of(x);
    return p == p ? cos_turns(p) : p;
}
inline double sin_of(double x) noexcept { return std::sin(x); }
inline double cos_of(double x) noexcept { return std::cos(x); }
// In float the engine's own (float_exp.hpp: the same bits on x86 and the M4, no libm).
template <typename T>
T exp_of(T x) noexcept {
    if constexpr (std::is_same_v<T, float>) return float_exp(x);
    else return std::exp(x);
}
template <typename T>
T expm1_of(T x) noexcept {
    if constexpr (std::is_same_v<T, float>) return float_expm1(x);
    else return std::expm1(x);
}

// Below this |Δ|·h², C and S come from their Taylor series: near critical damping the
// closed forms divide by √|Δ| → 0. Five terms leave an error below x⁶/12! ≈ 2e-21.
template <typename T>
inline constexpr T kSeriesLimit = T(1e-2);
// Below this ω0²·h² the spring is held at its starting force for the step: the velocity
// is then off by about ω0²h²/2 of itself (the spring's change over the step), which must be
// below the scalar's rounding, or a mass that often takes such short pieces (the remainder
// of a piece after an edge crossing) gains that much energy each time. The equilibrium
// f/k of a weak spring is far away, but the step adds (p − 1)·(y − f/k), whose rounding
// is that of the increment (f·h²/2m), not of f/k.
template <typename T>
inline constexpr T kFreeLimit = std::is_same_v<T, float> ? T(1e-14) : T(1e-12);
// Below this c·h/m, the free mass's integrals come from their series (expm1 would be exact,
// but (h − φ1)/a cancels: it loses 2/(c·h/m) ulps). The series go to (ch/m)⁸: their error
// is below 1e-12 of the sum at 0.25, where the cancellation beyond costs at most 8 ulps.
template <typename T>
inline constexpr T kFreeSeriesLimit = std::is_same_v<T, float> ? T(0.25) : T(1e-2);
// How closely tether_crossing closes its bracket, as a fraction of the step: 1e-9 in double;
// in float 2^-20, a few ulps of the step (its ulp is 2^-24 of it), where Newton still halves
// the bracket each step instead of stalling on rounding.
template <typename T>
inline constexpr T kCrossingTolerance = std::is_same_v<T, float> ? T(0x1p-20) : T(1e-9);

// Below this decay exponent (γh, or the slow mode's), a step adds increments to the state
// (below); beyond it e^{−γh} < 0.61 and the state is rebuilt whole, which keeps the relative
// precision of a motion that decays by orders of magnitude in one step.
template <typename T>
inline constexpr T kIncrementLimit = T(0.5);

// One step of the homogeneous oscillator z̈ + 2γż + ω0²z = 0:
//     z(h) = p·z0 + s·ż0,   ż(h) = q·ż0 − ω0²·s·z0
// with s = e^{−γh}·S(h), p = e^{−γh}·(C + γS), q = e^{−γh}·(C − γS). For a step that
// decays little (`increments`) the propagator holds p − 1 and q − 1 instead, formed without
// cancellation (from e^{−γh} − 1 = expm1 and C − 1), and the step adds increments to the
// state: its rounding is then that of the increment, not of the whole state. A state
// rebuilt whole from p·z0 carries an error of an ulp of itself per step, the same at every
// recurrence of a periodic motion: an undamped float mass that crosses an edge of its law
// twice a swing drifted by that each time (2.8e-7 an exact piece, 4.5e-4 of the energy
// over a minute, measured).
template <typename T>
struct Propagator {
    bool increments;  // p and q hold p − 1 and q − 1
    T p, s, q;
};

// cos θ − 1 without cancellation, given sin θ and cos θ.
template <typename T>
T cos_minus_1(T sine, T cosine) noexcept {
    return cosine >= 0 ? -(sine * sine) / (1 + cosine) : cosine - 1;
}

template <typename T>
Propagator<T> propagator(T gamma, T w2, T h) noexcept {
    const T delta = w2 - gamma * gamma;
    const T x = delta * h * h;
    if (std::fabs(x) < kSeriesLimit<T> || delta > 0) {
        T c, c_minus_1, s;  // C, C − 1 and S
        if (std::fabs(x) < kSeriesLimit<T>) {
            // C − 1 = Σ_{n≥1} (−x)ⁿ/(2n)!,  S/h = Σ (−x)ⁿ/(2n+1)!, nested.
            c_minus_1 = -x / 2 * (1 - x / 12 * (1 - x / 30 * (1 - x / 56 * (1 - x / 90))));
            c = 1 + c_minus_1;
            s = h * (1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72 * (1 - x / 110)))));
        } else {
            const T wd = std::sqrt(delta);
            const T sine = sin_of(wd * h);
            c = cos_of(wd * h);
            c_minus_1 = cos_minus_1(sine, c);
            s = sine / wd;
        }
        const T decay = gamma * h;
        if (decay < kIncrementLimit<T>) {
            // E·C − 1 = (E − 1)·C + (C − 1), E = e^{−γh}.
            const T e_minus_1 = expm1_of<T>(-decay);
            const T es = (1 + e_minus_1) * s;
            const T ec_minus_1 = e_minus_1 * c + c_minus_1;
            return {true, ec_minus_1 + gamma * es, es, ec_minus_1 - gamma * es};
        }
        const T e = exp_of<T>(-decay);
        const T es = e * s;
        const T ec = e * c;
        return {false, ec + gamma * es, es, ec - gamma * es};
    }
    // Overdamped: the two real modes decay at γ − β (slow) and γ + β (fast), β = √−Δ.
    // γ − β = ω0²/(γ + β) avoids the cancellation of two nearly equal numbers; fast − slow
    // = 2β, so p − 1 and q − 1 take the exponentials less 1 only.
    const T beta = std::sqrt(-delta);
    const T fast = gamma + beta;
    const T slow = w2 / fast;
    const T inv = 1 / (2 * beta);
    if (slow * h < kIncrementLimit<T>) {
        const T slow_minus_1 = expm1_of<T>(-slow * h);
        const T fast_minus_1 = expm1_of<T>(-fast * h);
        return {true, (fast * slow_minus_1 - slow * fast_minus_1) * inv, (slow_minus_1 - fast_minus_1) * inv,
                (fast * fast_minus_1 - slow * slow_minus_1) * inv};
    }
    const T e_slow = exp_of<T>(-slow * h);
    const T e_fast = exp_of<T>(-fast * h);
    return {false, (fast * e_slow - slow * e_fast) * inv, (e_slow - e_fast) * inv,
            (fast * e_fast - slow * e_slow) * inv};
}

// A free mass with damping and a constant force a_f = f/m: ÿ = −a·ẏ + a_f.
template <typename T>
BasicMassState<T> free_step(T a, T a_f, BasicMassState<T> x, T h) noexcept {
    // Without damping the series below is exactly φ1 = h, φ2 = h·h·0.5 and e = 1: the same
    // numbers without the exponential (Dynamic Inertia's mass coasting in its play).
    if (a == 0) return {x.position + x.velocity * h + a_f * (h * h * T(0.5)), x.velocity + a_f * h};
    const T ah = a * h;
    T phi1, phi2;  // φ1 = ∫₀ʰ e^{−at} dt, φ2 = ∫₀ʰ φ1(t) dt
    if (ah < kFreeSeriesLimit<T>) {
        // φ1 = h·Σ (−ah)ⁿ/(n+1)!,  φ2 = h²·Σ (−ah)ⁿ/(n+2)!, n = 0..8, nested from the last term.
        T sum1 = 1, sum2 = 1;  // φ1/h, and 2·φ2/h²
        for (int n = 8; n >= 1; --n) {
            sum1 = 1 - ah / static_cast<T>(n + 1) * sum1;
            sum2 = 1 - ah / static_cast<T>(n + 2) * sum2;
        }
        phi1 = h * sum1;
        phi2 = h * h * T(0.5) * sum2;
    }
    if (ah < kIncrementLimit<T>) {
        // The velocity by its increment (e^{−ah} − 1)·v, as the oscillator's.
        const T e_minus_1 = expm1_of<T>(-ah);
        if (!(ah < kFreeSeriesLimit<T>)) {
            phi1 = -e_minus_1 / a;
            phi2 = (h - phi1) / a;
        }
        return {x.position + (x.velocity * phi1 + a_f * phi2), x.velocity + (x.velocity * e_minus_1 + a_f * phi1)};
    }
    const T e = exp_of<T>(-ah);
    phi1 = (1 - e) / a;
    phi2 = (h - phi1) / a;
    return {x.position + (x.velocity * phi1 + a_f * phi2), x.velocity * e + a_f * phi1};
}

// ÿ(0): which way a motion starting at rest leaves.
template <typename T>
T initial_acceleration(const BasicSpringDamper<T>& s, BasicMassState<T> x) noexcept {
    return (s.force - s.stiffness * x.position - s.damping * x.velocity) / s.mass;
}

template <typename T>
T sign_of(T v) noexcept {
    return v > 0 ? T(1) : (v < 0 ? T(-1) : T(0));
}

// A function of t, its slope and its curvature there, and the motion's state at t it was
// read from. The curvature may be given as 0 (the search is then Newton's).
template <typename T>
struct Sample {
    T value, slope, curvature;
    BasicMassState<T> state;
};

// The step from a sample to the root of its Taylor parabola g + g'·d + g''·d²/2 nearest to
// it, d = −2g/(g' + sgn(g')·√(g'² − 2g·g'')), written so that nothing cancels (the root
// near 0 of a parabola whose other root is far); where the parabola has no real root,
// Newton's −2g/(2g') = −g/g' (the same quotient: doubling is exact). The closed form gives
// the curvature for free (the state's acceleration), and it is what a mass's motion over a
// short piece mostly is: a free mass without drag is a parabola exactly, and on a tether
// (ω·h ≤ 1) the model's error is of the jerk's order, so that the search converges with
// the cube of its error where Newton's squared it. A curvature of 0 is Newton's step. A
// slope of 0 may give an infinite or NaN step, which the search's bracket turns into a
// bisection.
template <typename T>
[[gnu::always_inline]] inline T parabola_step(const Sample<T>& at) noexcept {
    const T discriminant = at.slope * at.slope - 2 * at.value * at.curvature;
    const T root = discriminant >= 0 ? std::sqrt(discriminant) : std::fabs(at.slope);
    return -2 * at.value / (at.slope <= 0 ? at.slope - root : at.slope + root);
}

// The earliest t in (lo, hi] with g(t) <= 0, given g(lo) > 0 >= g(hi) (their samples
// given: the caller has read both already) and a single sign change between them, to
// within `tolerance`: steps to the root of each sample's parabola (parabola_step: g
// returns its slope and curvature too), kept inside the bracket and aimed half a tolerance
// past the root, so that the bracket closes from both sides; a step that leaves the
// bracket bisects instead. The bracket also closes on a sample at hi, descending there,
// whose own parabola puts the root within the tolerance below it (the model's error over
// so short a step is of the order of the tolerance cubed times the jerk): the search then
// ends without the evaluation on the other side that would only confirm it. Converges in
// one to three evaluations where Newton's steps took four and bisection 30; at most 64.
// at_hi comes back as the sample at the t returned (the state there, which the caller
// needs: no evaluation is repeated).
template <typename T, typename G>
T first_nonpositive(const G& g, T lo, const Sample<T>& at_lo, T hi, Sample<T>& at_hi, T tolerance) noexcept {
    Sample<T> at = at_lo;
    T t = lo;
    for (int i = 0; i < 64 && hi - lo > tolerance; ++i) {
        T next = t + parabola_step(at);
        if (at.value <= 0 && at.slope < 0 && next >= hi - tolerance) break;  // closed on the model's root
        next += at.value > 0 ? tolerance / 2 : -tolerance / 2;
        if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;
        t = next;
        at = g(t);
        if (at.value > 0) {
            lo = t;
        } else {
            hi = t;
            at_hi = at;
        }
    }
    return hi;
}

}  // namespace tether_step_impl

template <typename T>
BasicMassState<T> tether_step(const BasicSpringDamper<T>& s, BasicMassState<T> x, StepScalar<T> h) noexcept {
    using namespace tether_step_impl;
    if (!(h > 0)) return x;
    const T m = s.mass;
    const T w2 = s.stiffness / m;
    if (!(w2 * h * h >= kFreeLimit<T>)) {
        // No spring worth the name: the spring's force is held at its start value.
        return free_step<T>(s.damping / m, (s.force - s.stiffness * x.position) / m, x, h);
    }
    const T gamma = s.damping / (2 * m);
    const T equilibrium = s.force / s.stiffness;
    const T z0 = x.position - equilibrium;
    const Propagator<T> k = propagator<T>(gamma, w2, h);
    if (k.increments) {
        return {x.position + (k.p * z0 + k.s * x.velocity), x.velocity + (k.q * x.velocity - w2 * k.s * z0)};
    }
    return {equilibrium + (k.p * z0 + k.s * x.velocity), k.q * x.velocity - w2 * k.s * z0};
}

template <typename T>
T tether_omega(const BasicSpringDamper<T>& s) noexcept {
    return std::sqrt(s.stiffness / s.mass);
}

template <typename T>
int32_t tether_substeps(const BasicSpringDamper<T>& s, StepScalar<T> h, int32_t max_substeps) noexcept {
    const T wh = tether_omega(s) * h;
    if (!(wh > 1)) return 1;  // also NaN: one exact step
    if (!(wh < static_cast<T>(max_substeps))) return max_substeps < 1 ? 1 : max_substeps;
    // ⌈wh⌉ by a conversion (ceil is a library call on the Cortex-M4F): wh < max_substeps.
    int32_t n = static_cast<int32_t>(wh);
    if (static_cast<T>(n) < wh) ++n;
    return n;
}

template <typename T>
bool tether_crossing(const BasicSpringDamper<T>& s, BasicMassState<T> x, StepScalar<T> level, StepScalar<T> h,
                     T& t_cross) noexcept {
    if (!(h > 0)) return false;
    BasicMassState<T> at_cross;
    return tether_crossing<T>(s, x, tether_step<T>(s, x, h), level, h, t_cross, at_cross);
}

template <typename T>
bool tether_crossing(const BasicSpringDamper<T>& s, BasicMassState<T> x, BasicMassState<T> at_h,
                     StepScalar<T> level, StepScalar<T> h, T& t_cross, BasicMassState<T>& at_cross) noexcept {
    using namespace tether_step_impl;
    using State = BasicMassState<T>;
    if (!(h > 0)) return false;
    // side: +1 when the motion starts (or, from the level, leaves) above the level.
    T side = sign_of(x.position - level);
    if (side == 0) side = sign_of(x.velocity);
    if (side == 0) side = sign_of(initial_acceleration(s, x));
    if (side == 0) return false;  // at rest at an equilibrium on the level: it stays there
    // The state at t; at h it is known already.
    auto state_at = [&](T t) { return t == h ? at_h : tether_step<T>(s, x, t); };
    auto above_from = [&](State m) {
        return Sample<T>{side * (m.position - level), side * m.velocity, side * initial_acceleration(s, m), m};
    };
    auto above = [&](T t) { return above_from(state_at(t)); };
    const T tolerance = kCrossingTolerance<T> * h;

    // Which way the motion starts, seen from its side: +1 away from the level, −1 toward it.
    T direction = sign_of(side * x.velocity);
    if (direction == 0) direction = sign_of(side * initial_acceleration(s, x));
    if (direction == 0) return false;  // at rest at an equilibrium: it stays on its side
    // The one extremum the step may hold: where the velocity turns from its starting sign.
    auto onward_from = [&](State m) {
        return Sample<T>{direction * side * m.velocity, direction * side * initial_acceleration(s, m), T(0), m};
    };
    auto onward = [&](T t) { return onward_from(state_at(t)); };
    Sample<T> extremum = onward_from(at_h);
    const T t_extremum =
        extremum.value <= 0 ? first_nonpositive<T>(onward, T(0), onward_from(x), h, extremum, tolerance) : T(-1);

    if (direction > 0) {
        // Away first, then (after the extremum, if any) back: only the way back can cross.
        if (t_extremum < 0) return false;
        Sample<T> end = above_from(at_h);
        if (end.value > 0) return false;
        t_cross = first_nonpositive<T>(above, t_extremum, above_from(extremum.state), h, end, tolerance);
        at_cross = end.state;
        return true;
    }
    // Toward the level, monotone until the extremum (or the end of the step): the crossing,
    // if any, is before it; after it the motion heads away again.
    const T stop = t_extremum < 0 ? h : t_extremum;
    Sample<T> end = above_from(t_extremum < 0 ? at_h : extremum.state);
    if (end.value > 0) return false;
    t_cross = first_nonpositive<T>(above, T(0), above_from(x), stop, end, tolerance);
    at_cross = end.state;
    return true;
}

}  // namespace feel::detail
