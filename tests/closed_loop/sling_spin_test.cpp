// Dynamic Sling (§5.8) in the closed loop: a hand circles the joystick and spins the ball.
// "The faster you swing the ball, the stronger the force you feel."
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "contact_loop.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::test {
namespace {

constexpr double kCircleRadius = 2000;  // position units: ±10 mm of the joystick's ±50 mm

EffectParams spinning_ball() {
    EffectParams p;
    p.type = EffectType::dynamic_sling;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.dynamic.ball_mass = 8000;
    p.dynamic.string_length = 2000;
    p.dynamic.string_compliance = 3000;
    p.dynamic.ball_damping = 200;
    return p;
}

struct Spin {
    double mean_pull = 0;    // mean |force| over the last seconds, force units
    double mean_radius = 0;  // mean ball distance from the handle, position units
};

// Circles the hand at hz for 6 s and averages the last 3 s (the spin-up settles at the
// air's rate c/m, a few per second).
Spin spin(sim::Grip grip, double hz) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("joystick");
    const EngineConfig config = sim::engine_config_for(profile);
    const std::string motion = "circle:" + std::to_string(static_cast<int>(kCircleRadius)) + ":" + std::to_string(hz);
    sim::SimDevice device(profile, grip, sim::TargetMotion::parse(motion, 6.0, profile.axis_count));
    loop::ClosedLoop rig(config);
    rig.play(spinning_ball());
    Spin s;
    int counted = 0;
    for (int i = 0; i < 6000; ++i) {
        const TickOutput out = rig.tick(device);
        EXPECT_TRUE(out.has_mass);
        EXPECT_LT(std::fabs(out.force[0]), 10000.0f) << "the pull must stay below the motor's limit";
        EXPECT_LT(std::fabs(out.force[1]), 10000.0f);
        if (i >= 3000) {
            s.mean_pull += std::hypot(out.force[0], out.force[1]);
            s.mean_radius += std::hypot(out.mass_position[0], out.mass_position[1]);
            ++counted;
        }
    }
    s.mean_pull /= counted;
    s.mean_radius /= counted;
    return s;
}

// The steady state of a ball dragged around by a handle on a circle of radius a at rate Ω,
// with air resistance c, derived independently of the model. In the complex plane the
// handle is H = a·e^{iΩt} and the ball B = z·e^{iΩt}; m·B'' = F − c·B' with the string's
// pull F = −κ·(B − H), κ = k·(1 − L/d), d = |z − a|, gives z·(κ − mΩ² + icΩ) = κ·a, so
//     d = a·|mΩ² − icΩ| / |κ − mΩ² + icΩ|,
// one equation in d (> L), solved by bisection. The tension is k·(d − L).
double steady_tension(double m, double k, double L, double c, double a, double omega) {
    const double load = std::hypot(m * omega * omega, c * omega);
    auto excess = [&](double d) {  // d minus the d the equation returns
        const double kappa = k * (1 - L / d);
        return d - a * load / std::hypot(kappa - m * omega * omega, c * omega);
    };
    double lo = L * (1 + 1e-12), hi = 1e7;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (excess(mid) < 0 ? lo : hi) = mid;
    }
    return k * (0.5 * (lo + hi) - L);
}

class SlingSpin : public ::testing::TestWithParam<double> {};

TEST_P(SlingSpin, AHandleCirclingExactlySpinsTheBallToItsSteadyState) {
    const double hz = GetParam();
    const EngineConfig config = sim::engine_config_for(*sim::find_device_profile("joystick"));
    const EffectParams p = spinning_ball();
    const double m = p.dynamic.ball_mass / 10000.0 * config.dynamic_mass_ref;
    const double k = p.dynamic.string_compliance / 10000.0 * config.dynamic_stiffness_ref;
    const double c = p.dynamic.ball_damping / 10000.0 * config.dynamic_damping_ref;
    const double want = steady_tension(m, k, p.dynamic.string_length, c, kCircleRadius, 2 * std::numbers::pi * hz);
    const Spin s = spin(sim::Grip::kinematic, hz);
    // The sensor quantizes the handle to 4.9 units and the engine estimates its velocity:
    // the pull is the analytic one within a percent.
    EXPECT_NEAR(s.mean_pull, want, 0.01 * want) << hz << " Hz";
}

INSTANTIATE_TEST_SUITE_P(Rates, SlingSpin, ::testing::Values(1.0, 2.0));

TEST(SlingSpinByHand, CirclingFasterPullsHarder) {
    // A firm hand circling at 1 Hz and at 2 Hz: the centripetal pull m·Ω²·ρ grows with the
    // square of the rate (a little more, as the string stretches), and the ball flies wider.
    const Spin slow = spin(sim::Grip::firm, 1.0);
    const Spin fast = spin(sim::Grip::firm, 2.0);
    EXPECT_GT(slow.mean_pull, 100.0) << "spun up at all";
    EXPECT_GT(fast.mean_pull, 3.0 * slow.mean_pull);
    EXPECT_GT(fast.mean_radius, slow.mean_radius);
}

}  // namespace
}  // namespace feel::test
