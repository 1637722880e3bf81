// Integration you can trust (issue 4, section 4): the exact spring-damper step against the
// textbook, event location at the edges of a piecewise law, energy kept for a minute, and
// the coupled handle-mass loop stable on every device profile at the extremes of the
// parameter ranges, with a free handle and with every grip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "dynamics/tether_law.hpp"
#include "dynamics/tether_step.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/sim_device.hpp"
#include "tether_fixture.hpp"

namespace feel::test {
namespace {

using detail::MassState;
using detail::SpringDamper;

// --- the exact step ------------------------------------------------------------------------

// The textbook solution of m·ÿ + c·ẏ + k·y = f: the oscillator about y = f/k for k > 0; for
// k = 0 a mass under a constant force and linear drag (ballistic when c = 0).
MassState textbook(const SpringDamper& s, MassState x, double t) {
    if (s.stiffness > 0) {
        const double eq = s.force / s.stiffness;
        const Oscillator osc{s.mass, s.damping, s.stiffness, x.position - eq, x.velocity};
        double y, v;
        osc.at(t, y, v);
        return {y + eq, v};
    }
    if (s.damping == 0) {
        const double a = s.force / s.mass;
        return {x.position + x.velocity * t + a * t * t / 2, x.velocity + a * t};
    }
    // Terminal velocity f/c and relaxation rate c/m; long double because a light drag makes
    // the terminal velocity huge and the two terms of the position nearly cancel.
    const long double terminal = static_cast<long double>(s.force) / s.damping;
    const long double rate = static_cast<long double>(s.damping) / s.mass;
    const long double lt = t;
    const long double one_minus_e = -std::expm1(-rate * lt);
    const long double y = x.position + terminal * lt + (x.velocity - terminal) * one_minus_e / rate;
    const long double v = terminal + (x.velocity - terminal) * (1 - one_minus_e);
    return {static_cast<double>(y), static_cast<double>(v)};
}

// The worst error of tether_step<T> against the textbook over 20 000 random (m, k, c, f, h)
// across all regimes, in units of the motion's own scale (position, velocity): the step's
// state rounds to T, so the textbook (double) is compared with what T can hold.
template <typename T>
void expect_textbook(double position_tolerance, double velocity_tolerance, double equilibrium_rounding,
                     double phase_rounding) {
    using Spring = detail::BasicSpringDamper<T>;
    using State = detail::BasicMassState<T>;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
    for (int i = 0; i < 20000; ++i) {
        SpringDamper s;
        s.mass = log_uniform(1e-6, 1e-1);
        const double w0 = log_uniform(0.3, 3e3);  // the ranges' slowest tether is ~0.7 rad/s
        s.stiffness = i % 10 == 0 ? 0.0 : s.mass * w0 * w0;
        const double zeta = i % 7 == 0 ? 0.0 : (i % 13 == 0 ? 1.0 : log_uniform(1e-3, 1e3));
        s.damping = 2 * zeta * s.mass * (s.stiffness > 0 ? w0 : log_uniform(1e-2, 1e3));
        s.force = (unit(rng) - 0.5) * 2e4;
        MassState x{(unit(rng) - 0.5) * 2e4, (unit(rng) - 0.5) * 2e5};
        double h = log_uniform(1e-5, 2e-2);
        // The parameters as T holds them, so that the textbook solves the same system.
        const Spring st{static_cast<T>(s.mass), static_cast<T>(s.stiffness), static_cast<T>(s.damping),
                        static_cast<T>(s.force)};
        s = {st.mass, st.stiffness, st.damping, st.force};
        const State xt{static_cast<T>(x.position), static_cast<T>(x.velocity)};
        x = {xt.position, xt.velocity};
        h = static_cast<T>(h);
        const State got = detail::tether_step<T>(st, xt, static_cast<T>(h));
        const MassState want = textbook(s, x, h);
        // Both solutions shift to the equilibrium f/k: rounding there is eps·|f/k|.
        const double far = s.stiffness > 0 ? std::fabs(s.force / s.stiffness) : 0.0;
        // And the angle turned, θ = ω0·h, is a T of its own rounding: the phase is off by
        // phase_rounding·θ, the state by that times the swing's amplitude (of y, of ẏ).
        const double w = std::sqrt(s.stiffness / s.mass);
        const double amplitude = s.stiffness > 0 ? std::hypot(x.position - s.force / s.stiffness, x.velocity / w) : 0.0;
        const double phase = phase_rounding * w * h * amplitude;
        const double scale_y = std::fabs(x.position) + std::fabs(x.velocity) * h + std::fabs(want.position) +
                               (equilibrium_rounding * far + phase) / position_tolerance + 1;
        const double scale_v = std::fabs(x.velocity) + std::fabs(want.velocity) + std::fabs(s.force / s.mass) * h +
                               phase * w / velocity_tolerance + 1;
        ASSERT_NEAR(got.position, want.position, position_tolerance * scale_y)
            << "m=" << s.mass << " k=" << s.stiffness << " c=" << s.damping << " h=" << h;
        ASSERT_NEAR(got.velocity, want.velocity, velocity_tolerance * scale_v)
            << "m=" << s.mass << " k=" << s.stiffness << " c=" << s.damping << " h=" << h;
    }
}

TEST(TetherStep, MatchesTheTextbookInEveryRegime) {
    // Double (the paddle's contact): 1e-8 and 1e-7 of the motion's scale, 1e-15 of f/k.
    expect_textbook<double>(1e-8, 1e-7, 1e-15, 0.0);
}

TEST(TetherStep, MatchesTheTextbookInEveryRegimeInFloat) {
    // Float (the control laws'): float's epsilon is 2^-24 = 6e-8, and the closed form takes
    // a dozen roundings (an exponential, a sine and a cosine of a few ulps each, the
    // equilibrium's shift), so tens of eps of the motion's scale: 3e-6 and 1e-5 (the double
    // bounds are 1e8·2^-53 and 1e9·2^-53 alike). The shift to the equilibrium f/k rounds by
    // eps·|f/k|: 2e-7 of it. A spring with ω0²h² < 1e-5 is held at its starting force
    // (kFreeLimit: 2e-6 of the motion at most). The angle θ = ωd·h comes from float k/m, a
    // square root and a product, and its sine from a fraction of a turn: its rounding is a
    // few ulps of θ, 2^-21 (four ulps at the bottom of a binade) of it.
    expect_textbook<float>(3e-6, 1e-5, 2e-7, 0x1p-21);
}

TEST(TetherStep, OneLongStepIsManyShortOnes) {
    // Exactness: the solution is a flow, so stepping 1000 × h/1000 lands where one h does.
    for (const double zeta : {0.0, 0.05, 1.0, 40.0}) {
        const SpringDamper s{2e-3, 8.0, 2 * zeta * std::sqrt(8.0 * 2e-3), -300};
        MassState one = detail::tether_step(s, {500, -9000}, 0.25);
        MassState many{500, -9000};
        for (int i = 0; i < 1000; ++i) many = detail::tether_step(s, many, 0.25 / 1000);
        EXPECT_NEAR(one.position, many.position, 1e-8 * 1000) << zeta;
        EXPECT_NEAR(one.velocity, many.velocity, 1e-7 * 1e5) << zeta;
    }
}

TEST(TetherStep, ExtremeRatiosStayFiniteAndBounded) {
    // Stiff over light, damped over light, and every step length: never a NaN, and the
    // motion of a passive oscillator never gains energy.
    for (double m : {1e-9, 1e-6, 1.0}) {
        for (double k : {0.0, 1e-6, 1.0, 1e6}) {
            for (double c : {0.0, 1e-6, 1.0, 1e6}) {
                for (double h : {1e-6, 1e-3, 1.0}) {
                    const SpringDamper s{m, k, c, 0};
                    const MassState x{1000, 1e4};
                    const MassState y = detail::tether_step(s, x, h);
                    ASSERT_TRUE(std::isfinite(y.position) && std::isfinite(y.velocity)) << m << " " << k << " " << c;
                    if (k > 0) {
                        const double e0 = 0.5 * m * x.velocity * x.velocity + 0.5 * k * x.position * x.position;
                        const double e1 = 0.5 * m * y.velocity * y.velocity + 0.5 * k * y.position * y.position;
                        ASSERT_LE(e1, e0 * (1 + 1e-9)) << m << " " << k << " " << c << " " << h;
                    }
                }
            }
        }
    }
}

TEST(TetherCrossing, FindsTheCrossingOfASine) {
    // y = A·sin(ωt) over a step of 1/ω (y reaches A·sin 1 ≈ 0.84·A): a level below that is
    // crossed at asin(L/A)/ω; a level above it, or one it moves away from, is not.
    const double m = 1e-3, k = 4.0, w = std::sqrt(k / m), a = 800;
    const SpringDamper s{m, k, 0, 0};
    double t = 0;
    for (const double level : {1.0, 300.0, 600.0}) {
        ASSERT_TRUE(detail::tether_crossing(s, {0, a * w}, level, 1.0 / w, t)) << level;
        EXPECT_NEAR(t, std::asin(level / a) / w, 1e-9 / w) << level;
    }
    EXPECT_FALSE(detail::tether_crossing(s, {0, a * w}, 700, 1.0 / w, t));
    EXPECT_FALSE(detail::tether_crossing(s, {0, a * w}, -600, 1.0 / w, t));
}

TEST(TetherCrossing, FindsAGrazeThatComesBackWithinTheStep) {
    // Up through 100 and back down within one step: the first crossing is on the way up.
    const double m = 1e-3, k = 4.0, w = std::sqrt(k / m), a = 120;
    const SpringDamper s{m, k, 0, 0};
    const double h = 3.0 / w;
    double t = 0;
    ASSERT_TRUE(detail::tether_crossing(s, {0, a * w}, 100, h, t));
    EXPECT_NEAR(t, std::asin(100 / a) / w, 1e-9 * h);
    // Starting above 100 on the way up, over the top and back down: the way down counts.
    const MassState above{110, std::sqrt(a * a - 110 * 110) * w};
    ASSERT_TRUE(detail::tether_crossing(s, above, 100, h, t));
    const double t_top = (kPiD / 2 - std::asin(110 / a)) / w;
    EXPECT_NEAR(t, t_top + (kPiD / 2 - std::asin(100 / a)) / w, 1e-9 * h);
    // A crest below the level is not a crossing.
    EXPECT_FALSE(detail::tether_crossing(s, {0, a * w}, 121, h, t));
}

TEST(TetherCrossing, LeavingTheLevelIsNotACrossingComingBackIs) {
    const double m = 1e-3, k = 4.0, w = std::sqrt(k / m);
    const SpringDamper s{m, k, 0, 0};
    double t = 0;
    // From the level moving out, the return half a period later is the crossing.
    ASSERT_TRUE(detail::tether_crossing(s, {0, 5000}, 0, 3.5 / w, t));
    EXPECT_NEAR(t, kPiD / w, 1e-9 * 3.5 / w);
    // From rest on the level with a force pushing off it (gravity on a slack tether).
    const SpringDamper falling{m, 0, 0, -10};
    EXPECT_FALSE(detail::tether_crossing(falling, {0, 0}, 0, 1.0, t));
}

TEST(TetherCrossing, FindsTheCrossingOfASineInFloat) {
    // The control laws' precision: the bracket closes to 2^-20 of the step, and the motion is
    // evaluated to a few float ulps of its amplitude (y = A·sin ωt, slope A·ω·cos ωt), which
    // moves the root by a few eps/(ω·cos ωt): 1e-6/ω + 2^-20·h bounds both at these levels
    // (cos ωt >= 0.66). The graze and the return are located as well, within the same bound
    // scaled by how flat the motion is there (1/cos: 1.8 at 100 of 120).
    using detail::MassStateF;
    using detail::SpringDamperF;
    const float m = 1e-3f, k = 4.0f;
    const double w = std::sqrt(static_cast<double>(k) / static_cast<double>(m)), a = 800;
    const SpringDamperF s{m, k, 0, 0};
    const float h = static_cast<float>(1.0 / w);
    float t = 0;
    for (const double level : {1.0, 300.0, 600.0}) {
        ASSERT_TRUE(detail::tether_crossing(s, MassStateF{0, static_cast<float>(a * w)}, static_cast<float>(level), h, t))
            << level;
        EXPECT_NEAR(t, std::asin(level / a) / w, 1e-6 / w + 0x1p-20 * h) << level;
    }
    EXPECT_FALSE(detail::tether_crossing(s, MassStateF{0, static_cast<float>(a * w)}, 700.0f, h, t));
    EXPECT_FALSE(detail::tether_crossing(s, MassStateF{0, static_cast<float>(a * w)}, -600.0f, h, t));
    // A graze up through 100 and back within one step, and from the level the return.
    const double a2 = 120;
    const float h3 = static_cast<float>(3.0 / w);
    ASSERT_TRUE(detail::tether_crossing(s, MassStateF{0, static_cast<float>(a2 * w)}, 100.0f, h3, t));
    EXPECT_NEAR(t, std::asin(100 / a2) / w, 2 * (1e-6 / w + 0x1p-20 * h3));
    EXPECT_FALSE(detail::tether_crossing(s, MassStateF{0, static_cast<float>(a2 * w)}, 121.0f, h3, t));
    const float h35 = static_cast<float>(3.5 / w);
    ASSERT_TRUE(detail::tether_crossing(s, MassStateF{0, 5000}, 0.0f, h35, t));
    EXPECT_NEAR(t, kPiD / w, 1e-6 / w + 0x1p-20 * h35);
}

TEST(TetherCrossing, FindsTheCrossingOfAFreeMassInFloat) {
    // The play's motion: a free mass under a constant force, thrown at the level, dropped on
    // it from rest, and slowed by drag on its way. The crossing is the analytic one (the
    // quadratic's root; with drag, the root of the closed form y0 + v∞·t + (v0 − v∞)(1 −
    // e^{−a·t})/a, v∞ = f/(m·a), bisected in double), within the bracket's 2^-20 of the
    // step and the float ulps of the position it is read from (4 ulps of 128 over the speed
    // there).
    using detail::MassStateF;
    using detail::SpringDamperF;
    float t = 0;
    {
        // y = 80 − 20000·t − 2.5e5·t² reaches 65 within the 1 ms step.
        const SpringDamperF thrown{0.01f, 0, 0, -5000.0f};
        const double h = 1e-3, root = (-20000 + std::sqrt(20000.0 * 20000 + 4 * 2.5e5 * 15)) / (2 * 2.5e5);
        ASSERT_TRUE(detail::tether_crossing(thrown, MassStateF{80, -20000}, 65.0f, static_cast<float>(h), t));
        EXPECT_NEAR(t, root, 0x1p-20 * h + 4 * 0x1p-17 / (20000 + 5e5 * root));
    }
    {
        // From rest 50 above the level at 1e6 units/s²: there after √(2·50/1e6) = 10 ms.
        const SpringDamperF dropped{0.01f, 0, 0, -1e4f};
        const double h = 0.02, root = std::sqrt(2 * 50 / 1e6);
        ASSERT_TRUE(detail::tether_crossing(dropped, MassStateF{50, 0}, 0.0f, static_cast<float>(h), t));
        EXPECT_NEAR(t, root, 0x1p-20 * h + 4 * 0x1p-17 / (1e6 * root));
    }
    {
        // Drag a = c/m = 200/s, the force pushing on at 2e5 units/s², from 90 at 15000 units/s
        // toward 100 (crossed about 0.65 ms in).
        const SpringDamperF dragged{0.01f, 0, 2.0f, 2000.0f};
        const double a = 200, v0 = 15000, vinf = 2e5 / a, h = 1e-3;
        const auto y = [&](double tt) { return 90 + vinf * tt + (v0 - vinf) * -std::expm1(-a * tt) / a; };
        double lo = 0, hi = h;
        for (int i = 0; i < 200; ++i) (y((lo + hi) / 2) < 100 ? lo : hi) = (lo + hi) / 2;
        const double speed = vinf + (v0 - vinf) * std::exp(-a * hi);
        ASSERT_TRUE(detail::tether_crossing(dragged, MassStateF{90, 15000}, 100.0f, static_cast<float>(h), t));
        EXPECT_NEAR(t, hi, 0x1p-20 * h + 4 * 0x1p-17 / speed);
    }
}

// --- energy over a minute ---------------------------------------------------------------------

double law_energy(const ControlLawBlock& b, const EngineConfig& c, double s, double v) {
    const double m = per_10000(b.mass, c.dynamic_mass_ref);
    const double kp = per_10000(b.k_pos, c.dynamic_stiffness_ref), kn = per_10000(b.k_neg, c.dynamic_stiffness_ref);
    const double L = b.length;
    double u = 0;
    if (s > L) u = 0.5 * kp * (s - L) * (s - L);
    if (s < -L) u = 0.5 * kn * (s + L) * (s + L);
    return 0.5 * m * v * v + u;
}

class EnergyOverAMinute : public ::testing::TestWithParam<std::tuple<int32_t, int32_t, int32_t>> {};

TEST_P(EnergyOverAMinute, AnUndampedTetheredMassKeepsItsEnergy) {
    // Handle held still (kinematic), no damping, no drag: 60 s at 1 kHz, 60000 ticks and
    // hundreds of oscillations; the energy drifts by less than 0.1%.
    const auto [k_pos, k_neg, length] = GetParam();
    ControlLawBlock b = law_block(2000, k_pos);
    b.k_neg = k_neg;
    b.length = length;
    b.vel_init = 3000;
    b.pos_init = 700;
    DynamicRig rig;
    rig.tick({0, 0});
    rig.play(control_law_params(b));
    const TickOutput first = rig.tick({0, 0});
    const double e0 = law_energy(b, rig.config(), first.mass_position[0], first.mass_velocity[0]);
    double worst = 0;
    for (int n = 1; n < 60000; ++n) {
        const TickOutput out = rig.tick({0, 0});
        const double e = law_energy(b, rig.config(), out.mass_position[0], out.mass_velocity[0]);
        worst = std::max(worst, std::fabs(e - e0) / e0);
    }
    EXPECT_LT(worst, 1e-3);
    // In fact the energy does not drift: the state is float and each tick rounds it by
    // half an ulp (6e-8), a random walk that 60000 ticks take to about sqrt(60000)·1e-7
    // = 2.4e-5 of the energy; the propagator's rounded coefficients add no systematic gain
    // (tether_propagator.hpp).
    EXPECT_LT(worst, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(LinearAndPiecewise, EnergyOverAMinute,
                         ::testing::Values(std::make_tuple(5000, 5000, 0), std::make_tuple(9000, 1500, 0),
                                           std::make_tuple(4000, 7000, 900)));

// --- the coupled loop on every profile -------------------------------------------------------------

struct LoopRun {
    double first_swing = 0;  // handle peak-to-peak over the first second
    double last_swing = 0;   // over the last second
    double last_force = 0;   // largest |force| over the last second
    bool finite = true;
};

LoopRun run_loop(const sim::DeviceProfile& profile, sim::Grip grip, const EffectParams& p, int seconds = 4) {
    const EngineConfig config = sim::engine_config_for(profile);
    Engine engine(config);
    sim::SimDevice device(profile, grip, sim::TargetMotion::hold_at({0.0}));
    const CreateResult created = engine.create(p);
    EXPECT_TRUE(created.error.ok()) << created.error.message();
    EXPECT_TRUE(engine.start(created.id).ok());
    LoopRun run;
    std::vector<double> x;
    const int ticks = seconds * 1000;
    for (int n = 0; n < ticks; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        device.sense(in);
        TickOutput out;
        engine.tick(in, out);
        device.step(out.force, 1e-3);
        for (int a = 0; a < kMaxAxes; ++a) run.finite = run.finite && std::isfinite(out.force[a]);
        run.finite = run.finite && std::isfinite(out.mass_position[0]) && std::isfinite(out.mass_velocity[0]);
        x.push_back(device.position(0));
        if (n >= ticks - 1000) run.last_force = std::max(run.last_force, static_cast<double>(std::fabs(out.force[0])));
    }
    auto swing = [&](int from, int to) {
        const auto [lo, hi] = std::minmax_element(x.begin() + from, x.begin() + to);
        return *hi - *lo;
    };
    run.first_swing = swing(0, 1000);
    run.last_swing = swing(ticks - 1000, ticks);
    return run;
}

// The extremes: the lightest and the heaviest mass on the stiffest tether, undamped and at
// full tether damping, kicked at full intensity.
std::vector<ControlLawBlock> extreme_laws() {
    std::vector<ControlLawBlock> laws;
    for (int32_t mass : {1, 10000}) {
        for (int32_t b : {0, 10000}) {
            ControlLawBlock c = law_block(mass, 10000, b);
            c.vel_init = 10000;
            laws.push_back(c);
        }
    }
    ControlLawBlock dragged = law_block(10000, 10000, 0);
    dragged.drag = 10000;
    dragged.vel_init = 10000;
    laws.push_back(dragged);
    return laws;
}

TEST(CoupledLoop, StableOnEveryProfileAtTheExtremesFreeAndGripped) {
    for (const sim::DeviceProfile& profile : sim::device_profiles()) {
        if (!(profile.supported_types & effect_type_bit(EffectType::dynamic_control_law))) continue;  // I-FORCE 1.x: no Dynamics
        const double count = sim::engine_config_for(profile).sensor_step;
        for (sim::Grip grip : {sim::Grip::none, sim::Grip::loose, sim::Grip::firm, sim::Grip::stiff}) {
            for (const ControlLawBlock& law : extreme_laws()) {
                const LoopRun run = run_loop(profile, grip, control_law_params(law));
                const std::string what = std::string(profile.name) + " grip " + std::string(sim::grip_name(grip)) +
                                         " mass " + std::to_string(law.mass) + " b " + std::to_string(law.b) +
                                         " drag " + std::to_string(law.drag);
                ASSERT_TRUE(run.finite) << what;
                SCOPED_TRACE(what + ": swing first " + std::to_string(run.first_swing) + " last " +
                             std::to_string(run.last_swing) + ", force last " + std::to_string(run.last_force));
                // Nothing grows: after three seconds the handle swings at most a quarter of
                // what the kick did, or sits within a few sensor counts.
                EXPECT_LE(run.last_swing, std::max(3 * count, 0.25 * run.first_swing)) << what;
                if (law.b > 0 || law.drag > 0) {
                    // A damped tether has given all it had: the handle is at rest.
                    EXPECT_LE(run.last_swing, 2 * count) << what;
                    EXPECT_LT(run.last_force, 0.02 * kFullScale) << what;
                }
            }
        }
    }
}

TEST(CoupledLoop, AFullRecoilOnTheHeaviestMassSettlesWithAFreeHandle) {
    // The strongest undamped recoil the ranges allow, on two axes at once, with nothing
    // holding the handle.
    for (const sim::DeviceProfile& profile : sim::device_profiles()) {
        if (profile.axis_count < 2) continue;  // recoil plays on x and y
        if (!(profile.supported_types & effect_type_bit(EffectType::dynamic_recoil))) continue;  // I-FORCE 1.x: no Dynamics
        const LoopRun run = run_loop(profile, sim::Grip::none, recoil_params(4500, 10000, 10000, 10000, 0));
        ASSERT_TRUE(run.finite) << profile.name;
        EXPECT_LE(run.last_swing, std::max(3.0 * sim::engine_config_for(profile).sensor_step, 0.25 * run.first_swing))
            << profile.name;
    }
}

}  // namespace
}  // namespace feel::test
