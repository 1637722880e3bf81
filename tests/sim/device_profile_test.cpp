// The built-in profiles: the classes the issue asks for, with numbers that hold up
// against the hardware they describe (§3.7: a consumer joystick makes "less than 1 pound
// of force") and against human hand-arm impedance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "sim_test_support.hpp"

namespace feel::sim {
namespace {

constexpr double kNewtonsPerPoundForce = 4.4482216152605;

TEST(DeviceProfiles, TheBuiltInsAreJoystickWheel3AxisAndTheTwoIforceClasses) {
    const auto profiles = device_profiles();
    ASSERT_EQ(profiles.size(), 5u);
    EXPECT_EQ(profiles[0].name, "joystick");
    EXPECT_EQ(profiles[1].name, "wheel");
    EXPECT_EQ(profiles[2].name, "3axis");
    EXPECT_EQ(profiles[3].name, "iforce1");
    EXPECT_EQ(profiles[4].name, "iforce2");
    for (const DeviceProfile& p : profiles) {
        EXPECT_EQ(find_device_profile(p.name), &p);
        EXPECT_EQ(check_device_profile(p), "") << p.name;
        EXPECT_FALSE(p.description.empty());
    }
    EXPECT_EQ(find_device_profile("Joystick"), nullptr);
    EXPECT_EQ(find_device_profile(""), nullptr);
}

TEST(DeviceProfiles, TheJoystickIsAForceFxClassStick) {
    const DeviceProfile& p = *find_device_profile("joystick");
    ASSERT_EQ(p.axis_count, 2);
    for (int a = 0; a < 2; ++a) {
        EXPECT_EQ(p.axes[a].axis, static_cast<Axis>(a));
        EXPECT_EQ(p.axes[a].kind, AxisKind::linear);
        EXPECT_NEAR(p.axes[a].max_force, kNewtonsPerPoundForce, 0.01);  // about 1 lbf
    }
}

TEST(DeviceProfiles, TheWheelTurns450DegreesEachWayInRadians) {
    const DeviceProfile& p = *find_device_profile("wheel");
    ASSERT_EQ(p.axis_count, 1);
    EXPECT_EQ(p.axes[0].kind, AxisKind::rotary);
    EXPECT_NEAR(p.axes[0].half_travel, 450 * std::numbers::pi / 180, 1e-12);
    EXPECT_GE(p.axes[0].max_force, 1.0);  // "a few N·m"
    EXPECT_LE(p.axes[0].max_force, 10.0);
}

TEST(DeviceProfiles, The3AxisDeviceHasXYZ) {
    const DeviceProfile& p = *find_device_profile("3axis");
    ASSERT_EQ(p.axis_count, 3);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(p.axes[a].axis, static_cast<Axis>(a));
}

TEST(DeviceProfiles, VelocityRefIsABriskHandMotion) {
    // Velocity 10000 is a brisk hand motion: 0.2..1.5 m/s at a grip, 5..20 rad/s at a rim.
    for (const DeviceProfile& p : device_profiles()) {
        const AxisModel& a = p.axes[0];
        const double physical = p.velocity_ref / 10000 * a.half_travel;
        if (a.kind == AxisKind::linear) {
            EXPECT_GE(physical, 0.2) << p.name;
            EXPECT_LE(physical, 1.5) << p.name;
        } else {
            EXPECT_GE(physical, 5.0) << p.name;
            EXPECT_LE(physical, 20.0) << p.name;
        }
    }
}

TEST(DeviceProfiles, GripsStiffenInOrderAndAreDampedLikeHumanLimbs) {
    for (const DeviceProfile& p : device_profiles()) {
        EXPECT_LT(p.loose.stiffness, p.firm.stiffness) << p.name;
        EXPECT_LT(p.firm.stiffness, p.stiff.stiffness) << p.name;
        EXPECT_LE(p.loose.added_mass, p.firm.added_mass) << p.name;
        EXPECT_LE(p.firm.added_mass, p.stiff.added_mass) << p.name;
        for (Grip g : {Grip::loose, Grip::firm, Grip::stiff}) {
            const GripModel& grip = test::grip_of(p, g);
            const double m = p.axes[0].mass + grip.added_mass;
            const double zeta = (grip.damping + p.axes[0].viscous) / (2 * std::sqrt(grip.stiffness * m));
            EXPECT_GE(zeta, 0.1) << p.name << " " << grip_name(g);  // underdamped, like an arm
            EXPECT_LE(zeta, 0.5) << p.name << " " << grip_name(g);
            const double hz = std::sqrt(grip.stiffness / m) / (2 * std::numbers::pi);
            EXPECT_GE(hz, 1.0) << p.name << " " << grip_name(g);  // arm resonances: 1..12 Hz
            EXPECT_LE(hz, 12.0) << p.name << " " << grip_name(g);
        }
    }
}

TEST(DeviceProfiles, FullForceBarelyPressesIntoTheStops) {
    // A stop yields less than 1% of the travel to the motor's full force.
    for (const DeviceProfile& p : device_profiles()) {
        for (int a = 0; a < p.axis_count; ++a) {
            const AxisModel& ax = p.axes[a];
            EXPECT_LT(ax.max_force / ax.end_stop_stiffness, 0.01 * ax.half_travel) << p.name;
        }
    }
}

TEST(DeviceProfiles, CheckNamesTheBadFieldAndItsRange) {
    DeviceProfile p = test::bare_profile(0.1, 0, 0);
    EXPECT_EQ(check_device_profile(p), "");
    p.axis_count = 7;
    EXPECT_EQ(check_device_profile(p), "axis_count = 7 is out of range (allowed 1..6)");
    p = test::bare_profile(0.1, -1, 0);
    EXPECT_EQ(check_device_profile(p),
              "axes[0].viscous = -1 is out of range (allowed a finite value >= 0, N·s/m or N·m·s/rad)");
    p = test::bare_profile(0.1, 0, 0);
    p.axes[0].half_travel = std::nan("");
    EXPECT_NE(check_device_profile(p).find("axes[0].half_travel = nan"), std::string::npos);
    p = test::bare_profile(0.1, 0, 0);
    p.axes[0].sensor_counts = 1;
    EXPECT_EQ(check_device_profile(p), "axes[0].sensor_counts = 1 is out of range (allowed 2..16777216)");
    p = test::bare_profile(0.1, 0, 0);
    p.axes[0].axis = Axis::y;
    EXPECT_NE(check_device_profile(p).find("axis 0 of a device must be x"), std::string::npos);
    p = test::bare_profile(0.1, 0, 0);
    p.stiff.damping = -2;
    EXPECT_NE(check_device_profile(p).find("stiff.damping = -2"), std::string::npos);
    p = test::bare_profile(0.1, 0, 0);
    p.velocity_ref = 0;
    EXPECT_NE(check_device_profile(p).find("velocity_ref = 0"), std::string::npos);
    // The texts must reach the host whole in its device-info report.
    const std::string long_text(192, 'd');
    p = test::bare_profile(0.1, 0, 0);
    p.description = long_text;
    EXPECT_EQ(check_device_profile(p), "description is 192 bytes long (allowed 0..191 bytes)");
    p = test::bare_profile(0.1, 0, 0);
    p.name = std::string_view(long_text).substr(0, 24);
    EXPECT_EQ(check_device_profile(p), "name is 24 bytes long (allowed 1..23 bytes)");
    p = test::bare_profile(0.1, 0, 0);
    p.firmware_version = std::string_view(long_text).substr(0, 24);
    EXPECT_EQ(check_device_profile(p), "firmware_version is 24 bytes long (allowed 1..23 bytes)");
}

}  // namespace
}  // namespace feel::sim

namespace feel::sim {
namespace {

// The engine's normalized view of a device follows from the profile's physical facts:
// F_norm = F·10000/max_force and x_norm = x·10000/half_travel.
TEST(EngineConfigFor, FollowsTheProfilesPhysicalFacts) {
    for (const DeviceProfile& p : device_profiles()) {
        const EngineConfig c = engine_config_for(p);
        const AxisModel& a = p.axes[0];
        EXPECT_EQ(c.axis_count, p.axis_count) << p.name;
        EXPECT_FLOAT_EQ(c.velocity_ref, static_cast<float>(p.velocity_ref)) << p.name;
        EXPECT_FLOAT_EQ(c.sensor_step, static_cast<float>(20000.0 / a.sensor_counts)) << p.name;
        // A damping b resists velocity v with b·v newtons; in normalized units that force is
        // b·v·10000/max_force at a normalized velocity of v·10000/half_travel.
        const double v_phys = 0.1;
        const double force_norm = a.viscous * v_phys * 10000.0 / a.max_force;
        const double v_norm = v_phys * 10000.0 / a.half_travel;
        EXPECT_NEAR(c.device_damping, force_norm / v_norm, 1e-6 * force_norm / v_norm) << p.name;  // float
        // A mass m accelerated at a needs m·a newtons: m·a·10000/max_force normalized, at a
        // normalized acceleration of a·10000/half_travel.
        const double a_phys = 2.0;
        const double inertial_norm = a.mass * a_phys * 10000.0 / a.max_force;
        const double a_norm = a_phys * 10000.0 / a.half_travel;
        EXPECT_NEAR(c.device_mass, inertial_norm / a_norm, 1e-6 * inertial_norm / a_norm) << p.name;
        EXPECT_GT(c.acceleration_ref, 0.0f);
    }
}

}  // namespace
}  // namespace feel::sim
