// The simulation under abuse and repetition: identical runs are bit-identical, absurd
// inputs never produce NaN or inf, and bad profiles and motions are refused up front.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim_test_support.hpp"

namespace feel::sim {
namespace {

// A fixed pseudo-random force sequence (64-bit LCG), the same on every platform.
struct Lcg {
    uint64_t state = 0x9E3779B97F4A7C15ull;
    float next_force() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<float>(static_cast<int64_t>(state >> 40) % 20001 - 10000);
    }
};

std::vector<double> record_run(const DeviceProfile& profile, Grip grip, const char* motion) {
    SimDevice device(profile, grip, TargetMotion::parse(motion, 3, profile.axis_count));
    Lcg lcg;
    std::vector<double> trace;
    for (int n = 0; n < 3000; ++n) {
        float f[kMaxAxes] = {};
        for (int a = 0; a < profile.axis_count; ++a) f[a] = lcg.next_force();
        device.step(f, n % 7 == 0 ? 0.9e-3 : 1.0e-3);  // an uneven clock, like µs rounding
        for (int a = 0; a < profile.axis_count; ++a) {
            trace.push_back(device.physical_position(a));
            trace.push_back(device.physical_velocity(a));
            trace.push_back(device.hand_force(a));
        }
        TickInput in;
        device.sense(in);
        trace.insert(trace.end(), std::begin(in.position), std::end(in.position));
    }
    return trace;
}

TEST(Determinism, TwoIdenticalRunsAreBitIdentical) {
    for (const DeviceProfile& profile : device_profiles()) {
        for (Grip grip : {Grip::none, Grip::loose, Grip::stiff, Grip::kinematic}) {
            const char* motion = profile.axis_count >= 2 ? "circle:6000:1.5" : "sine:x:6000:1.5";
            const std::vector<double> a = record_run(profile, grip, motion);
            const std::vector<double> b = record_run(profile, grip, motion);
            ASSERT_EQ(a.size(), b.size());
            EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0)
                << profile.name << " " << grip_name(grip);
        }
    }
}

// bound: the largest |normalized position| the inputs allow.
void expect_finite_and_bounded(const SimDevice& device, const std::string& where,
                               double bound = 11500) {
    for (int a = 0; a < device.profile().axis_count; ++a) {
        ASSERT_TRUE(std::isfinite(device.physical_position(a))) << where;
        ASSERT_TRUE(std::isfinite(device.physical_velocity(a))) << where;
        ASSERT_TRUE(std::isfinite(device.hand_force(a))) << where;
        ASSERT_LE(std::fabs(device.position(a)), bound) << where;
    }
    TickInput in;
    device.sense(in);
    for (float p : in.position) ASSERT_TRUE(std::isfinite(p)) << where;
}

TEST(Robustness, AbsurdForcesAndStepsNeverProduceNaN) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    const float forces[] = {std::nanf(""), kInf, -kInf, FLT_MAX, -FLT_MAX, 1e30f, -1e30f,
                            10000, -10000, 0, FLT_MIN, -0.0f};
    const double good_dts[] = {1e-4, 1e-3, 1e-2, 0.3, 1.0, 1e-9};
    const double bad_dts[] = {0.0, -1e-3, std::nan(""), std::numeric_limits<double>::infinity(),
                              1.0000001, 1e300};
    // Holding still, the handle can only be thrown into a stop by the motor: the energy
    // bound of the end-stop test, (F + √(F² + 2·k·F·d))/k with a full-travel run-up d,
    // keeps every built-in profile within 11500. A hand shaking the handle at 50 Hz over
    // the full travel is not bounded by the motor, only finite.
    struct Case {
        const char* motion_2d;
        const char* motion_1d;
        double bound;
    };
    for (const Case& c : {Case{"hold:0", "hold:0", 11500},
                          Case{"circle:10000:50", "sine:x:10000:50", 1e9}}) {
        for (const DeviceProfile& profile : device_profiles()) {
            for (Grip grip : {Grip::none, Grip::loose, Grip::firm, Grip::stiff, Grip::kinematic}) {
                const char* motion = profile.axis_count >= 2 ? c.motion_2d : c.motion_1d;
                const std::string where = std::string(profile.name) + " " +
                                          std::string(grip_name(grip)) + " " + motion;
                SimDevice device(profile, grip, TargetMotion::parse(motion, 1, profile.axis_count));
                int64_t nonfinite = 0;
                for (double dt : good_dts) {
                    for (float f : forces) {
                        float force[kMaxAxes];
                        for (float& v : force) v = f;
                        for (int n = 0; n < 20; ++n) {
                            // Bang-bang at the loop rate: the hardest thing a motor can do.
                            force[0] = n % 2 == 0 ? f : -f;
                            device.step(force, dt);
                            if (!std::isfinite(f)) nonfinite += profile.axis_count;
                            expect_finite_and_bounded(device, where + " dt " + std::to_string(dt),
                                                      c.bound);
                        }
                    }
                }
                const double t = device.time_s();
                for (double dt : bad_dts) {
                    float force[kMaxAxes] = {10000, 10000, 10000};
                    device.step(force, dt);
                }
                EXPECT_EQ(device.time_s(), t) << where;
                EXPECT_EQ(device.rejected_steps(), 6) << where;
                EXPECT_EQ(device.nonfinite_forces(), nonfinite) << where;
                expect_finite_and_bounded(device, where, c.bound);
            }
        }
    }
}

TEST(Robustness, ANaNForceActsLikeNoForce) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    SimDevice with_nan(joystick, Grip::firm, TargetMotion::parse("sine:y:4000:3", 1, 2));
    SimDevice with_zero(joystick, Grip::firm, TargetMotion::parse("sine:y:4000:3", 1, 2));
    for (int n = 0; n < 1000; ++n) {
        const float f_nan[kMaxAxes] = {std::nanf(""), 2000};
        const float f_zero[kMaxAxes] = {0, 2000};
        with_nan.step(f_nan, 1e-3);
        with_zero.step(f_zero, 1e-3);
        ASSERT_EQ(with_nan.physical_position(0), with_zero.physical_position(0));
        ASSERT_EQ(with_nan.physical_position(1), with_zero.physical_position(1));
    }
    EXPECT_EQ(with_nan.nonfinite_forces(), 1000);
    EXPECT_EQ(with_zero.nonfinite_forces(), 0);
}

TEST(Robustness, AnAbsurdlyStiffProfileFallsBackToStableSprings) {
    // A 1 mg handle on a 1e12 N/m stop: ω = 3e7 rad/s, far beyond what kMaxSubsteps can
    // resolve at 100 Hz. The springs switch to backward Euler; the state stays finite
    // and the handle ends at rest against the stop.
    DeviceProfile profile = test::bare_profile(1e-6, 0, 0, 1.0, 0.05);
    profile.axes[0].end_stop_stiffness = 1e12;
    profile.axes[0].end_stop_damping = 1e3;
    SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
    EXPECT_EQ(device.substeps(1e-2), kMaxSubsteps);
    for (int n = 0; n < 500; ++n) {
        test::run(device, 10000, 1e-2, 1);
        expect_finite_and_bounded(device, "step " + std::to_string(n));
    }
    EXPECT_NEAR(device.position(0), 10000, 1e-3);
}

TEST(Robustness, SubstepsKeepTheStiffestSpringResolvedAtEveryLoopRate) {
    for (const DeviceProfile& profile : device_profiles()) {
        for (Grip grip : {Grip::none, Grip::stiff}) {
            SimDevice device(profile, grip, TargetMotion::hold_at({0}));
            const GripModel g = grip == Grip::stiff ? profile.stiff : GripModel{};
            for (double rate : {100.0, 500.0, 1000.0, 10000.0}) {
                const double h = 1 / rate / device.substeps(1 / rate);
                for (int a = 0; a < profile.axis_count; ++a) {
                    const AxisModel& ax = profile.axes[a];
                    const double m = ax.mass + g.added_mass;
                    const double omega = std::sqrt((ax.end_stop_stiffness + g.stiffness) / m);
                    EXPECT_LE(omega * h, kSubstepRateH * (1 + 1e-12)) << profile.name << " " << rate;
                }
            }
        }
    }
}

TEST(Robustness, BadProfilesAndMotionsAreRefusedWhenTheDeviceIsMade) {
    DeviceProfile p = test::bare_profile(0.1, 0, 0);
    p.axes[0].mass = 0;
    try {
        SimDevice device(p, Grip::none, TargetMotion::hold_at({0}));
        ADD_FAILURE() << "accepted a massless handle";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("axes[0].mass = 0 is out of range"), std::string::npos)
            << e.what();
    }
    const DeviceProfile& wheel = *find_device_profile("wheel");
    try {
        SimDevice device(wheel, Grip::firm, TargetMotion::hold_at({0, 100}));
        ADD_FAILURE() << "accepted a 2-axis motion on the wheel";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("moves 2 axes, but device \"wheel\" has 1"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(SimDevice(wheel, static_cast<Grip>(17), TargetMotion::hold_at({0})),
                 std::invalid_argument);
}

TEST(Robustness, TestHooksRefuseBadAxesAndValues) {
    const DeviceProfile& wheel = *find_device_profile("wheel");
    SimDevice device(wheel, Grip::none, TargetMotion::hold_at({0}));
    EXPECT_FALSE(device.set_position(1, 0));
    EXPECT_FALSE(device.set_position(-1, 0));
    EXPECT_FALSE(device.set_position(0, std::nan("")));
    EXPECT_FALSE(device.set_position(0, 20001));
    EXPECT_FALSE(device.set_velocity(0, 1e300));
    EXPECT_TRUE(device.set_position(0, -20000));
    EXPECT_EQ(device.position(0), -20000);
    EXPECT_EQ(device.position(3), 0);
    EXPECT_EQ(device.velocity(-2), 0);
}

}  // namespace
}  // namespace feel::sim
