// dynamic_control_law (§5.10, §8.4) against a kinematic handle: every parameter of the
// law checked against the textbook solution of a mass on a spring-damper.
//
// The handle is placed by the test (no device), so the mass's motion relative to it has a
// closed form; the engine reports that motion every tick (TickOutput::mass_position) and
// the force is the tether's mean reaction over the tick that follows (docs/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tether_fixture.hpp"

namespace feel::test {
namespace {

struct Scales {
    double mass, stiffness, damping, gravity, velocity;
};

Scales scales_of(const EngineConfig& c) {
    return {c.dynamic_mass_ref, c.dynamic_stiffness_ref, c.dynamic_damping_ref, c.gravity_ref, c.velocity_ref};
}

// Ticks once with nothing playing, so the effect's first tick already knows the tick length.
DynamicRig started_rig(const EffectParams& p) {
    DynamicRig rig;
    rig.tick();
    rig.play(p);
    return rig;
}

// Position tolerance: float outputs of motions a few thousand units across.
double position_tolerance(double amplitude) { return 1e-3 + 2e-6 * std::fabs(amplitude); }

// What n ticks of a float state add to it: the mass's stretch and velocity are float
// (docs/dynamics.md, "Precision"), so each tick rounds them by about half an ulp, and an
// undamped swing carries those roundings on as a random walk of its phase: about
// sqrt(n) half-ulps of the amplitude (2^-24 each), allowed four times over. 3000 ticks of a
// 1000-unit swing: 0.013 units, a 400th of a joystick sensor count.
double float_walk(double amplitude, int ticks) {
    return 4 * std::sqrt(static_cast<double>(ticks) + 1) * std::ldexp(std::fabs(amplitude), -24);
}

// What float does to the frequency: the law's mass and stiffness are float, and so are the
// propagator's shear coefficients (tether_propagator.hpp), each within an ulp or two of
// the law's, so the simulated frequency is within a few 2^-24 of the law's: a phase error
// of that fraction of the angle turned, allowed as 2^-22 (four half-ulps) of it.
double float_frequency(double amplitude, double angle) { return std::ldexp(std::fabs(amplitude * angle), -22); }

TEST(ControlLaw, AnUndampedMassOscillatesAgainstAHeldHandle) {
    ControlLawBlock b = law_block(2000, 5000);
    b.pos_init = 500;
    b.vel_init = 2000;
    DynamicRig rig = started_rig(control_law_params(b));
    const Scales s = scales_of(rig.config());
    const double m = per_10000(2000, s.mass), k = per_10000(5000, s.stiffness);
    const Oscillator osc{m, 0, k, 500, per_10000(2000, s.velocity)};
    const double amplitude = std::hypot(osc.y0, osc.v0 / osc.omega0());
    const double T = rig.period_s();
    for (int n = 0; n < 3000; ++n) {
        const double t = n * T;
        const TickOutput out = rig.tick({0, 0});
        ASSERT_TRUE(out.has_mass);
        const double walk = float_walk(amplitude, n) + float_frequency(amplitude, osc.omega0() * t);
        ASSERT_NEAR(out.mass_position[0], osc.position(t), position_tolerance(amplitude) + walk) << "t=" << t;
        ASSERT_NEAR(out.mass_velocity[0], osc.velocity(t), 1e-3 * osc.omega0() * amplitude) << "t=" << t;
        // The handle feels the tether's pull k·s, averaged over the tick the motor holds it.
        const double pull = mean_over([&](double u) { return k * osc.position(u); }, t, t + T);
        ASSERT_NEAR(out.force[0], pull, 2e-2 + k * walk) << "t=" << t;
        ASSERT_EQ(out.force[1], 0.0f);  // the effect is on x only
    }
}

// (mass, k, b) spanning light and heavy damping.
class DampedControlLaw : public ::testing::TestWithParam<std::tuple<int32_t, int32_t, int32_t>> {};

TEST_P(DampedControlLaw, FrequencyAndDecayMatchTheDampedOscillator) {
    const auto [mass, k_int, b_int] = GetParam();
    ControlLawBlock block = law_block(mass, k_int, b_int);
    block.vel_init = -4000;
    block.pos_init = 500;
    DynamicRig rig = started_rig(control_law_params(block));
    const Scales s = scales_of(rig.config());
    const double m = per_10000(mass, s.mass), k = per_10000(k_int, s.stiffness), c = per_10000(b_int, s.damping);
    const Oscillator osc{m, c, k, 500, per_10000(-4000, s.velocity)};
    const double amplitude = std::hypot(osc.y0, osc.v0 / osc.omega0());
    const double T = rig.period_s();
    for (int n = 0; n < 2000; ++n) {
        const double t = n * T;
        const TickOutput out = rig.tick({0, 0});
        ASSERT_NEAR(out.mass_position[0], osc.position(t), position_tolerance(amplitude)) << "t=" << t;
        const double pull = mean_over([&](double u) { return k * osc.position(u) + c * osc.velocity(u); }, t, t + T);
        ASSERT_NEAR(out.force[0], std::clamp(pull, -10000.0, 10000.0), 2e-2 + 1e-6 * std::fabs(pull)) << "t=" << t;
    }
}

INSTANTIATE_TEST_SUITE_P(UnderCriticalAndOverdamped, DampedControlLaw,
                         ::testing::Values(std::make_tuple(3000, 6000, 500),     // light damping
                                           std::make_tuple(3000, 6000, 3000),    // ζ ≈ 0.55
                                           std::make_tuple(1000, 2000, 10000),   // heavily overdamped
                                           std::make_tuple(10000, 10000, 10000)  // critical by the scale's rule
                                           ));

TEST(ControlLaw, TheDampedPeriodIsTheAnalyticOne) {
    // Measured from the zero crossings of the reported stretch, independently of phase.
    ControlLawBlock block = law_block(6000, 3000, 800);
    block.pos_init = 3000;
    DynamicRig rig = started_rig(control_law_params(block));
    const Scales s = scales_of(rig.config());
    const double m = per_10000(6000, s.mass), k = per_10000(3000, s.stiffness), c = per_10000(800, s.damping);
    const double gamma = c / (2 * m);
    const double wd = std::sqrt(k / m - gamma * gamma);
    std::vector<double> crossings;
    std::vector<double> peaks;  // |s| at each extremum
    double prev = 3000, prev_v = 0;
    for (int n = 0; n < 6000; ++n) {
        const TickOutput out = rig.tick({0, 0});
        const double x = out.mass_position[0], v = out.mass_velocity[0];
        const double t = n * rig.period_s();
        if (n > 0 && (prev > 0) != (x > 0)) crossings.push_back(t - rig.period_s() * x / (x - prev));
        if (n > 0 && (prev_v > 0) != (v > 0)) peaks.push_back(std::fabs(x));
        prev = x;
        prev_v = v;
    }
    ASSERT_GE(crossings.size(), 6u);
    const double half_period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    EXPECT_NEAR(half_period, kPiD / wd, 1e-4 * kPiD / wd);
    // Successive extrema shrink by exp(−γ·π/ωd).
    ASSERT_GE(peaks.size(), 4u);
    const double ratio = peaks[3] / peaks[1];
    EXPECT_NEAR(ratio, std::exp(-2 * gamma * kPiD / wd), 0.01 * ratio);
}

TEST(ControlLaw, GravitySagsTheMassByWeightOverStiffness) {
    for (int32_t g : {-7000, 4000}) {
        ControlLawBlock block = law_block(4000, 3000, 4000);
        block.gravity = g;
        DynamicRig rig = started_rig(control_law_params(block, {Axis::y}));
        const Scales s = scales_of(rig.config());
        const double weight = per_10000(4000, s.mass) * per_10000(g, s.gravity);
        const double k = per_10000(3000, s.stiffness);
        TickOutput out;
        for (int n = 0; n < 4000; ++n) out = rig.tick({0, 0});
        EXPECT_NEAR(out.mass_position[1], weight / k, 1e-3 * std::fabs(weight / k)) << "gravity " << g;
        // The handle holds the weight: the tether pulls it the way gravity pulls the mass.
        EXPECT_NEAR(out.force[1], weight, 1e-3 * std::fabs(weight)) << "gravity " << g;
        EXPECT_EQ(out.force[0], 0.0f);
    }
}

TEST(ControlLaw, GravityHangsTheMassBeyondTheFreePlay) {
    ControlLawBlock block = law_block(4000, 3000, 4000);
    block.k_neg = 6000;
    block.gravity = -5000;
    block.length = 800;
    DynamicRig rig = started_rig(control_law_params(block));
    const Scales s = scales_of(rig.config());
    const double weight = per_10000(4000, s.mass) * per_10000(-5000, s.gravity);
    TickOutput out;
    for (int n = 0; n < 4000; ++n) out = rig.tick({0, 0});
    EXPECT_NEAR(out.mass_position[0], -800 + weight / per_10000(6000, s.stiffness), 0.5);
    EXPECT_NEAR(out.force[0], weight, 1e-3 * std::fabs(weight));
}

// The exact piecewise solution of an undamped mass from s = 0 with velocity v > 0 on a
// tether with k_pos, k_neg and free play ±L: free flight across the play, a sine arc
// beyond it on each side.
struct PiecewiseOrbit {
    double m, k_pos, k_neg, length, v;
    [[nodiscard]] double w_pos() const { return std::sqrt(k_pos / m); }
    [[nodiscard]] double w_neg() const { return std::sqrt(k_neg / m); }
    [[nodiscard]] double period() const { return 4 * length / v + kPiD / w_pos() + kPiD / w_neg(); }
    [[nodiscard]] double position(double t) const {
        t = std::fmod(t, period());
        const double fly = length / v;  // 0 → +L, and −L → 0
        if (t < fly) return v * t;
        t -= fly;
        if (t < kPiD / w_pos()) return length + v / w_pos() * std::sin(w_pos() * t);
        t -= kPiD / w_pos();
        if (t < 2 * fly) return length - v * t;
        t -= 2 * fly;
        if (t < kPiD / w_neg()) return -length - v / w_neg() * std::sin(w_neg() * t);
        t -= kPiD / w_neg();
        return -length + v * t;
    }
    [[nodiscard]] double pull(double s) const {
        if (s > length) return k_pos * (s - length);
        if (s < -length) return k_neg * (s + length);
        return 0.0;
    }
};

class PiecewiseControlLaw : public ::testing::TestWithParam<std::tuple<int32_t, int32_t, int32_t>> {};

TEST_P(PiecewiseControlLaw, StiffnessBySideAndFreePlayFollowTheExactOrbit) {
    const auto [k_pos, k_neg, length] = GetParam();
    ControlLawBlock block = law_block(3000, k_pos);
    block.k_neg = k_neg;
    block.length = length;
    block.vel_init = 2500;
    DynamicRig rig = started_rig(control_law_params(block));
    const Scales s = scales_of(rig.config());
    const PiecewiseOrbit orbit{per_10000(3000, s.mass), per_10000(k_pos, s.stiffness), per_10000(k_neg, s.stiffness),
                               static_cast<double>(length), per_10000(2500, s.velocity)};
    const double amplitude = length + orbit.v / std::min(orbit.w_pos(), orbit.w_neg());
    const double T = rig.period_s();
    const int ticks = static_cast<int>(3 * orbit.period() / T);
    for (int n = 0; n < ticks; ++n) {
        const double t = n * T;
        const TickOutput out = rig.tick({0, 0});
        const double walk = float_walk(amplitude, n);
        ASSERT_NEAR(out.mass_position[0], orbit.position(t), position_tolerance(amplitude) + walk) << "t=" << t;
        const double pull = mean_over([&](double u) { return orbit.pull(orbit.position(u)); }, t, t + T, 2000);
        ASSERT_NEAR(out.force[0], pull, 0.05 + 1e-5 * std::fabs(pull) + std::max(orbit.k_pos, orbit.k_neg) * walk)
            << "t=" << t;
    }
}

INSTANTIATE_TEST_SUITE_P(SidesAndPlay, PiecewiseControlLaw,
                         ::testing::Values(std::make_tuple(8000, 2000, 0),     // stiffer ahead than behind
                                           std::make_tuple(3000, 3000, 1500),  // free play, same stiffness
                                           std::make_tuple(1000, 9000, 400)));

TEST(ControlLaw, NoForceWhileTheMassIsInsideTheFreePlay) {
    ControlLawBlock block = law_block(5000, 5000, 2000);
    block.length = 3000;
    block.vel_init = 1000;  // 10000 units/s on the default scale: across the play in 0.3 s
    DynamicRig rig = started_rig(control_law_params(block));
    const double v = per_10000(1000, rig.config().velocity_ref);
    const double t_edge = 3000 / v;
    const double T = rig.period_s();
    for (int n = 0; T * (n + 1) < t_edge; ++n) {
        const TickOutput out = rig.tick({0, 0});
        ASSERT_EQ(out.force[0], 0.0f) << "t=" << n * T;  // slack, no damping either
        ASSERT_NEAR(out.mass_position[0], v * n * T, 1e-3);
    }
}

TEST(ControlLaw, DragResistsSteadyMotionTetherDampingOnlyRelativeMotion) {
    // The handle moves at a steady u: with drag d the mass trails by d·u/k and the handle
    // feels −d·u; with only tether damping the mass keeps up and the handle feels nothing.
    const double u = 4000;  // units/s: 4 units per 1 ms tick, exact in float
    for (const bool drag : {true, false}) {
        ControlLawBlock block = law_block(2000, 6000);
        (drag ? block.drag : block.b) = 4000;
        DynamicRig rig;
        for (int n = 0; n < 50; ++n) rig.tick({u * n * rig.period_s() - 5000});  // the estimator locks on
        rig.play(control_law_params(block));
        TickOutput out;
        for (int n = 50; n < 2050; ++n) out = rig.tick({u * n * rig.period_s() - 5000});
        const Scales s = scales_of(rig.config());
        const double d = per_10000(4000, s.damping);
        if (drag) {
            EXPECT_NEAR(out.force[0], -d * u, 1e-3 * d * u);
            EXPECT_NEAR(out.mass_position[0], -d * u / per_10000(6000, s.stiffness), 0.05);
        } else {
            EXPECT_NEAR(out.force[0], 0.0, 0.05);
            EXPECT_NEAR(out.mass_position[0], 0.0, 0.01);
        }
        EXPECT_NEAR(out.mass_velocity[0], 0.0, 0.05);
    }
}

TEST(ControlLaw, InitialPositionAndVelocityAreRelativeToTheHandle) {
    // A handle moving steadily carries the tether along: the relative motion is the same
    // oscillator as against a held handle.
    const double u = -15000;
    ControlLawBlock block = law_block(2500, 4000);
    block.pos_init = -1200;
    block.vel_init = 2000;
    DynamicRig rig;
    for (int n = 0; n < 50; ++n) rig.tick({4000 + u * n * rig.period_s()});
    rig.play(control_law_params(block));
    const Scales s = scales_of(rig.config());
    const Oscillator osc{per_10000(2500, s.mass), 0, per_10000(4000, s.stiffness), -1200,
                         per_10000(2000, s.velocity)};
    const double amplitude = std::hypot(osc.y0, osc.v0 / osc.omega0());
    for (int n = 0; n < 500; ++n) {
        const double t = n * rig.period_s();
        const TickOutput out = rig.tick({4000 + u * (n + 50) * rig.period_s()});
        ASSERT_NEAR(out.mass_position[0], osc.position(t), position_tolerance(amplitude) + 1e-3) << "t=" << t;
        ASSERT_NEAR(out.mass_velocity[0], osc.velocity(t), 1e-3 * osc.omega0() * amplitude + 0.05) << "t=" << t;
    }
}

// The first tick at or after t at which a swing of amplitude a through its rest value has
// gone one sensor count past it (the hysteresis that keeps sensor flicker from counting).
double counted_at(double crossing_t, double omega, double amplitude, double hysteresis) {
    return crossing_t + std::asin(hysteresis / amplitude) / omega;
}

TEST(ControlLaw, HalfCyclesEndTheEffectWithAFinalReport) {
    for (const bool from_velocity : {true, false}) {
        ControlLawBlock block = law_block(3000, 2000);
        block.half_cycles = 5;
        (from_velocity ? block.vel_init : block.pos_init) = 2000;
        DynamicRig rig = started_rig(control_law_params(block));
        const Scales s = scales_of(rig.config());
        const Oscillator osc{per_10000(3000, s.mass), 0, per_10000(2000, s.stiffness),
                             from_velocity ? 0.0 : 2000.0, from_velocity ? per_10000(2000, s.velocity) : 0.0};
        const double w = osc.omega0();
        const double amplitude = std::hypot(osc.y0, osc.v0 / w);
        // From rest at the handle with a kick, half cycle N ends N half periods in; released
        // from a pre-stretch, the stretch first crosses its rest value a quarter period in.
        const double crossing = (from_velocity ? 5 * kPiD : 4.5 * kPiD) / w;
        const double due = counted_at(crossing, w, amplitude, rig.config().sensor_step);
        const double T = rig.period_s();
        const int64_t start_us = rig.t_us();
        int64_t ended_us = -1;
        for (int n = 0; n < 5000 && ended_us < 0; ++n) {
            const int64_t t_us = rig.t_us();
            const TickOutput out = rig.tick({0, 0});
            DynamicReport r;
            while (rig.engine().pop_report(r)) {
                ASSERT_EQ(r.kind, DynamicReport::Kind::final);
                ASSERT_EQ(r.effect, rig.id());
                ASSERT_EQ(r.axis_count, 1);
                ended_us = r.t_us;
                const double t = seconds_between(start_us, r.t_us);
                EXPECT_NEAR(r.position[0], osc.position(t), position_tolerance(amplitude));
                EXPECT_NEAR(r.velocity[0], osc.velocity(t), 1e-3 * w * amplitude);
                EXPECT_EQ(out.force[0], 0.0f);  // the ending tick applies no force
                EXPECT_EQ(t_us, r.t_us);
            }
        }
        ASSERT_GE(ended_us, 0) << "never ended";
        const double ended = seconds_between(start_us, ended_us);
        EXPECT_GE(ended, due - 1e-9) << (from_velocity ? "kick" : "pre-stretch");
        EXPECT_LT(ended, due + T) << (from_velocity ? "kick" : "pre-stretch");
        EXPECT_EQ(rig.engine().state(rig.id()), EffectState::stopped);
        EXPECT_EQ(rig.tick({0, 0}).force[0], 0.0f);
    }
}

TEST(ControlLaw, HalfCyclesCountAboutTheSaggedRestNotTheHandle) {
    // Under gravity the mass never comes back to the handle; it swings about its sag.
    ControlLawBlock block = law_block(3000, 2000);
    block.gravity = -3000;
    block.half_cycles = 2;
    DynamicRig rig = started_rig(control_law_params(block));
    const Scales s = scales_of(rig.config());
    const double m = per_10000(3000, s.mass), k = per_10000(2000, s.stiffness);
    const double sag = m * per_10000(-3000, s.gravity) / k;
    // Released at the handle, it swings from 0 to 2·sag and back: rest is crossed a quarter
    // period in, then three quarters in, when the second half cycle is done.
    const double w = std::sqrt(k / m);
    const double due = counted_at(1.5 * kPiD / w, w, std::fabs(sag), rig.config().sensor_step);
    const int64_t start_us = rig.t_us();
    int64_t ended_us = -1;
    for (int n = 0; n < 5000 && ended_us < 0; ++n) {
        rig.tick({0, 0});
        DynamicReport r;
        while (rig.engine().pop_report(r)) ended_us = r.t_us;
    }
    ASSERT_GE(ended_us, 0);
    const double ended = seconds_between(start_us, ended_us);
    EXPECT_GE(ended, due - 1e-9);
    EXPECT_LT(ended, due + rig.period_s());
}

TEST(ControlLaw, TheFirstAxisToFinishItsHalfCyclesEndsTheEffect) {
    EffectParams p = control_law_params(law_block(3000, 2000), {Axis::x, Axis::y});
    p.dynamic.control_law[0].vel_init = 2000;  // x: counts, but asks for many
    p.dynamic.control_law[0].half_cycles = 40;
    p.dynamic.control_law[1].vel_init = 0;     // y: never moves, never counts
    p.dynamic.control_law[1].half_cycles = 1;
    p.dynamic.control_law[1].k_pos = p.dynamic.control_law[1].k_neg = 8000;
    DynamicRig rig = started_rig(p);
    const double w = std::sqrt(per_10000(2000, rig.config().dynamic_stiffness_ref) /
                               per_10000(3000, rig.config().dynamic_mass_ref));
    int n = 0;
    while (rig.engine().state(rig.id()) != EffectState::stopped && n < 20000) {
        rig.tick({0, 0});
        ++n;
    }
    // y, asking for one half cycle, never swings: x's 40 decide.
    EXPECT_NEAR(n * rig.period_s(), 40 * kPiD / w, 0.01);
}

TEST(ControlLaw, AxesAreIndependent) {
    EffectParams p = control_law_params(law_block(3000, 2000), {Axis::y, Axis::x});
    p.dynamic.control_law[0].vel_init = 3000;   // effect axis 0 is y
    p.dynamic.control_law[1] = law_block(1000, 9000, 1000);
    p.dynamic.control_law[1].pos_init = -2000;  // effect axis 1 is x
    DynamicRig rig = started_rig(p);
    const Scales s = scales_of(rig.config());
    const Oscillator y{per_10000(3000, s.mass), 0, per_10000(2000, s.stiffness), 0, per_10000(3000, s.velocity)};
    const Oscillator x{per_10000(1000, s.mass), per_10000(1000, s.damping), per_10000(9000, s.stiffness), -2000, 0};
    for (int n = 0; n < 1000; ++n) {
        const double t = n * rig.period_s();
        const TickOutput out = rig.tick({0, 0});
        ASSERT_NEAR(out.mass_position[1], y.position(t), position_tolerance(5000)) << t;
        ASSERT_NEAR(out.mass_position[0], x.position(t), position_tolerance(2000)) << t;
    }
}

TEST(ControlLaw, InterimReportsCarryTheMassRelativeToTheHandle) {
    ControlLawBlock block = law_block(3000, 4000, 200);
    block.vel_init = 2500;
    EffectParams p = control_law_params(block, {Axis::y});
    p.dynamic.interim_reporting = true;
    DynamicRig rig;
    for (int n = 0; n < 20; ++n) rig.tick({0, 300});  // a handle held off centre, still
    rig.play(p);
    const Scales s = scales_of(rig.config());
    const Oscillator osc{per_10000(3000, s.mass), per_10000(200, s.damping), per_10000(4000, s.stiffness), 0,
                         per_10000(2500, s.velocity)};
    const int64_t start_us = rig.t_us();
    int reports = 0;
    for (int n = 0; n < 1000; ++n) {
        rig.tick({0, 300});  // reports stay relative to the handle
        DynamicReport r;
        while (rig.engine().pop_report(r)) {
            ASSERT_EQ(r.kind, DynamicReport::Kind::interim);
            const double t = seconds_between(start_us, r.t_us);
            EXPECT_NEAR(r.position[0], osc.position(t), position_tolerance(3000));
            EXPECT_NEAR(r.velocity[0], osc.velocity(t), 0.05 * osc.omega0());
            ++reports;
        }
    }
    EXPECT_NEAR(reports, 60, 1);  // 60 Hz for one second
}

TEST(ControlLaw, RestartingStartsTheMassOver) {
    ControlLawBlock block = law_block(3000, 4000);
    block.vel_init = 2500;
    DynamicRig rig = started_rig(control_law_params(block));
    std::vector<float> first;
    for (int n = 0; n < 100; ++n) first.push_back(rig.tick({0, 0}).force[0]);
    ASSERT_TRUE(rig.engine().start(rig.id()).ok());
    for (int n = 0; n < 100; ++n) ASSERT_EQ(rig.tick({0, 0}).force[0], first[static_cast<size_t>(n)]) << n;
}

}  // namespace
}  // namespace feel::test
