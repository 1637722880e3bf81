// dynamic_center_drift (§5.7): Stiffness → KPos = KNeg, DriftResistance → Drag. The origin
// is a light mass (mass 1) that the spring ties to the handle and the drag to the world,
// critically damped on its spring; with the drag on its own scale (docs/dynamics.md) the
// origin follows a held handle with time constant 10 s · resistance / stiffness.
#include <gtest/gtest.h>

#include <cmath>

#include "tether_fixture.hpp"

namespace feel::test {
namespace {

struct Drift {
    double m, k, c;  // the origin's mass, the spring, tether damping + drag
    // The slow root of m·r² − c·r + k = 0: the rate the origin creeps at, 1/s.
    [[nodiscard]] double rate() const { return (c - std::sqrt(c * c - 4 * k * m)) / (2 * m); }
};

Drift drift_of(const EngineConfig& cfg, int32_t stiffness, int32_t resistance) {
    const double m = per_10000(1, cfg.dynamic_mass_ref);
    const double k = per_10000(stiffness, cfg.dynamic_stiffness_ref);
    const double drag = per_10000(resistance, cfg.dynamic_stiffness_ref) * 10.0;  // 10 s · k_ref per 10000
    return {m, k, drag + 2 * std::sqrt(k * m)};
}

// Moves the handle from 0 to x_hold over 20 ms, holds it, and records the force.
std::vector<float> move_and_hold(const EffectParams& p, double x_hold, int hold_ticks) {
    DynamicRig rig;
    for (int n = 0; n < 3; ++n) rig.tick({0});
    rig.play(p);
    std::vector<float> f;
    for (int n = 0; n <= 20; ++n) f.push_back(rig.tick({x_hold * n / 20.0}).force[0]);
    for (int n = 0; n < hold_ticks; ++n) f.push_back(rig.tick({x_hold}).force[0]);
    return f;
}

TEST(CenterDrift, SpringsBackToTheOriginAtFirst) {
    // Right after the move the origin has barely followed: the pull is −k·x.
    const EngineConfig c;
    const std::vector<float> f = move_and_hold(center_drift_params(6000, 8000), 500, 10);
    const double k = per_10000(6000, c.dynamic_stiffness_ref);
    EXPECT_NEAR(f.back(), -k * 500, 0.01 * k * 500);
}

TEST(CenterDrift, TheOriginCreepsToTheHeldHandleAtTheOverdampedRate) {
    // Held still, the pull decays as exp(−r·t), r the slow root of the origin's
    // overdamped motion; the fast root has long died out after the first 50 ms.
    const EngineConfig c;
    for (const auto& [stiffness, resistance] : {std::pair{6000, 300}, std::pair{10000, 1000}, std::pair{2000, 2000}}) {
        const Drift d = drift_of(c, stiffness, resistance);
        // Held 300 units off: the pull (at most 300·k ≈ 6700) stays below full force.
        const std::vector<float> f = move_and_hold(center_drift_params(stiffness, resistance), 300, 4000);
        const size_t i0 = 100, i1 = f.size() - 1;
        ASSERT_LT(f[i0], -1.0f);
        ASSERT_LT(f[i1], 0.0f);
        const double measured = std::log(f[i0] / static_cast<double>(f[i1])) / (static_cast<double>(i1 - i0) * 1e-3);
        EXPECT_NEAR(measured, d.rate(), 0.005 * d.rate()) << stiffness << "/" << resistance;
        // and the rate is the design's 10 s · resistance / stiffness, to the light mass's
        // critical damping (c/k adds 2·sqrt(m/k), a few ms).
        EXPECT_NEAR(1 / d.rate(), 10.0 * resistance / stiffness, 0.01 + 0.001 * 10.0 * resistance / stiffness);
    }
}

TEST(CenterDrift, NoResistanceMeansTheOriginFollowsAtOnce) {
    const std::vector<float> f = move_and_hold(center_drift_params(10000, 0), 3000, 50);
    EXPECT_NEAR(f.back(), 0.0, 0.05);
    for (float x : f) EXPECT_LT(std::fabs(x), 0.01f * 10000);  // never more than a whisper
}

TEST(CenterDrift, AfterDriftingTheNewCentreHolds) {
    // Held long enough, the origin has moved to the handle: letting the handle back to
    // where it started now pulls it toward the new centre.
    DynamicRig rig;
    for (int n = 0; n < 3; ++n) rig.tick({0});
    rig.play(center_drift_params(8000, 100));  // τ = 10 s · 100 / 8000 = 125 ms
    for (int n = 0; n <= 20; ++n) rig.tick({300 * n / 20.0});
    for (int n = 0; n < 2000; ++n) rig.tick({300});  // 16 time constants
    for (int n = 0; n <= 20; ++n) rig.tick({300 - 300 * n / 20.0});
    const TickOutput out = rig.tick({0});
    const double k = per_10000(8000, rig.config().dynamic_stiffness_ref);
    EXPECT_GT(out.force[0], 0.5 * k * 300);  // pulled back toward +300
}

}  // namespace
}  // namespace feel::test
