// End stops and position sensors.
//   stops:   under a constant force F the handle rests at half_travel + F/k_s; on the way
//            there it cannot penetrate further than energy allows, ½·k_s·p² <= F·(d + p);
//            a stop never returns more energy than it received.
//   sensors: readings are multiples of 20000/sensor_counts, within half a step of the
//            truth, and end at ±10000.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "sim_test_support.hpp"

namespace feel::sim {
namespace {

TEST(EndStop, FullForceRestsTheHandleJustPastTheEndOfTheTravel) {
    for (const DeviceProfile& profile : device_profiles()) {
        for (float sign : {1.0f, -1.0f}) {
            SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
            double deepest = 0;
            float force[kMaxAxes];
            std::fill(std::begin(force), std::end(force), sign * 10000.0f);
            for (int n = 0; n < 5000; ++n) {
                device.step(force, 1e-3);
                deepest = std::max(deepest, std::fabs(device.position(0)));
            }
            for (int a = 0; a < profile.axis_count; ++a) {
                const AxisModel& ax = profile.axes[a];
                const double scale = test::per_unit(ax);
                const double rest = ax.half_travel + ax.max_force / ax.end_stop_stiffness;
                const double band = ax.coulomb / ax.end_stop_stiffness;
                SCOPED_TRACE(std::string(profile.name) + " axis " + std::to_string(a));
                EXPECT_NEAR(device.position(a), sign * rest * scale, band * scale + 1e-6);
                EXPECT_LT(std::fabs(device.position(a)), 10100);  // "near ±10000": within 1%
            }
            // Energy bound on the impact: the motor did work F·(d + p) over the run-up of
            // d = half_travel, all of it at most stored in the stop spring.
            const AxisModel& ax = profile.axes[0];
            const double f = ax.max_force, k = ax.end_stop_stiffness, d = ax.half_travel;
            const double p_max = (f + std::sqrt(f * f + 2 * k * f * d)) / k;
            EXPECT_LE(deepest, (d + p_max) * test::per_unit(ax)) << profile.name;
        }
    }
}

TEST(EndStop, ADampedStopDissipatesAndAnUndampedOneIsElastic) {
    for (double damping : {0.0, 20.0}) {
        DeviceProfile profile = test::bare_profile(0.2, 0, 0, 1.0, 0.05);
        profile.axes[0].end_stop_stiffness = 2e4;
        profile.axes[0].end_stop_damping = damping;
        SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
        const double scale = test::per_unit(profile.axes[0]);
        ASSERT_TRUE(device.set_velocity(0, 1.0 * scale));  // 1 m/s toward +x
        const double dt = 1e-3;
        const double omega_h = std::sqrt(2e4 / 0.2) * dt / device.substeps(dt);
        test::run(device, 0, dt, 150);  // reaches the stop at 50 ms, leaves well before 150 ms
        ASSERT_LT(device.position(0), 10000);
        const double v_out = -device.velocity(0) / scale;
        if (damping == 0) {
            EXPECT_NEAR(v_out, 1.0, omega_h);
        } else {
            EXPECT_GT(v_out, 0.0);
            EXPECT_LT(v_out, 0.9);
        }
    }
}

TEST(EndStop, TheStopPushesButNeverPullsTheHandleBackIn) {
    // A handle released from inside a stop, with no friction anywhere but the stop's own
    // damping: the stop damps only while the handle presses deeper, so on the way out
    // it keeps accelerating the handle outward and returns all of ½·k·p0² (elastic
    // release, speed p0·√(k/m), within the integrator's ripple).
    const DeviceProfile profile = test::with_friction(*find_device_profile("joystick"), 0, 0);
    const AxisModel& ax = profile.axes[0];
    SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
    ASSERT_TRUE(device.set_position(0, 10300));  // pressed 1.5 mm into the +x stop
    const double dt = 1e-3;
    const double omega = std::sqrt(ax.end_stop_stiffness / ax.mass);
    double v_previous = 0;
    while (device.position(0) > 10000) {
        test::run(device, 0, dt, 1);
        ASSERT_LE(device.velocity(0), v_previous);
        v_previous = device.velocity(0);
    }
    const double p0 = 300 / test::per_unit(ax);
    const double v_exit = -device.velocity(0) / test::per_unit(ax);
    EXPECT_NEAR(v_exit, p0 * omega, p0 * omega * omega * dt / device.substeps(dt));
}

TEST(Sensor, ReadingsStepBy20000OverTheSensorCounts) {
    for (const DeviceProfile& profile : device_profiles()) {
        const AxisModel& ax = profile.axes[0];
        const double step = 20000.0 / ax.sensor_counts;
        SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
        std::set<float> readings;
        for (int i = -100000; i <= 100000; ++i) {
            const double x = i * 0.1;
            ASSERT_TRUE(device.set_position(0, x));
            TickInput in;
            device.sense(in);
            const double r = in.position[0];
            ASSERT_LE(std::fabs(r - x), step / 2 + 1e-3) << profile.name << " x " << x;
            ASSERT_NEAR(r / step, std::round(r / step), 1e-6) << profile.name << " x " << x;
            readings.insert(in.position[0]);
        }
        EXPECT_EQ(readings.size(), static_cast<size_t>(ax.sensor_counts) + 1) << profile.name;
        float previous = *readings.begin();
        for (auto it = std::next(readings.begin()); it != readings.end(); ++it) {
            ASSERT_NEAR(*it - previous, step, 1e-3) << profile.name;
            previous = *it;
        }
        EXPECT_EQ(*readings.begin(), -10000.0f);
        EXPECT_EQ(*readings.rbegin(), 10000.0f);
    }
}

TEST(Sensor, AHandlePressedIntoAStopReadsTheEndOfTheTravel) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    SimDevice device(joystick, Grip::none, TargetMotion::hold_at({0}));
    ASSERT_TRUE(device.set_position(0, 10400));
    ASSERT_TRUE(device.set_position(1, -12000));
    TickInput in;
    device.sense(in);
    EXPECT_EQ(in.position[0], 10000.0f);
    EXPECT_EQ(in.position[1], -10000.0f);
}

TEST(Sensor, MissingAxesReadZeroAndNoButtonIsPressed) {
    const DeviceProfile& wheel = *find_device_profile("wheel");
    SimDevice device(wheel, Grip::none, TargetMotion::hold_at({2500}));
    TickInput in;
    std::fill(std::begin(in.position), std::end(in.position), 123.0f);
    in.buttons = 0xFFFFFFFF;
    in.t_us = 42;
    device.sense(in);
    EXPECT_NEAR(in.position[0], 2500, 20000.0 / wheel.axes[0].sensor_counts / 2);
    for (int a = 1; a < kMaxAxes; ++a) EXPECT_EQ(in.position[a], 0.0f);
    EXPECT_EQ(in.buttons, 0u);
    EXPECT_EQ(in.t_us, 42);  // the caller's
}

}  // namespace
}  // namespace feel::sim
