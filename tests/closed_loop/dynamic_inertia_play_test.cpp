// Dynamic Inertia with play on smooth motions (issue 16 §2, §5.6, §8.4): a kinematic hand
// moves the handle along sines and a circle, and the force is compared with what a mass in
// a gap does, worked out here from the motion, the play and the documented tether alone.
//
// §5.6: "Play defines a gap of free motion between the stick and the mass". §8.4 maps
// Inertia → Mass and Play → Length, the half-width of the control law's free play: the mass
// moves freely within ±Play of the handle and meets the tether (stiffness k, damping b,
// docs/dynamics.md) at either side. On a motion whose acceleration a(t) changes sign
// smoothly, the mass in the handle's frame (s = x_mass − x_handle) obeys s̈ = −a in the gap,
// so, with the rigid-contact approximation (the tether's sag M·a/k is a few counts):
//
//   * While the handle accelerates one way the mass rests against the side −a presses it
//     to, and the handle feels −M·a: the same as without play.
//   * At a zero t0 of a (the handle passing its centre at full speed on a sine) the mass
//     leaves that side with no relative velocity and crosses the gap 2·Play wide. For
//     a = −A·ω²·sin(ω(t − t0)): s = ∓Play ± A·(ωτ − sin ωτ), so it lands after the τ that
//     solves ωτ − sin ωτ = 2·Play/A (free_flight_phase), closing at v = A·ω·(1 − cos ωτ).
//     Throughout the flight the force is 0.
//   * The landing is a damped contact from speed v: its force k·y + b·ẏ starts at b·v and,
//     at a damping ratio of 0.7 (> 0.5), never exceeds that start; by superposition with
//     the press of −M·a the force in the window stays below b·v + M·max|a| (the bound each
//     window is checked against, with the allowance below). Its free part decays as
//     sqrt(k·M)·v·e^(−ζ·ω_c·t)/sqrt(1 − ζ²), ω_c = sqrt(k/M); the window ends when that
//     envelope is 10% of the peak inertial force.
//
// So each zero of a opens a window [t0, t0 + τ + settle], shifted by the lag the force
// shows; outside the windows the force must be −M·a within the bounds of the no-play
// case (35% of the peak inertial force at the best lag up to 30 ms, tick-to-tick jitter
// below 5% of it), and in each window the mass must really cross: the force is 0 through
// the flight, and the first force of the new sign comes τ after t0, up to the 30 ms lag.
//
// The engine drives the mass by its acceleration estimate, a fit to quantized samples that
// is within about 15% of the true acceleration on these motions (the no-play tests): the
// landing's speed and the press inherit that error, so the impact bound is allowed 25%.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "feel/sim/device_profile.hpp"
#include "friction_loop.hpp"

namespace feel::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMaxLag_s = 0.030;        // the allowance
constexpr double kDampingRatio = 0.7;      // docs/dynamics.md: Inertia's tether, ζ 0.7
constexpr double kEstimateAllowance = 1.25;  // the impact bound's margin (file comment)
constexpr double kSettleFraction = 0.1;    // the window ends at this fraction of the peak
// A landing is a force of the new sign above this fraction of the peak: the tether's damper
// may pull back briefly (b·ṡ) as the mass lifts off the side it leaves.
constexpr double kLandingFloor = 0.05;
// The tether is slack when the force is within this fraction of the peak of 0: exactly 0
// (a tick spent wholly in the play gives no tether impulse, tether_tick.cpp).
constexpr double kSlack = 0.0;
// The drive turns when the engine's acceleration estimate changes sign, which lags a(t):
// up to 49 ms at 0.5 Hz (the estimate's fit window; without play the force's zero
// crossings lag as much, docs/dynamics.md).
constexpr double kMaxTurnLag_s = 0.060;
// The flight time's tolerance: τ grows as the cube root of gap/A for a narrow gap and
// about as (gap/A)^0.36·... for the widest tested; the estimate's 15% amplitude error moves
// it by at most 6%, allowed twice.
constexpr double kFlightTolerance = 0.12;

// ωτ of the free flight across a gap of `gap` units: the root of x − sin x = gap/A in
// (0, π], by bisection (x − sin x increases).
double free_flight_phase(double amplitude, double gap) {
    const double target = gap / amplitude;
    double lo = 0, hi = kPi;
    for (int i = 0; i < 100; ++i) {
        const double mid = (lo + hi) / 2;
        (mid - std::sin(mid) < target ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// The mass, its tether and the motion of one axis: a(t) = −A·ω²·sin(ω·t + phase).
struct GapAxis {
    double mass = 0, k = 0, b = 0, play = 0;
    double amplitude = 0, w = 0, phase = 0;

    [[nodiscard]] double acceleration(double t) const { return -amplitude * w * w * std::sin(w * t + phase); }
    [[nodiscard]] double peak() const { return mass * amplitude * w * w; }
    [[nodiscard]] double flight_s() const { return free_flight_phase(amplitude, 2 * play) / w; }
    [[nodiscard]] double closing_speed() const { return amplitude * w * (1 - std::cos(w * flight_s())); }
    [[nodiscard]] double impact_bound() const { return kEstimateAllowance * (b * closing_speed() + peak()); }
    // From the landing until the contact's free ringing is kSettleFraction of the peak.
    [[nodiscard]] double settle_s() const {
        const double wc = std::sqrt(k / mass);
        const double envelope = std::sqrt(k * mass) * closing_speed() / std::sqrt(1 - kDampingRatio * kDampingRatio);
        return std::max(0.0, std::log(envelope / (kSettleFraction * peak())) / (kDampingRatio * wc));
    }
    // The zeros of a after `from` and before `to`: ω·t + phase = n·π.
    [[nodiscard]] std::vector<double> sign_changes(double from, double to) const {
        std::vector<double> zeros;
        for (int n = 0;; ++n) {
            const double t = (n * kPi - phase) / w;
            if (t > to) break;
            if (t >= from) zeros.push_back(t);
        }
        return zeros;
    }
};

// One sign change of a, as the trace shows it.
struct Crossing {
    double t0 = 0;       // the zero of a(t)
    double turn = -1;    // when the force passes 0 from the old side: the drive's turn
    double lift = -1;    // the first slack tick after it (|F| ≤ kSlack·peak)
    double landing = -1; // the first force of the new sign above kLandingFloor·peak
    bool slack_in_flight = true;  // every tick from lift to landing slack
    // The window the comparison with −M·a leaves out: from the turn to the landing's
    // contact settled (turn + τ + settle), two ticks wider each side (the tick the force
    // is held over, and the one before). A turn past the trace's end: from t0 on.
    double from = 0, to = 0;
};

std::vector<Crossing> crossings(const std::vector<LoopRow>& rows, const GapAxis& g, int axis, double tick) {
    std::vector<Crossing> out;
    const double end = rows.back().t_s;
    const double window = g.flight_s() + g.settle_s();
    for (double t0 : g.sign_changes(0.0, end)) {
        Crossing c;
        c.t0 = t0;
        // The side −a presses the mass to after t0; the force had the other sign before.
        const double after = -g.acceleration(t0 + 0.25 * kPi / g.w) > 0 ? 1.0 : -1.0;
        for (const LoopRow& r : rows) {
            if (r.t_s < t0) continue;
            const double f = r.force[axis] * after;
            if (c.turn < 0) {
                if (f >= 0) c.turn = r.t_s;
                continue;
            }
            if (c.lift < 0) {
                if (std::fabs(f) <= kSlack * g.peak()) c.lift = r.t_s;
                continue;
            }
            if (f > kLandingFloor * g.peak()) {
                c.landing = r.t_s;
                break;
            }
            c.slack_in_flight = c.slack_in_flight && std::fabs(f) <= kSlack * g.peak();
        }
        c.from = c.turn >= 0 ? c.turn - 2 * tick : t0;
        c.to = c.turn >= 0 ? c.turn + window + 2 * tick : 1e300;
        out.push_back(c);
    }
    return out;
}

bool inside(const std::vector<Crossing>& cs, double t) {
    for (const Crossing& c : cs) {
        if (t >= c.from && t <= c.to) return true;
    }
    return false;
}

struct PlayFit {
    double error = 1e300;  // the largest |F + M·a(t − lag)| outside the windows
    double lag_s = 0;
    double jitter = 0;     // the largest |ΔF − Δ(−M·a)| between ticks both outside them
    double impact = 0;     // the largest |F| inside them
    double outside_s = 0;  // the time the comparison covers
};

PlayFit fit(const std::vector<LoopRow>& rows, const GapAxis& g, const std::vector<Crossing>& cs, int axis,
            double settle) {
    PlayFit best;
    for (double lag = 0; lag <= kMaxLag_s + 1e-9; lag += 0.0005) {
        double error = 0;
        for (const LoopRow& r : rows) {
            if (r.t_s < settle || inside(cs, r.t_s)) continue;
            error = std::max(error, std::fabs(r.force[axis] + g.mass * g.acceleration(r.t_s - lag)));
        }
        if (error < best.error) {
            best.error = error;
            best.lag_s = lag;
        }
    }
    for (size_t i = 1; i < rows.size(); ++i) {
        const double t0 = rows[i - 1].t_s, t1 = rows[i].t_s;
        if (t0 < settle) continue;
        if (inside(cs, t1)) {
            best.impact = std::max(best.impact, std::fabs(rows[i].force[axis]));
            continue;
        }
        if (inside(cs, t0)) continue;
        best.outside_s += t1 - t0;
        const double expected = -g.mass * (g.acceleration(t1 - best.lag_s) - g.acceleration(t0 - best.lag_s));
        best.jitter = std::max(best.jitter, std::fabs(rows[i].force[axis] - rows[i - 1].force[axis] - expected));
    }
    return best;
}

// Each crossing after `settle` that the trace holds whole: the drive turns within
// kMaxTurnLag of t0; the mass lifts off about the tether's time constant b/k after the
// turn (beyond the edge the tether still holds it: with the load f falling through 0 at
// a rate ḟ, the quasi-static stretch f/k − (b/k²)·ḟ reaches the edge b/k after f does;
// half again is allowed, the estimate's slope not being constant near its zero); it
// flies with the force at 0, and lands the analytic flight time τ after the turn
// (the sag it leaves from is a few counts, so its flight is the rigid one), within
// kFlightTolerance·τ and three ticks.
void expect_the_mass_crosses(const std::vector<Crossing>& cs, const GapAxis& g, double tick, double settle,
                             double end) {
    const double tau = g.flight_s();
    int checked = 0;
    for (const Crossing& c : cs) {
        if (c.t0 < settle || c.t0 + kMaxTurnLag_s + tau + g.settle_s() > end) continue;
        SCOPED_TRACE("t0 " + std::to_string(c.t0) + " s, flight " + std::to_string(tau * 1e3) + " ms");
        ASSERT_GE(c.turn, c.t0) << "the force never turned";
        EXPECT_LE(c.turn - c.t0, kMaxTurnLag_s);
        ASSERT_GE(c.lift, 0) << "the mass never left the side";
        EXPECT_LE(c.lift - c.turn, 1.5 * g.b / g.k + 2 * tick);
        ASSERT_GE(c.landing, 0) << "no landing on the other side";
        EXPECT_TRUE(c.slack_in_flight) << "the force is 0 while the mass flies";
        EXPECT_NEAR(c.landing - c.turn, tau, kFlightTolerance * tau + 3 * tick);
        ++checked;
    }
    EXPECT_GE(checked, 1);
}

GapAxis gap_axis(const EngineConfig& c, int32_t inertia, int32_t play, double amplitude, double hz, double phase) {
    GapAxis g;
    g.mass = inertia / 10000.0 * c.dynamic_mass_ref;  // §8.4: Inertia → Mass
    g.k = c.dynamic_stiffness_ref;                    // feel's KPos = KNeg = 10000
    g.b = 2 * kDampingRatio * std::sqrt(g.k * g.mass);
    g.play = play;                                    // §8.4: Play → Length
    g.amplitude = amplitude;
    g.w = 2 * kPi * hz;
    g.phase = phase;
    return g;
}

void expect_a_mass_in_a_gap(const std::vector<LoopRow>& rows, const GapAxis& g, int axis, double rate,
                            double settle) {
    ASSERT_LE(g.peak() / g.k, 0.2 * 2 * g.play) << "the case is outside the regime: the sag is not small next to the gap";
    const double tick = 1.0 / rate;
    const std::vector<Crossing> cs = crossings(rows, g, axis, tick);
    const PlayFit f = fit(rows, g, cs, axis, settle);
    EXPECT_LE(f.error, 0.35 * g.peak()) << "lag " << f.lag_s * 1e3 << " ms";
    EXPECT_LE(f.jitter, 0.05 * g.peak());
    EXPECT_LE(f.impact, g.impact_bound()) << "closing speed " << g.closing_speed();
    EXPECT_GT(f.outside_s, 0.2 * (rows.back().t_s - settle)) << "the windows leave too little to compare";
    expect_the_mass_crosses(cs, g, tick, settle, rows.back().t_s);
}

struct Case {
    double amplitude, hz;
    int32_t inertia, play;
};

std::string motion_of(const Case& c) {
    return "sine:x:" + std::to_string(static_cast<int>(c.amplitude)) + ":" + std::to_string(c.hz);
}

// The sines of the no-play tests (0.5 to 5 Hz), each with inertias and plays in the regime
// of a mass in a gap: the sag stays under a fifth of the gap and the landing settles well
// within the half period. At 5 Hz that takes a light mass: at inertia 3000 and more the
// joystick's tether (10.7 Hz at 10000, 19.5 Hz at 3000) sags by more than any play whose
// landing settles before the next one.
constexpr Case kCases[] = {
    {2000, 1, 10000, 100}, {2000, 1, 10000, 500}, {2000, 1, 3000, 100}, {4000, 0.5, 10000, 200},
    {4000, 0.5, 3000, 200}, {1000, 2, 10000, 100}, {1000, 2, 3000, 50}, {500, 5, 1000, 30},
};

TEST(DynamicInertiaPlayClosedLoop, OnSinesTheMassRestsOnASideAndCrossesWhenTheAccelerationTurns) {
    const EngineConfig config = sim::engine_config_for(*sim::find_device_profile("joystick"));
    for (double rate : {500.0, 1000.0, 10000.0}) {
        for (const Case& c : kCases) {
            SCOPED_TRACE(std::to_string(rate) + " Hz, inertia " + std::to_string(c.inertia) + ", play " +
                         std::to_string(c.play) + ", " + motion_of(c));
            const auto rows = run_loop("joystick", sim::Grip::kinematic, motion_of(c),
                                       {dynamic_inertia_on({Axis::x}, c.inertia, c.play)}, 2.0 / c.hz + 0.5,
                                       rate);
            expect_a_mass_in_a_gap(rows, gap_axis(config, c.inertia, c.play, c.amplitude, c.hz, 0.0), 0, rate, 0.5);
        }
    }
}

TEST(DynamicInertiaPlayClosedLoop, OnACircleEachAxisIsAMassInItsGap) {
    // The control law is per axis, so the play is ±Play on each: on a circle x = A·cos,
    // y = A·sin, each axis is a sine, x a quarter period ahead.
    const EngineConfig config = sim::engine_config_for(*sim::find_device_profile("joystick"));
    for (double rate : {500.0, 1000.0, 10000.0}) {
        SCOPED_TRACE(std::to_string(rate) + " Hz");
        const auto rows = run_loop("joystick", sim::Grip::kinematic, "circle:2000:1",
                                   {dynamic_inertia_on({Axis::x, Axis::y}, 10000, 100)}, 2.5, rate);
        expect_a_mass_in_a_gap(rows, gap_axis(config, 10000, 100, 2000, 1, kPi / 2), 0, rate, 0.5);
        expect_a_mass_in_a_gap(rows, gap_axis(config, 10000, 100, 2000, 1, 0.0), 1, rate, 0.5);
    }
}

TEST(DynamicInertiaPlayClosedLoop, OnEveryProfileTheMassInTheGapIsTheSame) {
    // The wheel and the 3-axis device (their own mass and tether scales), the review's sine
    // with a play of 150 (the 3-axis device's tether sags 43 units on it), at the three
    // loop rates.
    for (const char* profile_name : {"wheel", "3axis"}) {
        const EngineConfig config = sim::engine_config_for(*sim::find_device_profile(profile_name));
        for (double rate : {500.0, 1000.0, 10000.0}) {
            SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz");
            const auto rows = run_loop(profile_name, sim::Grip::kinematic, "sine:x:2000:1",
                                       {dynamic_inertia_on({Axis::x}, 10000, 150)}, 2.5, rate);
            expect_a_mass_in_a_gap(rows, gap_axis(config, 10000, 150, 2000, 1, 0.0), 0, rate, 0.5);
        }
    }
}

TEST(DynamicInertiaPlayClosedLoop, TheMassIsProportionalToTheInertiaAndTheSameForEveryMotion) {
    // §8.4: Inertia → Mass, with play as without. M fitted by least squares of F against −a
    // over the ticks outside the transit windows must be the mapped M within 10%, for
    // every sine and every inertia.
    const EngineConfig config = sim::engine_config_for(*sim::find_device_profile("joystick"));
    // The sines at 0.5, 1 and 2 Hz with inertia 3000, 6000 and 10000, and at 5 Hz with
    // 1000 and 2000 (the regime of kCases).
    std::vector<Case> cases;
    for (int32_t inertia : {3000, 6000, 10000}) {
        cases.push_back({4000, 0.5, inertia, 200});
        cases.push_back({2000, 1, inertia, 100});
        cases.push_back({1000, 2, inertia, 100});
    }
    cases.push_back({500, 5, 1000, 30});
    cases.push_back({500, 5, 2000, 55});
    for (const Case& c : cases) {
        {
            SCOPED_TRACE("inertia " + std::to_string(c.inertia) + ", " + motion_of(c));
            const auto rows = run_loop("joystick", sim::Grip::kinematic, motion_of(c),
                                       {dynamic_inertia_on({Axis::x}, c.inertia, c.play)}, 2.0 / c.hz + 0.5);
            const GapAxis g = gap_axis(config, c.inertia, c.play, c.amplitude, c.hz, 0.0);
            const std::vector<Crossing> cs = crossings(rows, g, 0, 1e-3);
            const PlayFit f = fit(rows, g, cs, 0, 0.5);
            double fa = 0, aa = 0;
            for (const LoopRow& r : rows) {
                if (r.t_s < 0.5 || inside(cs, r.t_s)) continue;
                const double a = g.acceleration(r.t_s - f.lag_s);
                fa += -r.force[0] * a;
                aa += a * a;
            }
            EXPECT_NEAR(fa / aa, g.mass, 0.1 * g.mass);
        }
    }
}

}  // namespace
}  // namespace feel::test
