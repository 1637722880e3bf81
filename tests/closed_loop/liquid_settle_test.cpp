// Dynamic liquid (§5.5) in closed loop: an abrupt hand motion stirs the liquid up, and its
// undulations settle at the rate the parameters give.
//
// The hand moves the handle (kinematically: exactly as told, through the simulated
// device's quantized sensors and the engine's velocity estimate) 3000 units in 60 ms and
// holds it there. The liquid's mass, dragged along and left swinging, then moves relative
// to the still handle as the textbook damped oscillator with
//     m = density,  k = settle,  c = viscosity (tether) + viscosity (drag)
// (docs/dynamics.md): frequency sqrt(k/m − γ²), envelope exp(−γ·t), γ = c/(2m). The
// measured swing (the engine's report of the mass relative to the handle) must match both.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::test {
namespace {


// Where the hand goes: still for 200 ms, 3000 units in 60 ms, then held.
std::filesystem::path abrupt_move() {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "feel_liquid_settle_move.csv";
    std::ofstream f(path);
    f << "t_us,x\n0,0\n200000,0\n260000,3000\n";
    return path;
}

struct Swing {
    std::vector<double> t, amplitude;  // the swing's extrema after the stop: time, |stretch|
    double first_amplitude = 0;
};

// Plays the liquid on x through the move; collects the extrema of the mass's stretch from
// `from_s` on (after the stop, once the engine's velocity estimate reads the held handle as
// still: its longest window is 100 ms).
Swing stir(int32_t density, int32_t settle, int32_t viscosity, double from_s = 0.4) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("joystick");
    Engine engine(sim::engine_config_for(profile));
    sim::SimDevice device(profile, sim::Grip::kinematic,
                          sim::TargetMotion::parse("csv:" + abrupt_move().string(), 3.0, profile.axis_count));
    EffectParams p;
    p.type = EffectType::dynamic_liquid;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.dynamic.density = density;
    p.dynamic.settle = settle;
    p.dynamic.viscosity = viscosity;
    const CreateResult r = engine.create(p);
    EXPECT_TRUE(r.error.ok());
    EXPECT_TRUE(engine.start(r.id).ok());
    std::vector<double> s;
    for (int n = 0; n < 3000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        device.sense(in);
        TickOutput out;
        engine.tick(in, out);
        device.step(out.force, 1e-3);
        s.push_back(out.mass_position[0]);
    }
    Swing swing;
    const size_t from = static_cast<size_t>(from_s * 1000);
    for (size_t n = from; n + 1 < s.size(); ++n) {
        const bool extremum = (s[n] - s[n - 1]) * (s[n + 1] - s[n]) < 0;
        if (extremum && std::fabs(s[n]) > 1.0) {  // above float noise, far below the swing
            // The parabola through three samples places the extremum between ticks.
            const double a = (s[n + 1] + s[n - 1] - 2 * s[n]) / 2, b = (s[n + 1] - s[n - 1]) / 2;
            const double dt = -b / (2 * a);
            swing.t.push_back((static_cast<double>(n) + dt) * 1e-3);
            swing.amplitude.push_back(std::fabs(s[n] - b * b / (4 * a)));
        }
    }
    if (!swing.amplitude.empty()) swing.first_amplitude = swing.amplitude.front();
    return swing;
}

struct Expected {
    double gamma, omega_d;
};

Expected expected(int32_t density, int32_t settle, int32_t viscosity) {
    const EngineConfig c = sim::engine_config_for(*sim::find_device_profile("joystick"));
    const double m = density / 10000.0 * c.dynamic_mass_ref;
    const double k = settle / 10000.0 * c.dynamic_stiffness_ref;
    const double damping = 2 * viscosity / 10000.0 * c.dynamic_damping_ref;
    const double gamma = damping / (2 * m);
    return {gamma, std::sqrt(k / m - gamma * gamma)};
}

class LiquidSettle : public ::testing::TestWithParam<int32_t> {};

TEST_P(LiquidSettle, UndulationsSettleAtTheRateOfTheParameters) {
    const int32_t settle = GetParam();
    const Swing swing = stir(6000, settle, 300);
    const Expected want = expected(6000, settle, 300);
    ASSERT_GE(swing.t.size(), 6u) << "a visible undulation";
    // Half a damped period between extrema.
    const double half_period = (swing.t.back() - swing.t.front()) / static_cast<double>(swing.t.size() - 1);
    EXPECT_NEAR(half_period, std::numbers::pi / want.omega_d, 0.01 * std::numbers::pi / want.omega_d);
    // The envelope: the log of the extrema falls at γ per second.
    const double gamma = std::log(swing.amplitude.front() / swing.amplitude.back()) / (swing.t.back() - swing.t.front());
    EXPECT_NEAR(gamma, want.gamma, 0.02 * want.gamma);
}

INSTANTIATE_TEST_SUITE_P(SettleValues, LiquidSettle, ::testing::Values(1500, 3000, 8000));

TEST(LiquidSettle, LowSettleSwingsWideAndLongHighSettleOnlyMildly) {
    // §5.5: "A liquid with a high Settle parameter will oscillate mildly. A liquid with a low
    // settle parameter will oscillate for a long time." The same stop leaves a swing whose
    // size goes as 1/ω ∝ 1/sqrt(settle), and with the same envelope exp(−γ·t) a wider swing
    // takes longer to die below any threshold.
    const Swing low = stir(6000, 1500, 300, 0.3);
    const Swing high = stir(6000, 8000, 300, 0.3);
    ASSERT_FALSE(low.amplitude.empty());
    ASSERT_FALSE(high.amplitude.empty());
    EXPECT_GT(low.first_amplitude, 1.5 * high.first_amplitude);
    // When the envelope (log-linear between extrema) falls below 20 units.
    auto settled_at = [](const Swing& s, double threshold) {
        for (size_t i = 1; i < s.t.size(); ++i) {
            if (s.amplitude[i] <= threshold && s.amplitude[i - 1] > threshold) {
                const double f = std::log(s.amplitude[i - 1] / threshold) / std::log(s.amplitude[i - 1] / s.amplitude[i]);
                return s.t[i - 1] + f * (s.t[i] - s.t[i - 1]);
            }
        }
        return -1.0;
    };
    const double t_low = settled_at(low, 20.0), t_high = settled_at(high, 20.0);
    ASSERT_GT(t_low, 0.0);
    ASSERT_GT(t_high, 0.0);
    // Same envelope: the wider swing needs ln(ratio)/γ longer (half of it as the margin).
    const double gamma = expected(6000, 1500, 300).gamma;
    EXPECT_GT(t_low - t_high, 0.5 * std::log(low.first_amplitude / high.first_amplitude) / gamma);
}

}  // namespace
}  // namespace feel::test
