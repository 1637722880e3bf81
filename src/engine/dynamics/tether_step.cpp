// The exact spring-damper step (tether_step.hpp has the formulas and why they are written
// this way).
#include "dynamics/tether_step.hpp"

#include <cmath>

namespace feel::detail {

namespace {

// Below this |Δ|·h², C and S come from their Taylor series: near critical damping the
// closed forms divide by √|Δ| → 0. Five terms leave an error below x⁶/12! ≈ 2e-21.
constexpr double kSeriesLimit = 1e-2;
// Below this ω0²·h² the spring is held at its starting force for the step (error of
// relative order ω0²h², 1e-12): the equilibrium f/k of a vanishing spring is too far away
// to subtract accurately.
constexpr double kFreeLimit = 1e-12;
// Below this c·h/m, the free mass's exponentials come from their series (expm1 would be
// exact, but (h − φ1)/a would cancel).
constexpr double kFreeSeriesLimit = 1e-2;

// One step of the homogeneous oscillator z̈ + 2γż + ω0²z = 0:
//     z(h) = p·z0 + s·ż0,   ż(h) = q·ż0 − ω0²·s·z0
// with s = e^{−γh}·S(h), p = e^{−γh}·(C + γS), q = e^{−γh}·(C − γS).
struct Propagator {
    double p, s, q;
};

Propagator propagator(double gamma, double w2, double h) noexcept {
    const double delta = w2 - gamma * gamma;
    const double x = delta * h * h;
    if (std::fabs(x) < kSeriesLimit) {
        // C = Σ (−x)ⁿ/(2n)!,  S/h = Σ (−x)ⁿ/(2n+1)!, nested.
        const double c = 1 - x / 2 * (1 - x / 12 * (1 - x / 30 * (1 - x / 56 * (1 - x / 90))));
        const double sh = 1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72 * (1 - x / 110))));
        const double e = std::exp(-gamma * h);
        const double s = e * sh * h;
        const double ec = e * c;
        return {ec + gamma * s, s, ec - gamma * s};
    }
    if (delta > 0) {
        const double wd = std::sqrt(delta);
        const double e = std::exp(-gamma * h);
        const double s = e * std::sin(wd * h) / wd;
        const double ec = e * std::cos(wd * h);
        return {ec + gamma * s, s, ec - gamma * s};
    }
    // Overdamped: the two real modes decay at γ − β (slow) and γ + β (fast), β = √−Δ.
    // γ − β = ω0²/(γ + β) avoids the cancellation of two nearly equal numbers.
    const double beta = std::sqrt(-delta);
    const double fast = gamma + beta;
    const double slow = w2 / fast;
    const double e_slow = std::exp(-slow * h);
    const double e_fast = std::exp(-fast * h);
    const double inv = 1 / (2 * beta);
    return {(fast * e_slow - slow * e_fast) * inv, (e_slow - e_fast) * inv,
            (fast * e_fast - slow * e_slow) * inv};
}

// A free mass with damping and a constant force a_f = f/m: ÿ = −a·ẏ + a_f.
MassState free_step(double a, double a_f, MassState x, double h) noexcept {
    // Without damping the series below is exactly φ1 = h, φ2 = h·h·0.5 and e = 1: the same
    // numbers without the exponential (Dynamic Inertia's mass coasting in its play).
    if (a == 0) return {x.position + x.velocity * h + a_f * (h * h * 0.5), x.velocity + a_f * h};
    const double ah = a * h;
    double phi1, phi2, e;  // φ1 = ∫₀ʰ e^{−at} dt, φ2 = ∫₀ʰ φ1(t) dt, e = e^{−ah}
    if (ah < kFreeSeriesLimit) {
        phi1 = h * (1 - ah / 2 * (1 - ah / 3 * (1 - ah / 4 * (1 - ah / 5 * (1 - ah / 6)))));
        phi2 = h * h * (0.5 - ah / 6 * (1 - ah / 4 * (1 - ah / 5 * (1 - ah / 6 * (1 - ah / 7)))));
        e = std::exp(-ah);
    } else {
        phi1 = -std::expm1(-ah) / a;
        phi2 = (h - phi1) / a;
        e = std::exp(-ah);
    }
    return {x.position + x.velocity * phi1 + a_f * phi2, x.velocity * e + a_f * phi1};
}

// ÿ(0): which way a motion starting at rest leaves.
double initial_acceleration(const SpringDamper& s, MassState x) noexcept {
    return (s.force - s.stiffness * x.position - s.damping * x.velocity) / s.mass;
}

double sign_of(double v) noexcept { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

// A function of t and its slope there, and the motion's state at t it was read from.
struct Sample {
    double value, slope;
    MassState state;
};

// The earliest t in (lo, hi] with g(t) <= 0, given g(lo) > 0 >= g(hi) (their samples
// given: the caller has read both already) and a single sign change between them, to
// within `tolerance`: Newton's method on the closed form (g returns its slope too), kept
// inside the bracket and aimed half a tolerance past the root so that the bracket closes
// from both sides; a step that leaves the bracket bisects instead. Converges in a handful
// of evaluations where bisection takes 30; at most 64. at_hi comes back as the sample at
// the t returned (the state there, which the caller needs: no evaluation is repeated).
template <typename G>
double first_nonpositive(const G& g, double lo, const Sample& at_lo, double hi, Sample& at_hi,
                         double tolerance) noexcept {
    Sample at = at_lo;
    double t = lo;
    for (int i = 0; i < 64 && hi - lo > tolerance; ++i) {
        double next = at.slope != 0 ? t - at.value / at.slope : lo + (hi - lo) / 2;
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

}  // namespace

MassState tether_step(const SpringDamper& s, MassState x, double h) noexcept {
    if (!(h > 0)) return x;
    const double m = s.mass;
    const double w2 = s.stiffness / m;
    if (!(w2 * h * h >= kFreeLimit)) {
        // No spring worth the name: the spring's force is held at its start value.
        return free_step(s.damping / m, (s.force - s.stiffness * x.position) / m, x, h);
    }
    const double gamma = s.damping / (2 * m);
    const double equilibrium = s.force / s.stiffness;
    const double z0 = x.position - equilibrium;
    const Propagator k = propagator(gamma, w2, h);
    return {equilibrium + k.p * z0 + k.s * x.velocity, k.q * x.velocity - w2 * k.s * z0};
}

double tether_omega(const SpringDamper& s) noexcept { return std::sqrt(s.stiffness / s.mass); }

int32_t tether_substeps(const SpringDamper& s, double h, int32_t max_substeps) noexcept {
    const double wh = tether_omega(s) * h;
    if (!(wh > 1)) return 1;  // also NaN: one exact step
    const double n = std::ceil(wh);
    if (!(n < static_cast<double>(max_substeps))) return max_substeps < 1 ? 1 : max_substeps;
    return static_cast<int32_t>(n);
}

bool tether_crossing(const SpringDamper& s, MassState x, double level, double h,
                     double& t_cross) noexcept {
    if (!(h > 0)) return false;
    MassState at_cross;
    return tether_crossing(s, x, tether_step(s, x, h), level, h, t_cross, at_cross);
}

bool tether_crossing(const SpringDamper& s, MassState x, MassState at_h, double level, double h, double& t_cross,
                     MassState& at_cross) noexcept {
    if (!(h > 0)) return false;
    // side: +1 when the motion starts (or, from the level, leaves) above the level.
    double side = sign_of(x.position - level);
    if (side == 0) side = sign_of(x.velocity);
    if (side == 0) side = sign_of(initial_acceleration(s, x));
    if (side == 0) return false;  // at rest at an equilibrium on the level: it stays there
    // The state at t; at h it is known already.
    auto state_at = [&](double t) { return t == h ? at_h : tether_step(s, x, t); };
    auto above_from = [&](MassState m) { return Sample{side * (m.position - level), side * m.velocity, m}; };
    auto above = [&](double t) { return above_from(state_at(t)); };
    const double tolerance = 1e-9 * h;

    // Which way the motion starts, seen from its side: +1 away from the level, −1 toward it.
    double direction = sign_of(side * x.velocity);
    if (direction == 0) direction = sign_of(side * initial_acceleration(s, x));
    if (direction == 0) return false;  // at rest at an equilibrium: it stays on its side
    // The one extremum the step may hold: where the velocity turns from its starting sign.
    auto onward_from = [&](MassState m) {
        return Sample{direction * side * m.velocity, direction * side * initial_acceleration(s, m), m};
    };
    auto onward = [&](double t) { return onward_from(state_at(t)); };
    Sample extremum = onward_from(at_h);
    const double t_extremum =
        extremum.value <= 0 ? first_nonpositive(onward, 0.0, onward_from(x), h, extremum, tolerance) : -1.0;

    if (direction > 0) {
        // Away first, then (after the extremum, if any) back: only the way back can cross.
        if (t_extremum < 0) return false;
        Sample end = above_from(at_h);
        if (end.value > 0) return false;
        t_cross = first_nonpositive(above, t_extremum, above_from(extremum.state), h, end, tolerance);
        at_cross = end.state;
        return true;
    }
    // Toward the level, monotone until the extremum (or the end of the step): the crossing,
    // if any, is before it; after it the motion heads away again.
    const double stop = t_extremum < 0 ? h : t_extremum;
    Sample end = above_from(t_extremum < 0 ? at_h : extremum.state);
    if (end.value > 0) return false;
    t_cross = first_nonpositive(above, 0.0, above_from(x), stop, end, tolerance);
    at_cross = end.state;
    return true;
}

}  // namespace feel::detail
