// dynamic_impact (§5.4, §1.2.b example 3), the §8.4 mapping ImpactIntensity → VelInit
// (split by ImpactDirection), DynamicMass → Mass, Elasticity → KPos = KNeg,
// CollisionAbsorption → B.
#include <gtest/gtest.h>

#include <cmath>

#include "tether_fixture.hpp"

namespace feel::test {
namespace {

struct Hit {
    double peak = 0;          // largest pull along the blow, force units
    double time_to_peak = 0;  // s
    double first_x = 0, first_y = 0;
};

// Plays an impact against a held handle for `ticks` ticks; the peak is searched over the
// first `peak_ticks` (the first swing).
Hit play_impact(const EffectParams& p, int ticks = 600, int peak_ticks = 600) {
    DynamicRig rig;
    rig.tick({0, 0});
    rig.play(p);
    Hit h;
    for (int n = 0; n < ticks; ++n) {
        const TickOutput out = rig.tick({0, 0});
        if (n == 0) {
            h.first_x = out.force[0];
            h.first_y = out.force[1];
        }
        const double f = std::hypot(out.force[0], out.force[1]);
        if (n < peak_ticks && f > h.peak) {
            h.peak = f;
            h.time_to_peak = (n + 0.5) * rig.period_s();  // the tick's force is its mean
        }
    }
    return h;
}

TEST(Impact, TheBlowComesFromTheImpactDirection) {
    // §8.5's sample writes Intensity·cos(angle) on x and ·sin(angle) on y; feel's angle is
    // a compass angle naming where the blow comes from (docs/dynamics.md): from the right
    // (9000) the object is shoved left and pulls the handle toward −x; from behind
    // (18000) it pulls forward, +y.
    const Hit right = play_impact(impact_params(9000, 6000, 4000, 5000, 1000), 1);
    EXPECT_LT(right.first_x, -100.0);
    EXPECT_NEAR(right.first_y, 0.0, 1e-3 * std::fabs(right.first_x));
    const Hit behind = play_impact(impact_params(18000, 6000, 4000, 5000, 1000), 1);
    EXPECT_GT(behind.first_y, 100.0);
    EXPECT_NEAR(behind.first_x, 0.0, 1e-3 * behind.first_y);
    // 30° east of north: along (−sin 30°, −cos 30°).
    const Hit oblique = play_impact(impact_params(3000, 6000, 4000, 5000, 1000), 1);
    EXPECT_NEAR(oblique.first_x / oblique.first_y, std::tan(kPiD / 6), 1e-4);
    EXPECT_LT(oblique.first_y, 0.0);
}

TEST(Impact, ElasticObjectsHitSofterAndLongerInelasticOnesCrack) {
    // §5.4: "An elastic object will compress and absorb much of the impact ... a much
    // softer feel than an inelastic object which will collide with a crisp crack."
    // Undamped against a held handle: peak v·sqrt(k·m) at a quarter period π/(2·sqrt(k/m)).
    const EngineConfig c;
    const double m = per_10000(5000, c.dynamic_mass_ref);
    const double v = per_10000(3000, c.velocity_ref);
    double peaks[2], times[2];
    const int32_t elasticity[2] = {1500, 9000};
    for (int i = 0; i < 2; ++i) {
        const double k = per_10000(elasticity[i], c.dynamic_stiffness_ref);
        const int half_period_ticks = static_cast<int>(kPiD / std::sqrt(k / m) / 1e-3);
        const Hit h = play_impact(impact_params(0, 3000, 5000, elasticity[i], 0), half_period_ticks, half_period_ticks);
        EXPECT_NEAR(h.peak, v * std::sqrt(k * m), 2e-3 * h.peak) << elasticity[i];
        EXPECT_NEAR(h.time_to_peak, kPiD / 2 / std::sqrt(k / m), 1e-3) << elasticity[i];
        peaks[i] = h.peak;
        times[i] = h.time_to_peak;
    }
    EXPECT_LT(peaks[0], peaks[1]);
    EXPECT_GT(times[0], times[1]);
}

TEST(Impact, CollisionAbsorptionDissipatesTheDisturbance) {
    // High absorption: the disturbance is gone after one or two oscillations. The mass's
    // swing decays as exp(−b/(2m)·t), b = absorption on the damping scale.
    const EngineConfig c;
    for (int32_t absorption : {500, 4000}) {
        DynamicRig rig;
        rig.tick({0, 0});
        rig.play(impact_params(18000, 5000, 5000, 5000, absorption));
        const double m = per_10000(5000, c.dynamic_mass_ref), k = per_10000(5000, c.dynamic_stiffness_ref);
        const double b = per_10000(absorption, c.dynamic_damping_ref);
        const Oscillator osc{m, b, k, 0, per_10000(5000, c.velocity_ref)};
        for (int n = 0; n < 1500; ++n) {
            const double t = n * rig.period_s();
            const TickOutput out = rig.tick({0, 0});
            ASSERT_NEAR(out.mass_position[1], osc.position(t), 1e-2) << absorption << " t=" << t;
            ASSERT_NEAR(out.mass_position[0], 0.0, 1e-6);
        }
    }
}

TEST(Impact, SameParametersAsARecoilSameSensation) {
    // §8.4 maps both onto the same law: an impact from θ feels like a recoil fired at θ.
    DynamicRig a, b;
    a.tick({0, 0});
    b.tick({0, 0});
    a.play(impact_params(22500, 6500, 7000, 3000, 1200));
    b.play(recoil_params(22500, 6500, 7000, 3000, 1200));
    for (int n = 0; n < 500; ++n) {
        const double hand = 500 * std::sin(n * 0.02);
        const TickOutput fa = a.tick({hand, hand / 2});
        const TickOutput fb = b.tick({hand, hand / 2});
        ASSERT_EQ(fa.force[0], fb.force[0]);
        ASSERT_EQ(fa.force[1], fb.force[1]);
    }
}

}  // namespace
}  // namespace feel::test
