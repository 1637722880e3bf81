// Dynamic Sling (§5.8): a ball on a string tied to the handle, against the centripetal
// law, the conservation of energy and the exact decay of a ball in a viscous medium.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ball_rig.hpp"
#include "dynamics/ball_tick.hpp"

namespace feel::test {
namespace {

struct SlingPhysics {
    double m, k, L, c;
    double omega() const { return std::sqrt(k / m); }
};

SlingPhysics sling_physics_of(const EffectParams& p, const EngineConfig& c) {
    const DynamicBlock& d = p.dynamic;
    return {scaled(d.ball_mass, c.dynamic_mass_ref), scaled(d.string_compliance, c.dynamic_stiffness_ref),
            static_cast<double>(d.string_length), scaled(d.ball_damping, c.dynamic_damping_ref)};
}

// Puts the ball at (x, y) moving at (vx, vy), as if the last tick had sensed the handle
// at the rig's position, moving at the rig's velocity.
void place_ball(BallRig& rig, double x, double y, double vx, double vy) {
    rig.state.initialized = true;
    rig.state.ball.now.offset[0] = static_cast<float>(x - rig.position[0]);
    rig.state.ball.now.offset[1] = static_cast<float>(y - rig.position[1]);
    rig.state.ball.now.velocity[0] = static_cast<float>(vx);
    rig.state.ball.now.velocity[1] = static_cast<float>(vy);
    for (int a = 0; a < kMaxAxes; ++a) {
        rig.state.ball.handle[a] = rig.position[a];
        rig.state.ball.handle_velocity[a] = rig.velocity[a];
    }
}

double energy(const SlingPhysics& s, const detail::BallState& state) {
    const detail::BallMotion& b = state.now;
    const double r = norm2(b.offset[0], b.offset[1]);
    const double stretch = std::max(0.0, r - s.L);
    return 0.5 * s.m * (b.velocity[0] * b.velocity[0] + b.velocity[1] * b.velocity[1]) + 0.5 * s.k * stretch * stretch;
}

TEST(Sling, StartsHangingAtTheBobbinAndIsSlackWithinItsLength) {
    BallRig rig(detail::sling_dynamic, sling_params(5000, 3000, 5000, 0));
    rig.position[0] = 1234;
    rig.position[1] = -777;
    const auto first = rig.tick(0);
    EXPECT_EQ(first.force[0], 0.0);
    EXPECT_EQ(first.force[1], 0.0);
    EXPECT_EQ(first.result.mass_position[0], 0.0f);
    EXPECT_EQ(first.result.mass_position[1], 0.0f);
    // Walk the handle 2900 units away (less than the string) over 1 s: nothing pulls, and
    // the ball stays where it hung.
    for (int i = 1; i <= 1000; ++i) {
        rig.position[0] = static_cast<float>(1234 + 2.9 * i);
        const auto t = rig.tick(kBallTickS);
        ASSERT_EQ(t.force[0], 0.0);
        ASSERT_EQ(t.force[1], 0.0);
        ASSERT_FALSE(t.result.finished);
        EXPECT_DOUBLE_EQ(ball_position(rig, 0), 1234.0);
        EXPECT_DOUBLE_EQ(ball_position(rig, 1), -777.0);
    }
}

TEST(Sling, ATautStringPullsTheHandleTowardTheBall) {
    // On the engine's first tick the force is the string's instantaneous pull, k·(|r| − L)
    // along r. After that it is the mean pull over the coming tick: for a ball let go at
    // rest the stretch s0 shrinks as s0·(1 − ½ω²t²), so the second tick (the mean over
    // [T, 2T]) pulls k·s0·(1 − (7/6)·(ω·T)²), and the ball has fallen ½·(k·s0/m)·T².
    for (const double bx : {-3000.0, 1000.0, 4000.0}) {
        BallRig rig(detail::sling_dynamic, sling_params(5000, 3000, 5000, 0));
        const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
        const double by = -2000;
        place_ball(rig, bx, by, 0, 0);
        const double r = norm2(bx, by);
        const double pull = r > s.L ? s.k * (r - s.L) : 0.0;
        const auto now = rig.tick(0);
        // Float (issue 14): the scales, the distance, the ratio and the pull each round by
        // up to 2^-24, a few ulps of the pull.
        EXPECT_NEAR(now.force[0], pull * bx / r, 1e-6 * (1 + pull)) << bx;
        EXPECT_NEAR(now.force[1], pull * by / r, 1e-6 * (1 + pull)) << bx;
        const auto next = rig.tick(kBallTickS);
        const double shrink = 7.0 / 6.0 * std::pow(s.omega() * kBallTickS, 2);
        EXPECT_NEAR(next.force[0], pull * (1 - shrink) * bx / r, 0.1 * shrink * pull + 1e-9) << bx;
        EXPECT_NEAR(next.force[1], pull * (1 - shrink) * by / r, 0.1 * shrink * pull + 1e-9) << bx;
        const double fallen = norm2(next.result.mass_position[0] - bx, next.result.mass_position[1] - by);
        EXPECT_NEAR(fallen, 0.5 * pull / s.m * kBallTickS * kBallTickS, 0.05 * pull / s.m * kBallTickS * kBallTickS + 1e-3) << bx;
    }
}

// Engine::update of a playing sling's string, without restart: the ball stays where it is
// and the next tick pulls as the new string does (the sling keeps its law worked out
// between ticks, so the update must reach it). A heavy ball on a soft string (ω = 21 rad/s)
// stays within a few units of where it hung while the handle, moved 3000 units off, holds
// still: the pull is k·(3000 − L) toward it, within the ball's fall of k·s/m·t²/2.
TEST(Sling, AStringUpdatedWhileItPullsPullsAsTheNewString) {
    const EngineConfig config{};
    Engine engine(config);
    EffectParams p = sling_params(10000, 1000, 1000, 0);
    const CreateResult created = engine.create(p);
    ASSERT_TRUE(created.error.ok());
    ASSERT_TRUE(engine.start(created.id).ok());
    int64_t t_us = 0;
    const auto force_x = [&](float x) {
        TickInput in;
        in.t_us = t_us;
        in.position[0] = x;
        TickOutput out;
        engine.tick(in, out);
        t_us += 1000;
        return static_cast<double>(out.force[0]);
    };
    force_x(0);
    force_x(3000);  // the jump: its prediction has the handle going on at 3000 units a tick
    const double k = scaled(p.dynamic.string_compliance, config.dynamic_stiffness_ref);
    EXPECT_NEAR(force_x(3000), -k * (3000 - 1000), 0.01 * k * 2000);
    p.dynamic.string_length = 2000;
    ASSERT_TRUE(engine.update(created.id, p, effect_field::kTypeSpecific, false).ok());
    EXPECT_NEAR(force_x(3000), -k * (3000 - 2000), 0.01 * k * 1000);
    p.dynamic.string_compliance = 3000;
    ASSERT_TRUE(engine.update(created.id, p, effect_field::kTypeSpecific, false).ok());
    const double stiffer = scaled(p.dynamic.string_compliance, config.dynamic_stiffness_ref);
    EXPECT_NEAR(force_x(3000), -stiffer * (3000 - 2000), 0.01 * stiffer * 1000);
    EXPECT_EQ(engine.state(created.id), EffectState::playing);
}

// A ball circling a still handle at speed u on radius R with k·(R − L) = m·u²/R.
double orbit_radius(const SlingPhysics& s, double u) {
    return (s.L + std::sqrt(s.L * s.L + 4 * s.m * u * u / s.k)) / 2;
}

TEST(Sling, CirclesAStillHandleWithTheCentripetalPull) {
    BallRig rig(detail::sling_dynamic, sling_params(5000, 3000, 5000, 0));
    const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
    const double u = 20000;
    const double R = orbit_radius(s, u);
    place_ball(rig, R, 0, 0, u);
    const double centripetal = s.m * u * u / R;
    double t = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto tick = rig.tick(kBallTickS);
        t += kBallTickS;
        EXPECT_NEAR(norm2(tick.force[0], tick.force[1]), centripetal, 1e-3 * centripetal) << t;
        EXPECT_NEAR(norm2(tick.result.mass_position[0], tick.result.mass_position[1]), R, 1e-3 * (R - s.L));
    }
    // Uniform motion: after t the ball has turned u·t/R.
    const double angle = std::atan2(ball_position(rig, 1), ball_position(rig, 0));
    EXPECT_NEAR(std::remainder(angle - u * t / R, 2 * kBallPi), 0.0, 1e-3);
}

TEST(Sling, SpinningFasterPullsHarder) {
    double pull[2] = {};
    const double speeds[2] = {15000, 30000};
    for (int i = 0; i < 2; ++i) {
        BallRig rig(detail::sling_dynamic, sling_params(5000, 3000, 5000, 0));
        const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
        place_ball(rig, orbit_radius(s, speeds[i]), 0, 0, speeds[i]);
        double sum = 0;
        for (int n = 0; n < 1000; ++n) {
            const auto t = rig.tick(kBallTickS);
            sum += norm2(t.force[0], t.force[1]);
        }
        pull[i] = sum / 1000;
        EXPECT_NEAR(pull[i], s.m * speeds[i] * speeds[i] / orbit_radius(s, speeds[i]), 1e-3 * pull[i]);
    }
    // Twice the speed, a little more than twice the radius: close to four times the pull.
    EXPECT_GT(pull[1], 3.5 * pull[0]);
}

TEST(Sling, AHandleCirclingDrivesTheBallOnALargerCircle) {
    // No air resistance: the ball can turn with the handle (rate Ω, radius a) on the same
    // ray, radius ρ, where the string's pull k·(ρ − a − L) is the centripetal m·Ω²·ρ:
    // ρ = k·(a + L)/(k − m·Ω²).
    BallRig rig(detail::sling_dynamic, sling_params(5000, 3000, 5000, 0));
    const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
    const double a = 2000;
    const double Omega = 2 * kBallPi * 1.0;
    ASSERT_GT(s.k, s.m * Omega * Omega);
    const double rho = s.k * (a + s.L) / (s.k - s.m * Omega * Omega);
    rig.position[0] = static_cast<float>(a);
    rig.velocity[1] = static_cast<float>(a * Omega);
    place_ball(rig, rho, 0, 0, Omega * rho);
    const double pull = s.m * Omega * Omega * rho;
    for (int i = 1; i <= 3000; ++i) {
        const double t = i * kBallTickS;
        rig.position[0] = static_cast<float>(a * std::cos(Omega * t));
        rig.position[1] = static_cast<float>(a * std::sin(Omega * t));
        rig.velocity[0] = static_cast<float>(-a * Omega * std::sin(Omega * t));
        rig.velocity[1] = static_cast<float>(a * Omega * std::cos(Omega * t));
        const auto tick = rig.tick(kBallTickS);
        EXPECT_NEAR(norm2(tick.force[0], tick.force[1]), pull, 2e-3 * pull) << t;
        // Radially outward, toward the ball on the handle's ray: the mean over the coming
        // tick, so along the ray half a tick ahead (the handle's path between ticks is a
        // chord of its circle, and the coming tick is predicted along the last chord).
        EXPECT_NEAR(tick.force[0] / pull, std::cos(Omega * (t + kBallTickS / 2)), 2e-3) << t;
        EXPECT_NEAR(tick.force[1] / pull, std::sin(Omega * (t + kBallTickS / 2)), 2e-3) << t;
    }
}

TEST(Sling, TheHandleFeelsEveryImpulseTheStringGives) {
    // Newton's third law: over any stretch of ticks the force the motor holds, times the
    // tick, is minus the momentum the string gave the ball; without air that is the
    // ball's whole change of momentum. Exact while the hand moves steadily, as the
    // prediction assumes: here it drags the ball from hanging, across the travel.
    BallRig rig(detail::sling_dynamic, sling_params(3000, 1500, 7000, 0));
    const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
    const double ux = 6000, uy = -3500;  // position units/s
    rig.position[0] = -6000;
    rig.position[1] = 3500;
    rig.velocity[0] = static_cast<float>(ux);
    rig.velocity[1] = static_cast<float>(uy);
    rig.tick(0);
    double start[2] = {}, impulse[2] = {};
    for (int i = 1; i <= 2000; ++i) {
        // Steps of 6 and 3.5 units, which float holds exactly: a perfectly steady hand.
        rig.position[0] = static_cast<float>(-6000 + ux * i * kBallTickS);
        rig.position[1] = static_cast<float>(3500 + uy * i * kBallTickS);
        const auto tick = rig.tick(kBallTickS);
        if (i == 1) {
            start[0] = rig.state.ball.now.velocity[0];
            start[1] = rig.state.ball.now.velocity[1];
        }
        if (i < 2000) {  // the force of tick i acts until tick i + 1
            impulse[0] += tick.force[0] * kBallTickS;
            impulse[1] += tick.force[1] * kBallTickS;
        }
    }
    for (int a = 0; a < 2; ++a) {
        const double change = s.m * (rig.state.ball.now.velocity[a] - start[a]);
        EXPECT_NEAR(impulse[a], -change, 1e-6 * s.m * 6000) << a;
    }
    EXPECT_GT(ball_position(rig, 0), 0.0) << "the string dragged the ball across";
}

TEST(Sling, EnergyIsKeptWithAStillHandleAndNoAirResistance) {
    // A stiff string on a light ball (ω·tick ≈ 0.45, so the tick is cut into steps), thrown
    // so that it swings through slack and taut for 60 s. Verlet keeps a shadow energy
    // exactly; the true energy ripples about it by about (ω·h)²/2 < 1e-3 (h·ω <= 0.044),
    // and does not drift.
    BallRig rig(detail::sling_dynamic, sling_params(100, 2000, 10000, 0));
    const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
    ASSERT_GT(s.omega() * kBallTickS, 0.1);
    place_ball(rig, 1.3 * s.L, 0, 3000, 9000);
    const double e0 = energy(s, rig.state.ball);
    double worst = 0;
    double first_10s = 0, last_10s = 0;
    int taut_ticks = 0;
    for (int i = 0; i < 60000; ++i) {
        const auto t = rig.tick(kBallTickS);
        taut_ticks += t.force[0] != 0 || t.force[1] != 0;
        const double e = energy(s, rig.state.ball) / e0 - 1;
        worst = std::max(worst, std::fabs(e));
        if (i < 10000) first_10s += e / 10000;
        if (i >= 50000) last_10s += e / 10000;
    }
    EXPECT_LT(worst, 1e-3);
    EXPECT_LT(std::fabs(last_10s - first_10s), 1e-4) << "no drift";
    EXPECT_GT(taut_ticks, 1000);
    EXPECT_LT(taut_ticks, 59000) << "the ball should also fly slack";
}

TEST(Sling, AStringOfNoLengthSwingsAsASpringToTheStatedPhaseError) {
    // With L = 0 the string is a linear spring: a ball let go at rest at x0 beside a still
    // handle, without air, swings as x0·cos(ω·t) exactly. The steps (h·ω <= 0.044) run at
    // Verlet's rate (2/h)·asin(ω·h/2), ahead of ω by at most (ω·h)²/24 = 8.1e-5 of it, so the
    // ball is within x0·ω·t·8.1e-5 of the exact motion at every tick (plus float's rounding).
    // A string of the busy mix's ω (82 rad/s: 2 steps a tick) and a stiffer one on a lighter ball
    // (233 rad/s: 6 steps).
    for (const int32_t compliance : {3000, 10000}) {
        const int32_t mass = compliance == 3000 ? 2000 : 830;
        BallRig rig(detail::sling_dynamic, sling_params(mass, 0, compliance, 0));
        const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
        const double x0 = 3000;
        place_ball(rig, x0, 0, 0, 0);
        const double lead_per_radian = 0.044 * 0.044 / 24;
        double worst = 0;
        for (int i = 1; i <= 2000; ++i) {
            rig.tick(kBallTickS);
            const double t = i * kBallTickS;
            const double off = std::fabs(ball_position(rig, 0) - x0 * std::cos(s.omega() * t));
            worst = std::max(worst, off / (x0 * s.omega() * t * lead_per_radian + 0.05));
            ASSERT_LE(off, x0 * s.omega() * t * lead_per_radian + 0.05) << compliance << " at " << t;
            ASSERT_NEAR(ball_position(rig, 1), 0.0, 1e-3);
        }
        EXPECT_GT(worst, 0.3) << "the phase error is Verlet's, not hidden by a loose bound";
    }
}

TEST(Sling, AirResistanceSlowsAFreeBallExponentially) {
    // Inside its string's reach the ball only feels the air: v(t) = u·e^{−c·t/m} exactly.
    BallRig rig(detail::sling_dynamic, sling_params(5000, 9000, 5000, 2000));
    const SlingPhysics s = sling_physics_of(rig.params(), rig.config());
    const double u = 10000;
    ASSERT_LT(u * s.m / s.c, s.L) << "the ball must stay inside the string's reach";
    place_ball(rig, 0, 0, u, 0);
    for (int i = 1; i <= 200; ++i) {
        const auto t = rig.tick(kBallTickS);
        EXPECT_EQ(t.force[0], 0.0);
        // The air's factor e^(−c·h/2m) is float (issue 14): off by up to 2^-24 relative, applied
        // twice a step, one step a tick here: 2·i·2^-24 at tick i, at worst.
        EXPECT_NEAR(rig.state.ball.now.velocity[0], u * std::exp(-s.c / s.m * i * kBallTickS), (2 * i + 1) * 0x1p-24 * u);
        // Position: the integral, to the splitting's (c·h/m)²/24.
        const double x = u * s.m / s.c * (1 - std::exp(-s.c / s.m * i * kBallTickS));
        EXPECT_NEAR(ball_position(rig, 0), x, 1e-4 * x);
    }
}

TEST(Sling, TheAirsFactorIsTheExponentialToTwoUlps) {
    // ball_decay: e^(−x) of + and * only (the same bits on x86 and the board), against
    // double exp on a dense grid over float's range, and its limits.
    double worst_ulps = 0;
    for (float x = 0; x < 87.0f; x = x < 1e-3f ? x + 1e-6f : x * 1.0001f) {
        const double want = std::exp(-static_cast<double>(x));
        const double ulp = std::ldexp(1.0, std::ilogb(want) - 23);
        worst_ulps = std::max(worst_ulps, std::fabs(detail::ball_decay(x) - want) / ulp);
    }
    EXPECT_LE(worst_ulps, 2.0);
    EXPECT_EQ(detail::ball_decay(0.0f), 1.0f);
    EXPECT_EQ(detail::ball_decay(87.0f), 0.0f);
    EXPECT_EQ(detail::ball_decay(std::numeric_limits<float>::infinity()), 0.0f);
    EXPECT_TRUE(std::isnan(detail::ball_decay(std::numeric_limits<float>::quiet_NaN())));
}

TEST(Sling, TheTickRateDoesNotChangeTheMotion) {
    // Spun up from hanging at the bobbin by a handle circling at 1.5 Hz, with some air:
    // the ball after 2 s at three tick rates. The handle's path between ticks is a chord of
    // its circle, (Ω·dt)²/8 of its radius off; the ball's error is of that order.
    double x[3] = {}, y[3] = {};
    const double dts[3] = {1e-3, 0.5e-3, 0.25e-3};
    for (int k = 0; k < 3; ++k) {
        BallRig rig(detail::sling_dynamic, sling_params(4000, 2500, 6000, 300));
        const double a = 3000, Omega = 2 * kBallPi * 1.5;
        rig.position[0] = static_cast<float>(a);
        rig.tick(0);
        const int n = static_cast<int>(std::lround(2.0 / dts[k]));
        for (int i = 1; i <= n; ++i) {
            const double t = i * dts[k];
            rig.position[0] = static_cast<float>(a * std::cos(Omega * t));
            rig.position[1] = static_cast<float>(a * std::sin(Omega * t));
            rig.velocity[0] = static_cast<float>(-a * Omega * std::sin(Omega * t));
            rig.velocity[1] = static_cast<float>(a * Omega * std::cos(Omega * t));
            rig.tick(dts[k]);
        }
        x[k] = ball_position(rig, 0);
        y[k] = ball_position(rig, 1);
    }
    EXPECT_GT(norm2(x[2], y[2]), 3000.0) << "spun out beyond the handle's circle";
    EXPECT_NEAR(x[0], x[2], 0.2);
    EXPECT_NEAR(y[0], y[2], 0.2);
    EXPECT_NEAR(x[1], x[2], 0.1);
    EXPECT_NEAR(y[1], y[2], 0.1);
}

TEST(Sling, OnOneAxisItIsABallOnALine) {
    // A ball thrown along x from the bobbin flies the string's length, stretches it by
    // u·√(m/k) and comes back; the handle feels k·stretch toward the ball.
    EffectParams p = sling_params(5000, 2000, 5000, 0);
    p.axis_count = 1;
    BallRig rig(detail::sling_dynamic, p);
    const SlingPhysics s = sling_physics_of(p, rig.config());
    const double u = 15000;
    place_ball(rig, 0, 0, u, 0);
    double reach = 0, pull = 0;
    for (int i = 0; i < 400; ++i) {
        const auto t = rig.tick(kBallTickS);
        EXPECT_EQ(t.force[1], 0.0);
        EXPECT_EQ(t.result.mass_position[1], 0.0f);
        reach = std::max(reach, static_cast<double>(t.result.mass_position[0]));
        pull = std::max(pull, t.force[0]);
    }
    const double stretch = u * std::sqrt(s.m / s.k);
    EXPECT_NEAR(reach, s.L + stretch, 1e-3 * stretch);
    EXPECT_NEAR(pull, s.k * stretch, 1e-3 * s.k * stretch);
}

TEST(Sling, TheOrderOfTheAxesDoesNotMatter) {
    EffectParams yx = sling_params(5000, 2000, 5000, 100);
    yx.axes[0] = Axis::y;
    yx.axes[1] = Axis::x;
    BallRig a(detail::sling_dynamic, sling_params(5000, 2000, 5000, 100));
    BallRig b(detail::sling_dynamic, yx);
    for (int i = 0; i < 1500; ++i) {
        const double t = i * kBallTickS;
        for (BallRig* r : {&a, &b}) {
            r->position[0] = static_cast<float>(3000 * std::sin(9 * t));
            r->position[1] = static_cast<float>(2000 * std::cos(5 * t) - 2000);
        }
        const auto ta = a.tick(i == 0 ? 0 : kBallTickS);
        const auto tb = b.tick(i == 0 ? 0 : kBallTickS);
        ASSERT_NEAR(ta.force[0], tb.force[0], 1e-9 * (1 + std::fabs(ta.force[0])));
        ASSERT_NEAR(ta.force[1], tb.force[1], 1e-9 * (1 + std::fabs(ta.force[1])));
        ASSERT_FALSE(ta.result.finished);
    }
}

// Two slings rendered together (sling_pair_dynamic: their Verlet steps interleaved) move,
// pull and report exactly as each rendered alone: a sling's ball knows nothing of another.
// Different strings (different step counts), one axis beside two, a start a few ticks
// later, stalls and repeated timestamps, and stretches of a still handle where a ball left
// at rest takes the short way alone, and its idle advances beside a swinging one.
TEST(Sling, TwoSlingsTogetherMoveExactlyAsEachAlone) {
    struct Case {
        EffectParams a, b;
    };
    EffectParams one_axis = sling_params(1500, 800, 9000, 200);
    one_axis.axis_count = 1;
    const Case cases[] = {{sling_params(2000, 1500, 3000, 500), sling_params(2000, 1500, 3000, 500)},
                          {sling_params(500, 0, 10000, 0), sling_params(9000, 2500, 1000, 3000)},
                          {one_axis, sling_params(4000, 1200, 6000, 100)},
                          // a's string longer than the hand's reach: its ball never moves, and
                          // rests whenever the hand holds still while b swings on
                          {sling_params(2000, 10000, 3000, 500), sling_params(2000, 1500, 3000, 500)}};
    const EngineConfig config{};
    for (const Case& k : cases) {
        const detail::SlotDynamicBlock block_a = detail::slot_dynamic_block(k.a);
        const detail::SlotDynamicBlock block_b = detail::slot_dynamic_block(k.b);
        const detail::SlotParams pa = detail::slot_params(k.a, &block_a);
        const detail::SlotParams pb = detail::slot_params(k.b, &block_b);
        detail::DynamicState alone_a{}, alone_b{}, together_a{}, together_b{};
        float position[kMaxAxes] = {}, velocity[kMaxAxes] = {};
        const float acceleration[kMaxAxes] = {};
        const float start[kMaxAxes] = {};
        for (int i = 0; i < 3000; ++i) {
            const double t = i * kBallTickS;
            const bool still = (i / 400) % 3 == 2;  // 400 ticks of every 1200 the hand holds still
            if (!still) {
                position[0] = static_cast<float>(std::round(4000 * std::cos(7 * t) + 300 * std::sin(90 * t)));
                position[1] = static_cast<float>(std::round(4000 * std::sin(7 * t)));
                velocity[0] = static_cast<float>(-28000 * std::sin(7 * t));
                velocity[1] = static_cast<float>(28000 * std::cos(7 * t));
            } else {
                velocity[0] = velocity[1] = 0;
            }
            const float dt = static_cast<float>(i == 0 ? 0 : i % 97 == 0 ? 0.25 : i % 89 == 0 ? 0 : kBallTickS);
            const bool b_plays = i >= 5;
            using Context = detail::DynamicContext;
            const Context a1{&pa, &config, position, velocity, acceleration, start, dt, 0, &alone_a};
            const Context b1{&pb, &config, position, velocity, acceleration, start, dt, 0, &alone_b};
            const Context a2{&pa, &config, position, velocity, acceleration, start, dt, 0, &together_a};
            const Context b2{&pb, &config, position, velocity, acceleration, start, dt, 0, &together_b};
            float fa1[kMaxAxes] = {}, fb1[kMaxAxes] = {}, fa2[kMaxAxes] = {}, fb2[kMaxAxes] = {};
            detail::DynamicResult ra1, rb1, ra2, rb2;
            detail::sling_dynamic(a1, fa1, ra1);
            if (b_plays) {
                detail::sling_dynamic(b1, fb1, rb1);
                detail::sling_pair_dynamic(a2, b2, fa2, fb2, ra2, rb2);
            } else {
                detail::sling_dynamic(a2, fa2, ra2);
            }
            for (int ax = 0; ax < kMaxAxes; ++ax) {
                ASSERT_EQ(fa1[ax], fa2[ax]) << "case " << (&k - cases) << " tick " << i << " axis " << ax;
                ASSERT_EQ(fb1[ax], fb2[ax]) << "case " << (&k - cases) << " tick " << i << " axis " << ax;
                ASSERT_EQ(ra1.mass_position[ax], ra2.mass_position[ax]) << "case " << (&k - cases) << " tick " << i;
                ASSERT_EQ(rb1.mass_velocity[ax], rb2.mass_velocity[ax]) << "case " << (&k - cases) << " tick " << i;
                ASSERT_EQ(alone_a.ball.now.offset[ax], together_a.ball.now.offset[ax])
                    << "case " << (&k - cases) << " tick " << i;
                if (b_plays) {  // before its first tick b's ball is not the live member of its state
                    ASSERT_EQ(alone_b.ball.now.velocity[ax], together_b.ball.now.velocity[ax])
                        << "case " << (&k - cases) << " tick " << i;
                }
            }
        }
        // The motion was real: both balls were swung out beyond their strings.
        EXPECT_GT(std::fabs(alone_a.ball.now.offset[0]) + std::fabs(alone_b.ball.now.offset[0]), 100.0);
    }
}

// Through the engine, which renders two playing slings together (kPairSlings) found along
// a chain of the sling slots the commands keep: after slings are destroyed and their slots
// reused by a condition and by a new sling, the engine's force is still the sum, in slot
// order, of each effect played alone in an engine of its own with the same hand. (A chain
// left stale by destroy would reach the condition's slot as a sling's; one left stale by
// create would skip or misread the new sling.)
TEST(Sling, SlingsPairedByTheEngineAfterDestroysAndCreatesMoveAsEachAlone) {
    EngineConfig config;
    config.axis_count = 2;
    config.max_effects = 6;
    const EffectParams a = sling_params(3000, 1200, 4000, 300);
    const EffectParams b = sling_params(2000, 800, 6000, 100);
    const EffectParams c = sling_params(5000, 1500, 3000, 600);
    const EffectParams d = sling_params(1500, 600, 8000, 200);
    EffectParams spring;
    spring.type = EffectType::spring;
    spring.axis_count = 2;
    spring.axes[0] = Axis::x;
    spring.axes[1] = Axis::y;
    for (ConditionBlock& block : spring.conditions) block.pos_coefficient = block.neg_coefficient = 500;

    Engine together(config);
    // One engine per effect (b's is emptied at tick 500 and given b again at 1100).
    Engine alone_a(config), alone_spring(config), alone_c(config), alone_d(config), alone_b(config);
    const auto create_and_start = [](Engine& engine, EffectParams p) {
        p.gain = 2000;  // the sum stays below the device's maximum
        const CreateResult r = engine.create(p, {});
        EXPECT_TRUE(r.error.ok());
        EXPECT_TRUE(engine.start(r.id).ok());
        return r.id;
    };
    create_and_start(together, a);
    const EffectId in_b = create_and_start(together, b);
    const EffectId in_c = create_and_start(together, c);
    create_and_start(alone_a, a);
    const EffectId b_alone = create_and_start(alone_b, b);
    const EffectId c_alone = create_and_start(alone_c, c);

    constexpr int kTicks = 1500;
    double largest_force = 0.0;
    for (int tick = 0; tick < kTicks; ++tick) {
        if (tick == 500) {
            ASSERT_TRUE(together.destroy(in_b).ok());
            ASSERT_TRUE(alone_b.destroy(b_alone).ok());
            create_and_start(together, spring);  // into b's slot
            create_and_start(alone_spring, spring);
        }
        if (tick == 800) {
            create_and_start(together, d);  // after c
            create_and_start(alone_d, d);
        }
        if (tick == 1100) {
            // c's slot freed and taken by a sling again, between the spring and d.
            ASSERT_TRUE(together.destroy(in_c).ok());
            ASSERT_TRUE(alone_c.destroy(c_alone).ok());
            create_and_start(together, b);
            create_and_start(alone_b, b);
        }
        TickInput in;
        in.t_us = 1000 * static_cast<int64_t>(tick);
        const double angle = 2 * kBallPi * tick / 400.0;
        in.position[0] = static_cast<float>(std::round(3000 * std::cos(angle)));
        in.position[1] = static_cast<float>(std::round(3000 * std::sin(angle)));
        TickOutput out;
        together.tick(in, out);
        float expected[kMaxAxes] = {};
        for (Engine* engine : {&alone_a, &alone_spring, &alone_c, &alone_d, &alone_b}) {
            TickOutput single;
            engine->tick(in, single);
            for (int ax = 0; ax < 2; ++ax) expected[ax] += single.force[ax];
        }
        for (int ax = 0; ax < 2; ++ax) {
            ASSERT_NEAR(out.force[ax], expected[ax], 1e-3 + 1e-5 * std::fabs(expected[ax]))
                << "tick " << tick << ", axis " << ax;
            largest_force = std::max(largest_force, std::fabs(static_cast<double>(expected[ax])));
        }
    }
    EXPECT_GT(largest_force, 100.0);  // the slings pulled
}

// Random parameters across their whole ranges, and a random hand: jumps across the
// travel, jitter, stalls, repeated timestamps. Nothing may become NaN or infinite. (The
// force is the mean pull over the coming tick, along a string that turns during it, so it
// need not point at the ball of now.)
RC_GTEST_PROP(SlingProperty, StaysFiniteForAnyParametersAndHand, ()) {
    EffectParams p = sling_params(*rc::gen::inRange(1, 10001), *rc::gen::inRange(0, 10001),
                                  *rc::gen::inRange(1, 10001), *rc::gen::inRange(0, 10001));
    p.axis_count = *rc::gen::inRange(1, 4);
    p.axes[2] = Axis::z;
    BallRig rig(detail::sling_dynamic, p);
    const int ticks = *rc::gen::inRange(50, 400);
    for (int i = 0; i < ticks; ++i) {
        const int kind = *rc::gen::inRange(0, 20);
        double dt = *rc::gen::inRange(50, 20000) * 1e-6;
        if (kind == 0) dt = 0;
        if (kind == 1) dt = 0.5;
        for (int a = 0; a < 3; ++a) {
            if (kind < 6) rig.position[a] = static_cast<float>(*rc::gen::inRange(-10000, 10001));
            rig.velocity[a] = static_cast<float>(*rc::gen::inRange(-300000, 300001));
        }
        const auto t = rig.tick(i == 0 ? 0 : dt);
        for (int a = 0; a < kMaxAxes; ++a) {
            RC_ASSERT(std::isfinite(t.force[a]));
            RC_ASSERT(std::isfinite(t.result.mass_position[a]));
            RC_ASSERT(std::isfinite(t.result.mass_velocity[a]));
        }
        RC_ASSERT(!t.result.finished);
    }
}

}  // namespace
}  // namespace feel::test
