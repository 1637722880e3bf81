// dynamic_liquid (§5.5): Density → Mass, Settle → KPos = KNeg, Viscosity → B, and the one
// unmapped parameter feel sets, Drag = Viscosity (docs/dynamics.md: without it, steady
// wading would meet no resistance at all).
#include <gtest/gtest.h>

#include <cmath>

#include "tether_fixture.hpp"

namespace feel::test {
namespace {

struct Liquid {
    double m, k, c_tether, drag;
};

Liquid liquid_of(const EngineConfig& c, int32_t density, int32_t settle, int32_t viscosity) {
    const double b = per_10000(viscosity, c.dynamic_damping_ref);
    return {per_10000(density, c.dynamic_mass_ref), per_10000(settle, c.dynamic_stiffness_ref), b, b};
}

// The handle wades at u units/s for `wade_ticks`, then stops dead and is held.
struct Wade {
    std::vector<TickOutput> out;
    int stop_tick = 0;
};

Wade wade_and_stop(const EffectParams& p, double u, int wade_ticks, int hold_ticks) {
    DynamicRig rig;
    Wade w;
    double x = -4000;
    for (int n = 0; n < 50; ++n) rig.tick({x});  // at rest before
    rig.play(p);
    for (int n = 0; n < wade_ticks; ++n) {
        x += u * rig.period_s();
        w.out.push_back(rig.tick({x}));
    }
    w.stop_tick = wade_ticks;
    for (int n = 0; n < hold_ticks; ++n) w.out.push_back(rig.tick({x}));
    return w;
}

TEST(Liquid, ViscosityResistsSteadyWading) {
    // Moving steadily through the liquid the handle meets −viscosity·u, like a damper.
    const EngineConfig c;
    for (int32_t viscosity : {1000, 6000}) {
        const Liquid l = liquid_of(c, 4000, 3000, viscosity);
        const double u = 5000;
        const Wade w = wade_and_stop(liquid_params(4000, 3000, viscosity), u, 1500, 0);
        EXPECT_NEAR(w.out.back().force[0], -l.drag * u, 2e-3 * l.drag * u) << viscosity;
        // ... and trails it by drag·u/k.
        EXPECT_NEAR(w.out.back().mass_position[0], -l.drag * u / l.k, 0.02 + 2e-3 * l.drag * u / l.k);
    }
}

TEST(Liquid, AnAbruptStopSetsItJigglingAndItSettlesAsTheOscillatorSays) {
    // After the stop the handle is still: the liquid's mass swings about it as a damped
    // oscillator with m = density, k = settle, c = viscosity (tether) + viscosity (drag).
    // The engine's velocity estimate needs a few ticks to see the stop, so the comparison
    // starts from the reported state 120 ms after it (past the estimator's longest window,
    // 100 ms, so it reads the still handle as exactly still).
    const EngineConfig c;
    for (int32_t settle : {1500, 6000}) {
        const Liquid l = liquid_of(c, 6000, settle, 400);
        const Wade w = wade_and_stop(liquid_params(6000, settle, 400), 9000, 600, 1500);
        const int from = w.stop_tick + 120;
        const TickOutput& start = w.out[static_cast<size_t>(from)];
        const Oscillator osc{l.m, l.c_tether + l.drag, l.k, start.mass_position[0], start.mass_velocity[0]};
        const double amplitude = std::hypot(osc.y0, osc.v0 / osc.omega0());
        ASSERT_GT(amplitude, 20.0) << "the stop must leave a jiggle to watch";
        for (size_t n = static_cast<size_t>(from); n < w.out.size(); ++n) {
            const double t = static_cast<double>(n - static_cast<size_t>(from)) * 1e-3;
            ASSERT_NEAR(w.out[n].mass_position[0], osc.position(t), 1e-3 + 1e-5 * amplitude) << settle << " t=" << t;
        }
    }
}

TEST(Liquid, DenserLiquidDisturbsMore) {
    // §5.5: "the greater the density, the larger the disturbance": the same stop leaves a
    // jiggle whose energy grows with the liquid's mass.
    double energy[2] = {};
    const int32_t density[2] = {1000, 8000};
    const EngineConfig c;
    for (int i = 0; i < 2; ++i) {
        const Liquid l = liquid_of(c, density[i], 3000, 300);
        const Wade w = wade_and_stop(liquid_params(density[i], 3000, 300), 8000, 600, 150);
        const TickOutput& o = w.out.back();
        energy[i] = 0.5 * l.m * o.mass_velocity[0] * o.mass_velocity[0] + 0.5 * l.k * o.mass_position[0] * o.mass_position[0];
    }
    EXPECT_GT(energy[1], 4 * energy[0]);
}

TEST(Liquid, PlaysOnEveryAxisItIsGiven) {
    // No direction: each axis is its own liquid.
    DynamicRig rig;
    rig.tick({0, 0});
    rig.play(liquid_params(3000, 3000, 2000, {Axis::y}));
    double x = 0;
    TickOutput out;
    for (int n = 0; n < 500; ++n) {
        x += 4.0;  // 4000 units/s on both axes
        out = rig.tick({x, x});
    }
    EXPECT_EQ(out.force[0], 0.0f);  // x is not the effect's
    EXPECT_LT(out.force[1], -100.0f);
}

}  // namespace
}  // namespace feel::test
