// A handle without a hand, against the closed-form motion of a mass:
//   constant force:   x = F·t²/(2m), v = F·t/m
//   viscous only:     v = v0·exp(−b·t/m)
//   Coulomb only:     stops after t = v0·m/F_c, having slid v0²·m/(2·F_c)
// with the error bounds of the integrator (semi-implicit Euler, implicit damping).
#include <gtest/gtest.h>

#include <cmath>

#include "sim_test_support.hpp"

namespace feel::sim {
namespace {

using test::bare_profile;

TEST(FreeMass, ConstantForceFollowsTheParabolaWithinTheEulerBound) {
    // m = 0.2 kg, F = 2 N: a = 10 m/s². Semi-implicit Euler gives v_n = a·n·h exactly and
    // x_n = a·h²·n(n+1)/2 = a·t²/2 + a·t·h/2: the error is positive and at most a·t·h/2.
    const double m = 0.2, f = 2.0, a = f / m;
    for (double dt : {1e-4, 1e-3, 1e-2}) {
        const DeviceProfile profile = bare_profile(m, 0, 0, f);
        SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
        const double h = dt / device.substeps(dt);
        const double scale = test::per_unit(profile.axes[0]);
        const int steps = static_cast<int>(std::lround(1.0 / dt));
        float force[kMaxAxes] = {10000};
        for (int n = 1; n <= steps; ++n) {
            device.step(force, dt);
            const double t = n * dt;
            const double x = device.position(0) / scale;
            const double error = x - a * t * t / 2;
            ASSERT_GE(error, -1e-12 * (1 + x)) << "dt " << dt << " t " << t;
            ASSERT_LE(error, a * t * h / 2 * (1 + 1e-9) + 1e-12) << "dt " << dt << " t " << t;
            ASSERT_NEAR(device.velocity(0) / scale, a * t, 1e-9 * a * t);
        }
    }
}

TEST(FreeMass, MotorForceSaturatesAtTheProfileLimit) {
    const DeviceProfile profile = bare_profile(0.5, 0, 0, 3.0);
    SimDevice full(profile, Grip::none, TargetMotion::hold_at({0}));
    SimDevice over(profile, Grip::none, TargetMotion::hold_at({0}));
    SimDevice half(profile, Grip::none, TargetMotion::hold_at({0}));
    SimDevice negative(profile, Grip::none, TargetMotion::hold_at({0}));
    test::run(full, 10000, 1e-3, 500);
    test::run(over, 25000, 1e-3, 500);
    test::run(half, 5000, 1e-3, 500);
    test::run(negative, -1e30f, 1e-3, 500);
    const double scale = test::per_unit(profile.axes[0]);
    EXPECT_NEAR(full.velocity(0) / scale, 3.0 / 0.5 * 0.5, 1e-9);  // v = F·t/m
    EXPECT_EQ(over.position(0), full.position(0));
    EXPECT_NEAR(half.velocity(0) / scale, 1.5 / 0.5 * 0.5, 1e-9);
    EXPECT_EQ(negative.position(0), -full.position(0));
}

TEST(FreeMass, ViscousDecayMatchesTheExponentialWithinTheImplicitEulerBound) {
    // m = 0.5 kg, b = 2 N·s/m: λ = b/m = 4/s. Implicit Euler gives v_n = v0·(1 + λh)^−n,
    // which lies between v0·e^−λt and v0·e^−λt·e^(λ²·h·t/2).
    const double m = 0.5, b = 2.0, lambda = b / m, v0 = 1.0;
    const DeviceProfile profile = bare_profile(m, b, 0);
    const double scale = test::per_unit(profile.axes[0]);
    double error_at_1s[2] = {};
    int which = 0;
    for (double dt : {2e-3, 1e-3}) {
        SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
        ASSERT_TRUE(device.set_velocity(0, v0 * scale));
        const double h = dt / device.substeps(dt);
        const int steps = static_cast<int>(std::lround(1.0 / dt));
        for (int n = 1; n <= steps; ++n) {
            test::run(device, 0, dt, 1);
            const double t = n * dt;
            const double exact = v0 * std::exp(-lambda * t);
            const double ratio = device.velocity(0) / scale / exact;
            ASSERT_GE(ratio, 1 - 1e-12) << "t " << t;
            ASSERT_LE(ratio, std::exp(lambda * lambda * h * t / 2) + 1e-12) << "t " << t;
        }
        error_at_1s[which++] = device.velocity(0) / scale - v0 * std::exp(-lambda);
        // Position: x = v0/λ·(1 − e^−λt), to first order in h.
        EXPECT_NEAR(device.position(0) / scale, v0 / lambda * (1 - std::exp(-lambda)),
                    v0 * lambda * h);
    }
    // First-order method: halving the step halves the error.
    EXPECT_NEAR(error_at_1s[0] / error_at_1s[1], 2.0, 0.05);
}

TEST(FreeMass, CoulombFrictionStopsASlidingMassAtV0MOverFc) {
    // m = 0.3 kg, F_c = 0.6 N: decelerates at 2 m/s²; from 1 m/s it stops after 0.5 s and
    // 0.25 m.
    const double m = 0.3, fc = 0.6, v0 = 1.0, dt = 1e-3;
    const DeviceProfile profile = bare_profile(m, 0, fc);
    const double scale = test::per_unit(profile.axes[0]);
    SimDevice device(profile, Grip::none, TargetMotion::hold_at({0}));
    ASSERT_TRUE(device.set_velocity(0, v0 * scale));
    double t_stop = -1;
    for (int n = 1; n <= 1000 && t_stop < 0; ++n) {
        test::run(device, 0, dt, 1);
        if (device.velocity(0) == 0) t_stop = n * dt;
    }
    EXPECT_NEAR(t_stop, v0 * m / fc, dt);
    EXPECT_NEAR(device.position(0) / scale, v0 * v0 * m / (2 * fc), v0 * dt);
    // Stopped means stopped: no chatter, no creep.
    const double x_stop = device.position(0);
    for (int n = 0; n < 1000; ++n) {
        test::run(device, 0, dt, 1);
        ASSERT_EQ(device.velocity(0), 0.0);
        ASSERT_EQ(device.position(0), x_stop);
    }
}

TEST(FreeMass, CoulombFrictionHoldsAgainstASmallerForceAndYieldsToALargerOne) {
    const double m = 0.3, fc = 0.6, max_force = 1.2, dt = 1e-3;
    const DeviceProfile profile = bare_profile(m, 0, fc, max_force);
    const double scale = test::per_unit(profile.axes[0]);

    SimDevice held(profile, Grip::none, TargetMotion::hold_at({0}));
    for (int n = 0; n < 1000; ++n) {
        test::run(held, n % 2 == 0 ? 4900.0f : -4900.0f, dt, 1);  // ±0.588 N < F_c
        ASSERT_EQ(held.velocity(0), 0.0);
        ASSERT_EQ(held.position(0), 0.0);
    }

    // 1.2 N against 0.6 N of friction: a = 2 m/s², x = t² after 1 s, first order in h.
    SimDevice sliding(profile, Grip::none, TargetMotion::hold_at({0}));
    test::run(sliding, 10000, dt, 1000);
    const double a = (max_force - fc) / m;
    EXPECT_NEAR(sliding.velocity(0) / scale, a * 1.0, 1e-9);
    EXPECT_NEAR(sliding.position(0) / scale, a / 2, a * dt / 2 + 1e-12);
}

}  // namespace
}  // namespace feel::sim
