// dynamic_recoil (§5.3), the §8.4 mapping BlastIntensity → VelInit (split by BlastDirection),
// DynamicMass → Mass, BlastResonance → KPos = KNeg, BlastDecay → B, against a held handle.
#include <gtest/gtest.h>

#include <cmath>

#include "tether_fixture.hpp"

namespace feel::test {
namespace {

struct Kick {
    double m, k, b, vx, vy;  // the control law §8.4 makes of a recoil or an impact
};

// The §8.4 mapping, by hand: a compass angle θ names where the kick comes from, so the
// mass is launched along −(sin θ, cos θ) (docs/conventions.md, docs/dynamics.md).
Kick recoil_kick(const EngineConfig& c, int32_t direction, int32_t intensity, int32_t mass, int32_t resonance,
                 int32_t decay) {
    const double theta = direction / 100.0 * kPiD / 180.0;
    const double v = per_10000(intensity, c.velocity_ref);
    return {per_10000(mass, c.dynamic_mass_ref), per_10000(resonance, c.dynamic_stiffness_ref),
            per_10000(decay, c.dynamic_damping_ref), -v * std::sin(theta), -v * std::cos(theta)};
}

// Plays the recoil against a handle held at the centre and checks every tick of both axes
// against the damped oscillator of each axis (mean tether pull over the tick).
void expect_kick_trace(const EffectParams& p, const Kick& kick, int ticks) {
    DynamicRig rig;
    rig.tick({0, 0});
    rig.play(p);
    const Oscillator ox{kick.m, kick.b, kick.k, 0, kick.vx};
    const Oscillator oy{kick.m, kick.b, kick.k, 0, kick.vy};
    const double T = rig.period_s();
    for (int n = 0; n < ticks; ++n) {
        const double t = n * T;
        const TickOutput out = rig.tick({0, 0});
        const Oscillator* axes[2] = {&ox, &oy};
        for (int a = 0; a < 2; ++a) {
            const Oscillator& o = *axes[a];
            const double pull =
                mean_over([&](double u) { return kick.k * o.position(u) + kick.b * o.velocity(u); }, t, t + T);
            ASSERT_NEAR(out.force[a], std::clamp(pull, -10000.0, 10000.0), 0.02 + 1e-6 * std::fabs(pull))
                << "axis " << a << " t=" << t;
            ASSERT_NEAR(out.mass_position[a], o.position(t), 1e-3 + 1e-6 * std::fabs(o.v0) / o.omega0())
                << "axis " << a << " t=" << t;
        }
    }
}

TEST(Recoil, IsTheControlLawOfTheTable) {
    const EngineConfig c;
    for (int32_t direction : {0, 9000, 13500, 21000, 31500}) {
        const EffectParams p = recoil_params(direction, 5000, 6000, 7000, 2500);
        expect_kick_trace(p, recoil_kick(c, direction, 5000, 6000, 7000, 2500), 800);
    }
}

TEST(Recoil, TheKickComesFromTheBlastDirection) {
    // Fired ahead (0), the weapon kicks back toward the user: the handle's first pull is
    // toward −y, as a force coming from 0. From the right (9000) it pulls toward −x.
    struct Case {
        int32_t direction, intensity;
        double sx, sy;  // expected signs of the first force on x and y (0: none)
    };
    for (const Case& k : {Case{0, 6000, 0, -1}, Case{9000, 6000, -1, 0}, Case{18000, 6000, 0, 1},
                          Case{27000, 6000, 1, 0}, Case{13500, 6000, -1, 1}, Case{0, -6000, 0, 1}}) {
        DynamicRig rig;
        rig.tick({0, 0});
        rig.play(recoil_params(k.direction, k.intensity, 5000, 5000, 1000));
        const TickOutput out = rig.tick({0, 0});
        const float f[2] = {out.force[0], out.force[1]};
        const double s[2] = {k.sx, k.sy};
        for (int a = 0; a < 2; ++a) {
            if (s[a] == 0) {
                EXPECT_NEAR(f[a], 0.0, 1e-3 * std::fabs(f[1 - a])) << k.direction << " axis " << a;
            } else {
                EXPECT_GT(f[a] * s[a], 100.0) << k.direction << " axis " << a;
            }
        }
        if (k.sx != 0 && k.sy != 0) {
            EXPECT_NEAR(std::fabs(f[0]), std::fabs(f[1]), 1e-3 * std::fabs(f[0]));
        }
    }
}

TEST(Recoil, AHeavierWeaponKicksHarderAsTheSquareRootOfItsMass) {
    // Undamped against a held handle the peak pull is v·sqrt(k·m) (the kick's momentum
    // times the resonance's angular frequency).
    const EngineConfig c;
    double peaks[2] = {};
    const int32_t masses[2] = {1500, 6000};
    for (int i = 0; i < 2; ++i) {
        DynamicRig rig;
        rig.tick({0, 0});
        rig.play(recoil_params(0, 2500, masses[i], 4000, 0));
        for (int n = 0; n < 500; ++n) peaks[i] = std::max(peaks[i], static_cast<double>(-rig.tick({0, 0}).force[1]));
        const Kick k = recoil_kick(c, 0, 2500, masses[i], 4000, 0);
        EXPECT_NEAR(peaks[i], std::fabs(k.vy) * std::sqrt(k.k * k.m), 1e-3 * peaks[i]) << masses[i];
    }
    EXPECT_NEAR(peaks[1] / peaks[0], 2.0, 2e-3);
}

TEST(Recoil, HighResonanceShakesFasterHighDecayDiesSooner) {
    // Blast resonance sets the ring's frequency sqrt(k/m); blast decay its damping: the
    // envelope falls as exp(−b/(2m)·t). Measured from the zero crossings and extrema.
    const EngineConfig c;
    for (const auto& [resonance, decay] : {std::pair{2000, 300}, std::pair{8000, 300}, std::pair{8000, 1500}}) {
        DynamicRig rig;
        rig.tick({0, 0});
        rig.play(recoil_params(0, 4000, 5000, resonance, decay));
        const Kick k = recoil_kick(c, 0, 4000, 5000, resonance, decay);
        const double gamma = k.b / (2 * k.m);
        const double wd = std::sqrt(k.k / k.m - gamma * gamma);
        double prev = 0, last_cross = -1, first_cross = -1;
        int crossings = 0;
        for (int n = 0; n < 3000; ++n) {
            const double s = rig.tick({0, 0}).mass_position[1];
            const double t = n * rig.period_s();
            if (n > 0 && prev != 0 && (prev < 0) != (s < 0) && std::fabs(s - prev) > 1e-3) {
                const double tc = t - rig.period_s() * s / (s - prev);
                if (first_cross < 0) first_cross = tc;
                last_cross = tc;
                ++crossings;
            }
            prev = s;
        }
        ASSERT_GE(crossings, 3);
        EXPECT_NEAR((last_cross - first_cross) / (crossings - 1), kPiD / wd, 1e-3 * kPiD / wd)
            << resonance << "/" << decay;
    }
}

TEST(Recoil, ASettledMassComesToAnExactRestOnceItsEnvelopeIsBelowFloatsRange) {
    // The mass decays as the textbook oscillator; a stretch or velocity below float's
    // smallest normal number (1.2e-38) is flushed to exactly 0 (control_law_dynamic.cpp:
    // subnormal arithmetic is a hundred times slower on x86). Once the textbook envelope,
    // e^(−γt)·|v0|/ωd for the position and (γ + ωd) times that for the velocity, is under
    // 1e-39, the mass is exactly at rest and pulls exactly nothing: not the subnormal tail
    // that would otherwise last until the envelope reaches float's last subnormal (1.4e-45,
    // 0.14 s later here).
    const EngineConfig c;
    const Kick kick = recoil_kick(c, 9000, 5000, 2000, 7000, 3000);
    const Oscillator o{kick.m, kick.b, kick.k, 0, kick.vx};
    const double gamma = o.gamma();
    const double wd = std::sqrt(o.omega0() * o.omega0() - gamma * gamma);
    ASSERT_GT(wd, 0.0) << "underdamped, as the envelope assumes";
    const double amplitude = std::fabs(kick.vx) / wd * (1 + gamma + wd);  // bounds both
    DynamicRig rig;
    rig.tick({0, 0});
    rig.play(recoil_params(9000, 5000, 2000, 7000, 3000));
    const double T = rig.period_s();
    int at_rest = 0;
    for (int n = 0; n < 2000 && at_rest < 50; ++n) {
        const TickOutput out = rig.tick({0, 0});
        if (amplitude * std::exp(-gamma * n * T) >= 1e-39) continue;
        for (int a = 0; a < 2; ++a) {
            ASSERT_EQ(out.mass_position[a], 0.0f) << "axis " << a << " tick " << n;
            ASSERT_EQ(out.mass_velocity[a], 0.0f) << "axis " << a << " tick " << n;
            ASSERT_EQ(out.force[a], 0.0f) << "axis " << a << " tick " << n;
        }
        ++at_rest;
    }
    EXPECT_EQ(at_rest, 50);
}

TEST(Recoil, IsExactlyTheControlLawWithTheMappedIntegers) {
    // §8.4 by construction: fired straight ahead, VelInit is −intensity on y and 0 on x,
    // and a control law with those integers renders the same forces bit for bit.
    const EffectParams recoil = recoil_params(0, 7000, 3000, 6000, 800);
    EffectParams law = control_law_params(law_block(3000, 6000, 800), {Axis::x, Axis::y});
    law.dynamic.control_law[1].vel_init = -7000;
    DynamicRig a, b;
    a.tick({0, 0});
    b.tick({0, 0});
    a.play(recoil);
    b.play(law);
    for (int n = 0; n < 1000; ++n) {
        const double hand = 200 * std::sin(n * 0.01);  // any hand motion
        const TickOutput fa = a.tick({hand, -hand});
        const TickOutput fb = b.tick({hand, -hand});
        ASSERT_EQ(fa.force[0], fb.force[0]) << n;
        ASSERT_EQ(fa.force[1], fb.force[1]) << n;
    }
}

}  // namespace
}  // namespace feel::test

namespace feel::test {
namespace {

TEST(Recoil, OnOneAxisTheSignOfTheIntensityIsTheDirection) {
    // §5.4's Indy car hitting a wall is felt on a wheel: one axis. There the intensity's sign
    // aims the kick: + pulls the handle toward +, like a positive constant force on that
    // axis, exactly as the planar recoil does on x when fired from the west (27000).
    for (int32_t intensity : {6000, -6000}) {
        EffectParams line = recoil_params(0, intensity, 5000, 5000, 1000);
        line.axis_count = 1;
        line.axes[0] = Axis::x;
        DynamicRig on_line;
        on_line.tick({0, 0});
        on_line.play(line);
        DynamicRig in_plane;
        in_plane.tick({0, 0});
        in_plane.play(recoil_params(27000, intensity, 5000, 5000, 1000));
        for (int k = 0; k < 200; ++k) {
            const TickOutput a = on_line.tick({0, 0});
            const TickOutput b = in_plane.tick({0, 0});
            if (k == 0) {
                EXPECT_GT(a.force[0] * (intensity > 0 ? 1.0 : -1.0), 100.0);
            }
            ASSERT_NEAR(a.force[0], b.force[0], 1e-3) << k;
            ASSERT_EQ(a.force[1], 0.0f);
        }
    }
}

TEST(Recoil, OnThreeAxesASphericalDirectionAimsItAsItAimsAWave) {
    // §5.10 speaks of 3D devices. On x, y, z the kick is aimed by a spherical direction and
    // its first pull comes from that direction, like a constant force with the same one.
    EngineConfig config;
    config.axis_count = 3;
    for (const Direction d : {Direction{DirectionKind::spherical, {4500, 6000, 0}},
                              Direction{DirectionKind::spherical, {27000, 13500, 0}}}) {
        EffectParams kick = recoil_params(0, 6000, 5000, 5000, 1000);
        kick.axis_count = 3;
        kick.axes[2] = Axis::z;
        kick.direction = d;
        EffectParams push;
        push.type = EffectType::constant;
        push.duration_us = kInfiniteUs;
        push.axis_count = 3;
        push.axes[0] = Axis::x;
        push.axes[1] = Axis::y;
        push.axes[2] = Axis::z;
        push.direction = d;
        push.constant.magnitude = 5000;
        DynamicRig kicked(config), pushed(config);
        kicked.tick({0, 0, 0});
        pushed.tick({0, 0, 0});
        kicked.play(kick);
        pushed.play(push);
        const TickOutput a = kicked.tick({0, 0, 0});
        const TickOutput b = pushed.tick({0, 0, 0});
        const double na = std::hypot(a.force[0], a.force[1], a.force[2]);
        const double nb = std::hypot(b.force[0], b.force[1], b.force[2]);
        ASSERT_GT(na, 100.0);
        for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(a.force[axis] / na, b.force[axis] / nb, 1e-4) << axis;
    }
}

TEST(Recoil, AimsOnlyInTheFormsThePrimerGives) {
    DynamicRig rig;
    EffectParams p = recoil_params(9000, 6000, 5000, 5000, 1000);
    p.axis_count = 1;  // on one axis the sign aims it: an angle is refused
    Error e = rig.engine().create(p).error;
    EXPECT_EQ(std::string(e.field), "dynamic.blast_direction");
    EXPECT_NE(e.message().find("the angle must be 0"), std::string::npos) << e.message();
    EffectParams paddle = planar_dynamic(EffectType::dynamic_paddle);
    paddle.axis_count = 1;
    e = rig.engine().create(paddle).error;
    EXPECT_NE(e.message().find("2D only"), std::string::npos) << e.message();
}

}  // namespace
}  // namespace feel::test
