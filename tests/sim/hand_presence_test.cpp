// The hand lets go and grabs again (SimDevice::set_hand_present), against mechanics:
//   held under a constant force F:  the grip spring holds the handle at x = F/k_g (statics)
//   let go:  the bare handle (no hand mass, no spring) accelerates as m·a = F − F_c − b·v,
//            x(t) = F'/b·(t − m/b·(1 − exp(−b·t/m))) with F' = F − F_c, from rest
//   grab:    an inelastic collision: v' = (m·v + m_hand·v_target)/(m + m_hand); the hand
//            takes the handle where it is, its target returning to the motion as
//            d0·(1 + s/τ)·e^(−s/τ)
// and the dead-man switch reports it on a profile that has one, never on one that has not.
#include <gtest/gtest.h>

#include <cmath>

#include "sim_test_support.hpp"

namespace feel::sim {
namespace {

constexpr double kDt = 1e-3;

// Steps with the same force on axis 0, nothing on the others.
void run_x(SimDevice& device, double force, int steps) {
    float f[kMaxAxes] = {static_cast<float>(force)};
    for (int i = 0; i < steps; ++i) device.step(f, kDt);
}

TEST(HandPresence, StartsPresentAndTheSwitchReportsIt) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    ASSERT_TRUE(joystick.dead_man_switch);
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0, 0}));
    EXPECT_TRUE(device.hand_present());
    EXPECT_TRUE(device.handle_held());
    TickInput in;
    in.handle_held = false;
    device.sense(in);
    EXPECT_TRUE(in.handle_held);

    device.set_hand_present(false);
    EXPECT_FALSE(device.handle_held());
    device.sense(in);
    EXPECT_FALSE(in.handle_held);

    device.set_hand_present(true);
    device.sense(in);
    EXPECT_TRUE(in.handle_held);
}

TEST(HandPresence, NoGripMeansNoHandWhateverTheFlag) {
    SimDevice device(*find_device_profile("joystick"), Grip::none, TargetMotion::hold_at({0}));
    device.set_hand_present(true);
    EXPECT_FALSE(device.handle_held());
    TickInput in;
    device.sense(in);
    EXPECT_FALSE(in.handle_held);
}

TEST(HandPresence, ADeviceWithoutASwitchAlwaysReportsHeld) {
    for (const char* name : {"wheel", "3axis"}) {
        const DeviceProfile& profile = *find_device_profile(name);
        ASSERT_FALSE(profile.dead_man_switch) << name;
        for (Grip grip : {Grip::none, Grip::firm}) {
            SimDevice device(profile, grip, TargetMotion::hold_at({0}));
            device.set_hand_present(false);
            TickInput in;
            in.handle_held = false;
            device.sense(in);
            EXPECT_TRUE(in.handle_held) << name << " " << grip_name(grip);
        }
    }
}

// Held, the firm grip holds the handle at F/k_g; let go, the bare handle runs off as a free
// mass; the hand applies no force while it is away.
TEST(HandPresence, LettingGoFreesTheHandle) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const AxisModel& ax = joystick.axes[0];
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0, 0}));
    const double force = 4000;  // normalized
    const double f_phys = force / 10000 * ax.max_force;
    run_x(device, force, 3000);  // 3 s: the grip's ringing (ζ 0.3, 5.8 Hz) has died out
    const double statics = f_phys / joystick.firm.stiffness * test::per_unit(ax);
    const double band = ax.coulomb / joystick.firm.stiffness * test::per_unit(ax);
    EXPECT_NEAR(device.position(0), statics, band + 1.0);
    EXPECT_NEAR(device.velocity(0), 0, 1.0);

    // Let go: from rest (within the friction band) the handle follows the free-mass law.
    device.set_velocity(0, 0);
    const double x0 = device.physical_position(0);
    device.set_hand_present(false);
    const double m = ax.mass;
    const double b = ax.viscous;
    const double f = f_phys - ax.coulomb;
    for (int n = 1; n <= 40; ++n) {
        run_x(device, force, 1);
        const double t = n * kDt;
        const double expected = f / b * (t - m / b * (1 - std::exp(-b * t / m)));
        // Symplectic Euler on h = 1 ms / substeps is first order: |error| <= a·t·h.
        const double h = kDt / device.substeps(kDt);
        EXPECT_NEAR(device.physical_position(0) - x0, expected, f / m * t * h + 1e-12)
            << "t = " << t;
        EXPECT_EQ(device.hand_force(0), 0.0);
    }
    // Without its spring the hand no longer holds it: it ends in the stop, at the depth
    // where the stop spring balances the motor alone.
    run_x(device, force, 1000);
    EXPECT_NEAR(device.physical_position(0), ax.half_travel + f_phys / ax.end_stop_stiffness,
                ax.coulomb / ax.end_stop_stiffness + 1e-9);
}

// Grabbing again is an inelastic collision with the hand (moving with a held target: at
// rest), and then the grip pulls the handle back to F/k_g.
TEST(HandPresence, GrabbingAgainConservesMomentumAndRestoresTheGrip) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const AxisModel& ax = joystick.axes[0];
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0, 0}));
    device.set_hand_present(false);
    ASSERT_TRUE(device.set_position(0, 2000));
    ASSERT_TRUE(device.set_velocity(0, 30000));
    device.set_hand_present(true);
    const double m = ax.mass;
    const double m_hand = joystick.firm.added_mass;
    EXPECT_NEAR(device.velocity(0), 30000 * m / (m + m_hand), 1e-9);
    // Grabbing twice is one grab: a hand already there does not collide again.
    device.set_hand_present(true);
    EXPECT_NEAR(device.velocity(0), 30000 * m / (m + m_hand), 1e-9);

    const double force = -3000;
    run_x(device, force, 3000);
    const double statics = force / 10000 * ax.max_force / joystick.firm.stiffness *
                           test::per_unit(ax);
    const double band = ax.coulomb / joystick.firm.stiffness * test::per_unit(ax);
    EXPECT_NEAR(device.position(0), statics, band + 1.0);
    // The hand pushes back against the motor: hand force = −F at rest (within friction).
    EXPECT_NEAR(device.hand_force(0), -force / 10000 * ax.max_force, ax.coulomb + 1e-6);
}

// A hand following a moving target brings its momentum when it grabs.
TEST(HandPresence, AMovingHandBringsItsMomentum) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const AxisModel& ax = joystick.axes[0];
    // sine:x:5000:2 at t = 0.25 s (half a period): x = 0, v = −2π·2·5000.
    SimDevice device(joystick, Grip::loose, TargetMotion::parse("sine:x:5000:2", 1, 2));
    device.set_hand_present(false);
    run_x(device, 0, 250);
    ASSERT_TRUE(device.set_velocity(0, 0));
    device.set_hand_present(true);
    const double v_hand = -2 * 3.141592653589793 * 2 * 5000;
    const double m = ax.mass;
    const double m_hand = joystick.loose.added_mass;
    EXPECT_NEAR(device.velocity(0), m_hand * v_hand / (m + m_hand), 1e-6 * std::fabs(v_hand));
}

// The kinematic hand lets go too: the handle is then a free mass; grabbing again takes it
// where it is and brings it back to the target along d0·(1 + s/τ)·e^(−s/τ) exactly.
TEST(HandPresence, KinematicHandLetsGoAndTakesBack) {
    const DeviceProfile profile = test::bare_profile(0.2, 0.0, 0.0, 2.0);
    SimDevice device(profile, Grip::kinematic, TargetMotion::hold_at({1000}));
    run_x(device, 10000, 10);
    EXPECT_NEAR(device.position(0), 1000, 1e-9);  // prescribed despite the motor
    device.set_hand_present(false);
    const double x0 = device.physical_position(0);
    run_x(device, 10000, 1000);
    const double t = 1.0;
    const double a = 2.0 / 0.2;
    const double h = kDt / device.substeps(kDt);
    EXPECT_NEAR(device.physical_position(0) - x0, 0.5 * a * t * t, a * t * h + 1e-12);
    EXPECT_EQ(device.hand_force(0), 0.0);
    device.set_hand_present(true);
    const double d0 = device.position(0) - 1000;
    ASSERT_GT(d0, 100.0);
    for (int n = 1; n <= 2000; ++n) {
        run_x(device, 10000, 1);
        const double s = n * kDt / kRegrabReturnS;
        ASSERT_NEAR(device.position(0), 1000 + d0 * (1 + s) * std::exp(-s), 1e-6 * d0) << n;
        ASSERT_NEAR(device.velocity(0), -d0 * s / kRegrabReturnS * std::exp(-s), 1e-6 * d0) << n;
    }
}

// A hand takes the handle where it finds it: the tether starts unstretched (no yank), and
// the hand brings the handle back to its target over a few kRegrabReturnS.
TEST(HandPresence, AGrabTakesTheHandleWhereItIsAndBringsItBack) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const AxisModel& ax = joystick.axes[0];
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0, 0}));
    device.set_hand_present(false);
    ASSERT_TRUE(device.set_position(0, 7000));
    device.set_hand_present(true);
    run_x(device, 0, 1);
    // Unstretched: the hand pushes no more than the mechanism's friction.
    EXPECT_LT(std::fabs(device.hand_force(0)), ax.coulomb + 1e-3);
    double previous = device.position(0);
    for (int n = 0; n < 2000; ++n) {  // the return never overshoots: it is critically damped
        run_x(device, 0, 1);
        ASSERT_LE(device.position(0), previous + 1e-9) << n;
        previous = device.position(0);
    }
    // Within the friction band of where the hand wants it by now.
    const double s = 2.001 / kRegrabReturnS;
    const double target = 7000 * (1 + s) * std::exp(-s);
    const double band = ax.coulomb / joystick.firm.stiffness * test::per_unit(ax);
    EXPECT_NEAR(device.position(0), target, band + 1.0);
}

// The bare handle is lighter than handle plus hand: its stop spring rings faster, and
// step() takes the substeps that keep ω·h <= kSubstepRateH for it.
TEST(HandPresence, TheFreeHandleGetsItsOwnSubsteps) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    const AxisModel& ax = joystick.axes[0];
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0, 0}));
    const auto expected = [&](double m, double k, double b) {
        const double rate = std::max(std::sqrt(k / m), b / m);
        return static_cast<int32_t>(std::ceil(rate * kDt / kSubstepRateH));
    };
    const GripModel& g = joystick.firm;
    EXPECT_EQ(device.substeps(kDt),
              expected(ax.mass + g.added_mass, ax.end_stop_stiffness + g.stiffness,
                       ax.viscous + g.damping + ax.end_stop_damping));
    device.set_hand_present(false);
    EXPECT_EQ(device.substeps(kDt),
              expected(ax.mass, ax.end_stop_stiffness, ax.viscous + ax.end_stop_damping));
    EXPECT_GT(device.substeps(kDt), 9);
}

}  // namespace
}  // namespace feel::sim
