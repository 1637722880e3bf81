// dynamic_inertia (§5.6): Inertia → Mass, Play → Length; feel sets the unmapped tether to
// the stiffest stiffness (10000) with a damping ratio of 0.7 against a held handle
// (docs/dynamics.md), so the handle feels weight rather than a spring.
#include <gtest/gtest.h>

#include <cmath>

#include "feel/sim/device_profile.hpp"
#include "tether_fixture.hpp"

namespace feel::test {
namespace {

TEST(Inertia, AnAcceleratedHandleFeelsTheMassItDrags) {
    // Handle at constant acceleration a: once the tether's transient has died, the mass
    // accelerates with it and the handle feels −m·a. Without play the mass is simulated
    // in the handle's frame, driven by the engine's acceleration estimate (a parabola fit
    // to the quantized samples, control_law_dynamic.cpp); the bound allowed here,
    // k·sqrt(2·q·a)·T/2 (q: a sensor count), is that of the earlier drive through the
    // velocity estimate, which lagged a steadily accelerating handle by about sqrt(2·q·a).
    const EngineConfig c = sim::engine_config_for(*sim::find_device_profile("joystick"));
    for (int32_t inertia : {2000, 10000}) {
        const double m = per_10000(inertia, c.dynamic_mass_ref);
        const double a = 5e5;  // units/s²: a brisk start, 8100 units in 0.18 s
        DynamicRig rig(c);
        for (int n = 0; n < 5; ++n) rig.tick({-9000});
        rig.play(inertia_params(inertia, 0));
        TickOutput out;
        for (int n = 0; n < 180; ++n) {
            const double t = n * rig.period_s();
            out = rig.tick({-9000 + a * t * t / 2});
        }
        const double lag_error = c.dynamic_stiffness_ref * std::sqrt(2 * c.sensor_step * a) * rig.period_s() / 2;
        EXPECT_NEAR(out.force[0], -m * a, 0.01 * m * a + lag_error) << inertia;
    }
}

TEST(Inertia, Weight10000IsTheInertiaConditionsFullScale) {
    // The profiles' mass scale: inertia 10000 is the mass full force accelerates at
    // acceleration_ref, the inertia condition's 10000 (conditions/inertia_condition.cpp).
    for (const sim::DeviceProfile& profile : sim::device_profiles()) {
        const EngineConfig c = sim::engine_config_for(profile);
        EXPECT_NEAR(c.dynamic_mass_ref * c.acceleration_ref, 10000.0, 1.0) << profile.name;
    }
}

// The exact relative motion of a mass at rest picked up by a handle moving steadily at u
// through the play L: slack until the handle has moved L (t_e = L/u), then the damped
// oscillator of the tether from the edge with relative velocity −u.
struct PickUp {
    double m, k, b, L, u;
    [[nodiscard]] double t_engage() const { return L / u; }
    // The damped tether swings the mass back to the edge of the play half a damped period
    // after taking it up; from there it is slack again (the rattle of the play).
    [[nodiscard]] double t_release() const {
        const double gamma = b / (2 * m);
        return t_engage() + kPiD / std::sqrt(k / m - gamma * gamma);
    }
    [[nodiscard]] Oscillator tether() const { return {m, b, k, 0, -u}; }
    [[nodiscard]] double stretch(double t) const {
        if (t <= t_engage()) return -u * t;
        return -L + tether().position(t - t_engage());
    }
    [[nodiscard]] double pull(double t) const {
        if (t <= t_engage()) return 0.0;
        const Oscillator o = tether();
        return k * o.position(t - t_engage()) + b * o.velocity(t - t_engage());
    }
};

TEST(Inertia, PlayThenATetherDampedAtZetaPointSeven) {
    // From rest, the handle moves off at a steady u: for the first `play` units the tether
    // is slack and there is no force at all; then the mass is taken up by a tether of
    // stiffness 10000 damped at ζ = 0.7, whose overshoot (4.6%) then swings it back into
    // the play. Every tick against the exact piecewise motion.
    const EngineConfig c;
    for (const int32_t play : {150, 450}) {
        const double m = per_10000(6000, c.dynamic_mass_ref), k = c.dynamic_stiffness_ref;
        const double u = 6000;
        const PickUp pick{m, k, 2 * 0.7 * std::sqrt(k * m), static_cast<double>(play), u};
        DynamicRig rig;
        for (int n = 0; n < 3; ++n) rig.tick({-5000});
        rig.play(inertia_params(6000, play));
        rig.tick({-5000});  // the effect's first tick: the handle still at rest
        // While the tether is slack the engine's velocity estimate locks onto the handle's
        // new motion (a few ticks); the pick-up then follows the exact solution.
        bool slack_again = false;
        for (int n = 1; n < 400; ++n) {
            const double t = n * rig.period_s();
            const TickOutput out = rig.tick({-5000 + u * t});
            if (t > pick.t_release() + rig.period_s()) {
                slack_again = slack_again || out.force[0] == 0.0f;
                continue;
            }
            if (t + rig.period_s() > pick.t_release()) continue;  // the tick of the release
            ASSERT_NEAR(out.mass_position[0], pick.stretch(t), 1e-2) << "t=" << t;
            const double pull = mean_over([&](double v) { return pick.pull(v); }, t, t + rig.period_s(), 2000);
            // (1e-3: the damper reads the handle through the velocity estimator, whose fit
            // windows still reach back to the start now and then.)
            ASSERT_NEAR(out.force[0], pull, 0.05 + 1e-3 * std::fabs(pull)) << "t=" << t;
            if (t + rig.period_s() < pick.t_engage()) {
                ASSERT_EQ(out.force[0], 0.0f) << "t=" << t;
            }
        }
        EXPECT_TRUE(slack_again) << "the overshoot of ζ = 0.7 carries the mass back into the play";
    }
}

TEST(Inertia, PlayLetsTheMassRattle) {
    // A quick reversal inside the play feels nothing; the mass keeps drifting.
    DynamicRig rig;
    for (int n = 0; n < 3; ++n) rig.tick({0});
    rig.play(inertia_params(8000, 2000));
    for (int n = 0; n < 200; ++n) {
        const double x = 500 * std::sin(2 * kPiD * 5 * n * rig.period_s());  // ±500 within ±2000
        ASSERT_EQ(rig.tick({x}).force[0], 0.0f) << n;
    }
}

}  // namespace
}  // namespace feel::test
