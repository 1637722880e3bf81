// A hand tethered to the handle, against the damped oscillator (m + m_hand, k_g, b + b_g):
//   free response: period 2π/ωd, ωd = ωn·√(1 − ζ²), ωn = √(k/m), ζ = b/(2·√(k·m)),
//                  successive maxima shrink by exp(−ζ·ωn·Td)
//   constant motor force F: settles at x = F/k (statics), the hand pushing back with −F
// and the kinematic hand, which prescribes the motion exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "sim_test_support.hpp"

namespace feel::sim {
namespace {


struct Oscillation {
    double period = 0;      // s, mean over the downward zero crossings
    double decay = 0;       // ratio of successive maxima
};

// Releases axis 0 from `start` (normalized) and measures the free oscillation.
Oscillation measure(const DeviceProfile& profile, Grip grip, double start, double dt,
                    int crossings_wanted) {
    SimDevice device(profile, grip, TargetMotion::hold_at({0}));
    EXPECT_TRUE(device.set_position(0, start));
    std::vector<double> crossings, maxima;
    double x_prev2 = start, x_prev = start;
    for (int n = 1; n < 200000 && static_cast<int>(crossings.size()) < crossings_wanted; ++n) {
        test::run(device, 0, dt, 1);
        const double x = device.position(0);
        if (x_prev > 0 && x <= 0) {  // downward crossing between n−1 and n
            crossings.push_back((n - 1 + x_prev / (x_prev - x)) * dt);
        }
        if (n >= 2 && x_prev > x_prev2 && x_prev >= x) {  // maximum at n−1, refined
            const double curvature = x_prev2 - 2 * x_prev + x;
            const double offset = 0.5 * (x_prev2 - x) / curvature;
            maxima.push_back(x_prev - 0.25 * (x_prev2 - x) * offset);
        }
        x_prev2 = x_prev;
        x_prev = x;
    }
    Oscillation o;
    if (crossings.size() >= 2) {
        o.period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    }
    if (maxima.size() >= 2) o.decay = maxima[1] / maxima[0];
    return o;
}

struct GripCase {
    const char* device;
    Grip grip;
    double rate_hz;
    friend void PrintTo(const GripCase& c, std::ostream* os) {
        *os << c.device << " " << grip_name(c.grip) << " " << c.rate_hz << " Hz";
    }
};

class GripOscillator : public ::testing::TestWithParam<GripCase> {};

TEST_P(GripOscillator, RingsAtTheDampedNaturalFrequency) {
    const GripCase c = GetParam();
    // Without dry friction the released handle is a linear damped oscillator.
    const DeviceProfile& base = *find_device_profile(c.device);
    const DeviceProfile profile = test::with_friction(base, base.axes[0].viscous, 0);
    const GripModel& g = test::grip_of(profile, c.grip);
    const double m = profile.axes[0].mass + g.added_mass;
    const double b = profile.axes[0].viscous + g.damping;
    const double wn = std::sqrt(g.stiffness / m);
    const double zeta = b / (2 * std::sqrt(g.stiffness * m));
    const double wd = wn * std::sqrt(1 - zeta * zeta);
    const double td = 2 * std::numbers::pi / wd;

    const Oscillation o = measure(profile, c.grip, 3000, 1.0 / c.rate_hz, 5);
    EXPECT_NEAR(o.period, td, 0.002 * td) << "ζ = " << zeta;
    const double decay = std::exp(-zeta * wn * td);
    EXPECT_NEAR(o.decay, decay, 0.02 * decay) << "ζ = " << zeta;
}

INSTANTIATE_TEST_SUITE_P(
    ProfilesGripsRates, GripOscillator,
    ::testing::Values(GripCase{"joystick", Grip::loose, 1000}, GripCase{"joystick", Grip::firm, 1000},
                      GripCase{"joystick", Grip::stiff, 1000}, GripCase{"joystick", Grip::stiff, 100},
                      GripCase{"joystick", Grip::firm, 10000}, GripCase{"wheel", Grip::loose, 1000},
                      GripCase{"wheel", Grip::firm, 100}, GripCase{"wheel", Grip::stiff, 10000},
                      GripCase{"3axis", Grip::firm, 1000}, GripCase{"3axis", Grip::stiff, 100}),
    [](const ::testing::TestParamInfo<GripCase>& case_info) {
        const GripCase& c = case_info.param;
        return std::string(c.device == std::string_view("3axis") ? "three_axis" : c.device) +
               "_" + std::string(grip_name(c.grip)) + "_" +
               std::to_string(static_cast<int>(c.rate_hz)) + "Hz";
    });

// Where a handle pushed by F against a hand spring k_g comes to rest: F/k_g, or, past the
// end of the travel, where the stop spring shares the load.
double static_deflection(const AxisModel& a, double f, double k_g) {
    const double x = f / k_g;
    if (x <= a.half_travel) return x;
    return (f + a.end_stop_stiffness * a.half_travel) / (k_g + a.end_stop_stiffness);
}

TEST(Grip, FullMotorForceDeflectsTheHandByFOverK) {
    for (const DeviceProfile& profile : device_profiles()) {
        for (Grip grip : {Grip::loose, Grip::firm, Grip::stiff}) {
            const GripModel& g = test::grip_of(profile, grip);
            SimDevice device(profile, grip, TargetMotion::hold_at({0}));
            test::run(device, 10000, 1e-3, 6000);
            for (int a = 0; a < profile.axis_count; ++a) {
                const AxisModel& ax = profile.axes[a];
                const double x = static_deflection(ax, ax.max_force, g.stiffness);
                const bool in_stop = x > ax.half_travel;
                // Dry friction holds the handle anywhere within ±F_c/k of the balance.
                const double k = g.stiffness + (in_stop ? ax.end_stop_stiffness : 0);
                const double band = ax.coulomb / k * test::per_unit(ax);
                SCOPED_TRACE(std::string(profile.name) + " " + std::string(grip_name(grip)) +
                             " axis " + std::to_string(a));
                EXPECT_NEAR(device.position(a), x * test::per_unit(ax), band + 1e-6);
                EXPECT_NEAR(device.velocity(a), 0, 1e-3);
                if (!in_stop) {
                    EXPECT_NEAR(device.hand_force(a), -ax.max_force, ax.coulomb + 1e-9);
                }
            }
        }
    }
}

TEST(Grip, WithoutDryFrictionTheDeflectionIsExactlyFOverK) {
    const DeviceProfile profile = test::with_friction(*find_device_profile("joystick"), 0.5, 0);
    SimDevice device(profile, Grip::firm, TargetMotion::hold_at({0, 0}));
    test::run(device, -6000, 1e-3, 6000);
    const AxisModel& ax = profile.axes[0];
    const double f = -0.6 * ax.max_force;
    for (int a = 0; a < 2; ++a) {
        EXPECT_NEAR(device.position(a), f / profile.firm.stiffness * test::per_unit(ax), 1e-6);
        EXPECT_NEAR(device.hand_force(a), -f, 1e-9);
    }
}

TEST(Grip, TheHandleSettlesOnTheTargetAfterARamp) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const DeviceProfile frictionless = test::with_friction(joystick, 0.5, 0);
    for (const DeviceProfile* profile : {&joystick, &frictionless}) {
        for (Grip grip : {Grip::loose, Grip::firm, Grip::stiff}) {
            SimDevice device(*profile, grip, TargetMotion::parse("ramp:y:0:6000", 1.0, 2));
            test::run(device, 0, 1e-3, 4000);
            const double band = profile->axes[1].coulomb / test::grip_of(*profile, grip).stiffness *
                                test::per_unit(profile->axes[1]);
            EXPECT_NEAR(device.position(1), 6000, band + 1e-3) << grip_name(grip);
            EXPECT_NEAR(device.position(0), 0, 1e-9);
        }
    }
}

TEST(Grip, NoneLeavesTheHandleAlone) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    SimDevice device(joystick, Grip::none, TargetMotion::parse("sine:x:5000:2", 1, 2));
    test::run(device, 0, 1e-3, 1000);
    EXPECT_EQ(device.position(0), 0.0);
    EXPECT_EQ(device.velocity(0), 0.0);
    EXPECT_EQ(device.hand_force(0), 0.0);
}

TEST(Kinematic, TheHandleFollowsTheTargetExactly) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const double w = 2 * std::numbers::pi * 2;
    SimDevice device(joystick, Grip::kinematic, TargetMotion::parse("sine:x:5000:2", 1, 2));
    const AxisModel& ax = joystick.axes[0];
    const double scale = 1 / test::per_unit(ax);
    const double dt = 1e-3;
    for (int n = 1; n <= 2000; ++n) {
        test::run(device, n % 3 == 0 ? 10000.0f : -3000.0f, dt, 1);  // the motor cannot move it
        const double t = n * dt;
        ASSERT_NEAR(device.position(0), 5000 * std::sin(w * t), 1e-7);  // t accumulates dt
        ASSERT_NEAR(device.velocity(0), 5000 * w * std::cos(w * t), 1e-6);
        ASSERT_EQ(device.position(1), 0.0);
        // The hand supplies m·a + b·v + F_c·sign(v) − F_motor (the code differences v over
        // the step, a(t − dt/2): off by at most m·|jerk|·dt/2).
        const double v = 5000 * w * std::cos(w * t) * scale;
        const double acc = -5000 * w * w * std::sin(w * t) * scale;
        const double jerk = 5000 * w * w * w * scale;
        if (std::fabs(v) < 1e-9) continue;  // friction's sign is undefined at v = 0
        const double motor = (n % 3 == 0 ? 1.0 : -0.3) * ax.max_force;
        const double expected = ax.mass * acc + ax.viscous * v + std::copysign(ax.coulomb, v) - motor;
        ASSERT_NEAR(device.hand_force(0), expected, ax.mass * jerk * dt / 2 * 1.01) << t;
    }
}

TEST(Kinematic, FollowsACircleOnTwoAxes) {
    const DeviceProfile& three = *find_device_profile("3axis");
    SimDevice device(three, Grip::kinematic, TargetMotion::parse("circle:4000:0.5", 1, 3));
    const double w = 2 * std::numbers::pi * 0.5;
    for (int n = 1; n <= 3000; ++n) {
        test::run(device, 0, 1e-3, 1);
        const double t = n * 1e-3;
        ASSERT_NEAR(device.position(0), 4000 * std::cos(w * t), 1e-8);
        ASSERT_NEAR(device.position(1), 4000 * std::sin(w * t), 1e-8);
        ASSERT_NEAR(std::hypot(device.velocity(0), device.velocity(1)), 4000 * w, 1e-6);
        ASSERT_EQ(device.position(2), 0.0);
    }
}

TEST(Energy, AnUndampedGripConservesEnergyWithinTheSymplecticRipple) {
    // m = 0.2 kg on a 400 N/m hand with no damping or friction anywhere: the energy
    // ½·m·v² + ½·k·x² must neither drift nor ripple by more than ω·h.
    DeviceProfile profile = test::bare_profile(0.2, 0, 0, 1.0, 0.05);
    profile.firm = GripModel{.stiffness = 400, .damping = 0, .added_mass = 0.1};
    SimDevice device(profile, Grip::firm, TargetMotion::hold_at({0}));
    ASSERT_TRUE(device.set_position(0, 5000));
    const double m = 0.3, k = 400, dt = 1e-3;
    const double h = dt / device.substeps(dt);
    const double omega_h = std::sqrt(k / m) * h;
    const auto energy = [&] {
        const double x = device.physical_position(0), v = device.physical_velocity(0);
        return 0.5 * m * v * v + 0.5 * k * x * x;
    };
    const double e0 = energy();
    double first_second_max = 0, last_second_max = 0;
    for (int n = 1; n <= 20000; ++n) {
        test::run(device, 0, dt, 1);
        const double e = energy();
        ASSERT_NEAR(e / e0, 1.0, omega_h) << "step " << n;
        if (n <= 1000) first_second_max = std::max(first_second_max, e);
        if (n > 19000) last_second_max = std::max(last_second_max, e);
    }
    EXPECT_NEAR(last_second_max / first_second_max, 1.0, 1e-3);  // no secular drift
}

}  // namespace
}  // namespace feel::sim
