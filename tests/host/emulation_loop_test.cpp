// Host-emulated walls in closed loop through a modelled link (src/host/emulation/
// emulated_loop.hpp), against sampled-data theory.
//
// The truth used here (docs/real-devices.md, "Host emulation", derives it):
//  * Stability. A virtual wall of stiffness K on a mechanism with viscous damping b, held
//    for an update period T and seen with a loop delay L, is stable for
//    K < b / (T/2 + L) (Colgate & Schenkel's b > K·T/2 for L = 0; Gil, Avello, Rubio &
//    Flórez, "Stability analysis of a 1 DOF haptic interface using the Routh-Hurwitz
//    criterion", 2004, for the delay). With the passivity controller off and the
//    mechanism's dry friction removed (friction hides small cycles), a wall at half the
//    bound rings down (the swing of the last second is under a tenth of the first's) and a
//    wall at twice the bound does not (its swing grows until the motor's limit holds it).
//    Without friction the sensor's counts leave a cycle of a few counts, so "rung down" is
//    judged against the first swing, not against zero.
//  * Lag. With the handle moved kinematically at speed v into a wall of stiffness K_h, the
//    force the handle meets at time t is K_h times its penetration at some t − τ, with
//    τ ∈ [L, L + T): the error against K_h·p(t) is at most K_h·v·(L + T), plus the
//    passivity controller's damper when it is on (at most K_h·v·T, docs/stability.md),
//    plus one sensor count of K_h·q and a unit of rounding; and, without the controller,
//    on average at least K_h·v·L − K_h·q on a host loop, whose delay is real.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "emulation/emulated_loop.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::host::emulation::test {
namespace {

const sim::DeviceProfile& joystick() { return *sim::find_device_profile("iforce2"); }

// The bound K < b/(T/2 + L), normalized stiffness.
double delayed_bound(const EngineConfig& c, double t_s, double l_s) { return c.device_damping / (t_s / 2 + l_s); }

int32_t hardness_for(const EngineConfig& c, double k) {
    return static_cast<int32_t>(std::lround(k / c.wall_stiffness * 10000.0));
}

struct Rate {
    int32_t period_ms;
    const char* name;
};
constexpr Rate kRates[] = {{1, "1 kHz"}, {2, "500 Hz"}, {8, "125 Hz"}};

TEST(EmulatedWallLoop, NaiveHostWallFollowsTheDelayedSampledDataBound) {
    sim::DeviceProfile frictionless = joystick();
    frictionless.axes[0].coulomb = 0.0;
    EngineConfig config = sim::engine_config_for(frictionless);
    config.passivity_control = false;
    for (const Rate& rate : kRates) {
        const LoopLink link{rate.period_ms, 1, 1, true};
        const double bound = delayed_bound(config, rate.period_ms * 1e-3, 2e-3);
        const int32_t soft = hardness_for(config, 0.5 * bound);
        const int32_t hard = hardness_for(config, 2.0 * bound);
        ASSERT_GE(soft, 1);
        ASSERT_LE(hard, 10000);
        const WallRun below = run_pressed_wall(frictionless, config, soft, link, 3000, 0, 8.0);
        const WallRun above = run_pressed_wall(frictionless, config, hard, link, 3000, 0, 8.0);
        EXPECT_LT(swing(below, 7.0, 8.0), 0.1 * swing(below, 0.0, 1.0))
            << rate.name << ": hardness " << soft << " (0.5x the bound)";
        EXPECT_GE(swing(above, 7.0, 8.0), swing(above, 0.0, 1.0))
            << rate.name << ": hardness " << hard << " (2x the bound)";
    }
}

TEST(EmulatedWallLoop, RampForceErrorIsTheLoopsLag) {
    const sim::DeviceProfile& profile = joystick();
    const int32_t hardness = 1000;
    const double q = 20000.0 / profile.axes[0].sensor_counts;
    // 40 mm/s at the joystick's grip: the delay's 2 ms are 16 units, over three sensor
    // counts, and the deepest press (1400 units) stays under the motor's limit.
    const double v = 8000.0;
    for (const bool controller : {false, true}) {
        EngineConfig config = sim::engine_config_for(profile);
        config.passivity_control = controller;
        const double k_h = config.wall_stiffness * static_cast<double>(hardness) / 10000.0;
        for (const Rate& rate : kRates) {
            for (const bool host : {false, true}) {
                const LoopLink link{rate.period_ms, 1, 1, host};
                const double l_s = host ? 2e-3 : 0.0;
                const double t_s = rate.period_ms * 1e-3;
                const WallRun run = run_ramp_into_wall(profile, config, hardness, link, -200.0, v, 0.2);
                double worst = 0, sum = 0;
                int n = 0;
                for (size_t i = 0; i < run.position.size(); ++i) {
                    const double p = run.position[i];
                    if (p < v * (l_s + t_s) + 2 * q) continue;  // the lagged position is inside too
                    // The wall pushes toward −x: its force falls short of K_h·p by the lag.
                    const double shortfall = run.force[i] + k_h * p;
                    worst = std::max(worst, std::abs(shortfall));
                    sum += shortfall;
                    ++n;
                }
                ASSERT_GT(n, 100);
                const std::string what = std::string(rate.name) + (host ? " host" : " device") +
                                         (controller ? ", controller on" : ", naive");
                const double damper = controller ? k_h * v * t_s : 0.0;
                EXPECT_LE(worst, k_h * v * (l_s + t_s) + damper + k_h * q + 1.0) << what;
                // Without the controller the lag is all there is: on the host the mean
                // shortfall is at least the delay's.
                if (host && !controller) {
                    EXPECT_GE(sum / n, k_h * v * l_s - k_h * q) << what << ": the delay shows";
                }
            }
        }
    }
}

TEST(EmulatedWallLoop, PassivityControllerHoldsTheDesignWallAtOneKilohertzOnTheHost) {
    // Hardness 2000 is the naive bound 2b/T of the device's own 1 kHz loop (stability.md);
    // with one ms up and one down it is 2.5× the delayed bound, and the controller keeps
    // it settled with the mechanism's friction.
    const sim::DeviceProfile& profile = joystick();
    const EngineConfig config = sim::engine_config_for(profile);
    const WallRun run = run_pressed_wall(profile, config, 2000, LoopLink{1, 1, 1, true}, 3000, 0, 5.0);
    EXPECT_TRUE(settled(run, profile));
}

}  // namespace
}  // namespace feel::host::emulation::test
