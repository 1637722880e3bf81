// The safety monitor on synthetic input, against the rules of §2.2 and mechanics:
//   * the fade-in is the linear ramp L(t) = (t − t_grab)/fade_in_us, from 0 at the grab
//     tick to 1, at any tick rate; no force at all while the switch says "not held";
//   * the watchdog trips on the first tick with t − heard > timeout, not at the timeout;
//   * hands-off: fed the closed-form motion of a bare handle under a constant force,
//       v(t) = A/c·(1 − e^(−c·t)), A = k·F − f_c,
//     the detector latches; fed the closed-form motion of a handle held by each grip of the
//     joystick (a damped oscillator of mass m + m_hand, under a step and under sinusoids),
//     it does not; a hand's push re-arms it and the forces fade back in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "feel/runtime/safety.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"

namespace feel::runtime {
namespace {

constexpr double kPi = std::numbers::pi;

const sim::DeviceProfile& joystick() { return *sim::find_device_profile("joystick"); }

// The first 1 kHz tick at or after t_us.
int64_t tick_at_or_after(int64_t t_us) { return (t_us + 999) / 1000 * 1000; }

SafetyMonitor configured(const SafetyConfig& c) {
    SafetyMonitor m;
    const Error e = m.configure(c);
    EXPECT_TRUE(e.ok()) << e.message();
    return m;
}

// One tick with the same force on every axis; returns the output on axis 0.
float tick(SafetyMonitor& m, int64_t t_us, float force, bool held = true,
           int64_t host_heard_us = -1) {
    SafetyInput in;
    in.t_us = t_us;
    in.handle_held = held;
    in.host_heard_us = host_heard_us < 0 ? t_us : host_heard_us;
    float f[kMaxAxes];
    for (float& v : f) v = force;
    m.process(in, f);
    return f[0];
}

// --- configuration ----------------------------------------------------------------------

TEST(SafetyConfig, DefaultsAndProfilesAreValid) {
    EXPECT_TRUE(check_safety_config(SafetyConfig{}).ok());
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        const Error e = check_safety_config(safety_config_for(p));
        EXPECT_TRUE(e.ok()) << p.name << ": " << e.message();
    }
}

// The free-handle model is the profile's mechanics in normalized units.
TEST(SafetyConfig, TheFreeHandleModelIsTheProfilesMechanics) {
    const SafetyConfig c = safety_config_for(joystick());
    ASSERT_EQ(c.axis_count, 2);
    // 4.45 N on 0.15 kg is 29.67 m/s²; 1 m is 10000/0.05 units: 5.93e6 units/s² at 10000.
    EXPECT_NEAR(c.hands_off.axes[0].accel_per_force * 10000.0, 29.6667 * 2e5, 2e2);
    EXPECT_NEAR(c.hands_off.axes[1].damping_rate, 0.5 / 0.15, 1e-5);
    EXPECT_NEAR(c.hands_off.axes[0].friction_accel, 1.0 * 2e5, 1.0);  // 0.15 N / 0.15 kg
    EXPECT_FLOAT_EQ(c.hands_off.runaway_speed, 3e5f);
    EXPECT_FLOAT_EQ(c.hands_off.rest_speed, 1e3f);

    const SafetyConfig wheel = safety_config_for(*sim::find_device_profile("wheel"));
    ASSERT_EQ(wheel.axis_count, 1);
    // 2.5 N·m on 0.015 kg·m² is 166.7 rad/s²; 1 rad is 10000/7.854 units.
    EXPECT_NEAR(wheel.hands_off.axes[0].accel_per_force * 10000.0, 166.667 * 10000 / 7.853981634, 1.0);
    EXPECT_FLOAT_EQ(wheel.hands_off.runaway_speed, 6e4f);
}

TEST(SafetyConfig, BadFieldsAreNamedWithTheirRange) {
    const auto message = [](auto mutate) {
        SafetyConfig c;
        mutate(c);
        return check_safety_config(c).message();
    };
    EXPECT_EQ(message([](SafetyConfig& c) { c.axis_count = 7; }),
              "axis_count = 7 is out of range (allowed 1..6)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.fade_in_us = -5; }),
              "fade_in_us = -5 is out of range (allowed 0..65000000)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.host_timeout_us = 0; }),
              "host_timeout_us (or -1: no watchdog) = 0 is out of range (allowed 1..65000000)");
    EXPECT_TRUE(check_safety_config([] {
                    SafetyConfig c;
                    c.host_timeout_us = kInfiniteUs;
                    return c;
                }()).ok());
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.axes[1].accel_per_force = 0; }),
              "hands_off.axes[1].accel_per_force: must be a finite value > 0 (position "
              "units/s² per force unit: max_force / (mass · half_travel))");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.axes[0].damping_rate = NAN; }),
              "hands_off.axes[0].damping_rate: must be a finite value >= 0 (1/s: viscous "
              "damping / mass)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.window_us = 500; }),
              "hands_off.window_us = 500 is out of range (allowed 1000..100000)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.max_mismatch = 1.0f; }),
              "hands_off.max_mismatch: must be within (0, 1) (a ratio of speed gains)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.sustain_us = 2'000'000; }),
              "hands_off.sustain_us = 2000000 is out of range (allowed 0..1000000)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.min_force = 0; }),
              "hands_off.min_force: must be within 1..10000 (force units)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.runaway_speed = INFINITY; }),
              "hands_off.runaway_speed: must be a finite value > 0 (position units/s)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.fade_out_us = 70'000'000; }),
              "hands_off.fade_out_us = 70000000 is out of range (allowed 0..65000000)");
    EXPECT_EQ(message([](SafetyConfig& c) { c.hands_off.stop_zone = 10001; }),
              "hands_off.stop_zone: must be within 1..10000 (position units)");
    // A disabled detector needs no model; axes beyond axis_count are not checked.
    EXPECT_TRUE(check_safety_config([] {
                    SafetyConfig c;
                    c.hands_off.enabled = false;
                    c.hands_off.axes[0].accel_per_force = 0;
                    return c;
                }()).ok());
    EXPECT_TRUE(check_safety_config([] {
                    SafetyConfig c;
                    c.axis_count = 1;
                    c.hands_off.axes[1].accel_per_force = 0;
                    return c;
                }()).ok());

    // A bad configuration changes nothing.
    SafetyMonitor m;
    SafetyConfig good;
    good.fade_in_us = 1234;
    ASSERT_TRUE(m.configure(good).ok());
    SafetyConfig bad;
    bad.axis_count = 0;
    EXPECT_FALSE(m.configure(bad).ok());
    EXPECT_EQ(m.config().fade_in_us, 1234);
}

// --- dead-man switch and fade-in -----------------------------------------------------------

SafetyConfig ramp_only(int64_t fade_in_us) {
    SafetyConfig c;
    c.fade_in_us = fade_in_us;
    c.host_timeout_us = kInfiniteUs;
    c.hands_off.enabled = false;
    return c;
}

TEST(SafetyFadeIn, RampsLinearlyFromZeroAtTheGrabToFullAfterFadeIn) {
    for (int64_t dt_us : {1000, 100, 10000}) {  // 1 kHz, 10 kHz, 100 Hz
        SafetyMonitor m = configured(ramp_only(500'000));
        for (int64_t t = 0; t <= 800'000; t += dt_us) {
            const double want = 8000.0 * std::min(1.0, static_cast<double>(t) / 500'000.0);
            ASSERT_NEAR(tick(m, t, 8000), want, 1e-3) << "dt " << dt_us << " t " << t;
            ASSERT_NEAR(m.state().fade_level, want / 8000.0, 1e-7);
        }
        EXPECT_EQ(tick(m, 900'000, -8000), -8000.0f);  // full force is passed bit-exact
    }
}

TEST(SafetyFadeIn, UnevenTicksFollowTheSameRamp) {
    SafetyMonitor m = configured(ramp_only(300'000));
    int64_t t = 0;
    for (int n = 0; t < 400'000; ++n) {
        const double want = 5000.0 * std::min(1.0, static_cast<double>(t) / 300'000.0);
        ASSERT_NEAR(tick(m, t, 5000), want, 1e-3) << "t " << t;
        t += 137 + (n * 7919) % 3000;  // irregular periods, 137..3136 µs
    }
}

TEST(SafetyDeadMan, NoForceWhileNotHeldAndAFreshRampAfterEachGrab) {
    SafetyMonitor m = configured(ramp_only(200'000));
    // Held from 0: halfway up the ramp at 100 ms.
    for (int64_t t = 0; t <= 100'000; t += 1000) tick(m, t, 6000);
    EXPECT_NEAR(m.state().fade_level, 0.5, 1e-6);
    // Let go at 101 ms: nothing at all, on every axis, at once.
    for (int64_t t = 101'000; t < 400'000; t += 1000) {
        SafetyInput in;
        in.t_us = t;
        in.handle_held = false;
        float f[kMaxAxes] = {10000, -10000, 5000, 1, -1, 3};
        m.process(in, f);
        for (int a = 0; a < kMaxAxes; ++a) ASSERT_EQ(f[a], 0.0f) << "t " << t << " axis " << a;
        ASSERT_FALSE(m.state().handle_held);
        ASSERT_EQ(m.state().fade_level, 0.0f);
    }
    // Grab at 400 ms: the ramp starts again from 0, not from where it was.
    for (int64_t t = 400'000; t <= 700'000; t += 1000) {
        const double want = 6000.0 * std::min(1.0, static_cast<double>(t - 400'000) / 200'000.0);
        ASSERT_NEAR(tick(m, t, 6000), want, 1e-3) << "t " << t;
    }
    // A let-go and grab inside the ramp restart it as well.
    tick(m, 701'000, 6000, false);
    for (int64_t t = 702'000; t <= 800'000; t += 1000) {
        const double want = 6000.0 * static_cast<double>(t - 702'000) / 200'000.0;
        ASSERT_NEAR(tick(m, t, 6000), want, 1e-3) << "t " << t;
    }
}

TEST(SafetyFadeIn, ZeroFadeInRestoresAtOnce) {
    SafetyMonitor m = configured(ramp_only(0));
    EXPECT_EQ(tick(m, 0, 7000), 7000.0f);
    EXPECT_EQ(tick(m, 1000, 7000, false), 0.0f);
    EXPECT_EQ(tick(m, 2000, 7000), 7000.0f);
}

TEST(SafetyActuators, DisabledMeansNoForceAndEnablingFadesIn) {
    SafetyMonitor m = configured(ramp_only(100'000));
    for (int64_t t = 0; t <= 200'000; t += 1000) tick(m, t, 4000);
    EXPECT_EQ(tick(m, 201'000, 4000), 4000.0f);
    m.set_actuators_enabled(false);
    EXPECT_FALSE(m.state().actuators_enabled);
    for (int64_t t = 202'000; t <= 300'000; t += 1000) ASSERT_EQ(tick(m, t, 4000), 0.0f);
    m.set_actuators_enabled(true);
    for (int64_t t = 301'000; t <= 450'000; t += 1000) {
        const double want = 4000.0 * std::min(1.0, static_cast<double>(t - 301'000) / 100'000.0);
        ASSERT_NEAR(tick(m, t, 4000), want, 1e-3) << "t " << t;
    }
}

TEST(SafetyOutput, ForcesAreClampedToTheMotorLimitAndNonFiniteOnesCut) {
    SafetyConfig c = ramp_only(0);
    c.axis_count = 3;
    SafetyMonitor m = configured(c);
    SafetyInput in;
    float f[kMaxAxes] = {25000, -1e30f, NAN, 500, 600, 700};
    m.process(in, f);
    EXPECT_EQ(f[0], 10000.0f);
    EXPECT_EQ(f[1], -10000.0f);
    EXPECT_EQ(f[2], 0.0f);
    EXPECT_EQ(f[3], 0.0f);  // beyond axis_count
    EXPECT_EQ(f[5], 0.0f);
    EXPECT_EQ(m.state().nonfinite_forces, 1u);
    float inf[kMaxAxes] = {INFINITY};
    in.t_us = 1000;
    m.process(in, inf);
    EXPECT_EQ(inf[0], 0.0f);
    EXPECT_EQ(m.state().nonfinite_forces, 2u);
}

// --- host-link watchdog --------------------------------------------------------------------

TEST(SafetyWatchdog, TripsAfterTheTimeoutAndNotBefore) {
    SafetyConfig c = ramp_only(0);
    c.host_timeout_us = 100'000;
    c.host_fade_out_us = 0;  // cut at once: the trip itself is what is looked at here
    SafetyMonitor m = configured(c);
    // The host talks every 10 ms until 500 ms, then falls silent.
    int64_t heard = 0;
    int events = 0;
    for (int64_t t = 0; t <= 700'000; t += 1000) {
        if (t <= 500'000 && t % 10'000 == 0) heard = t;
        const float out = tick(m, t, 3000, true, heard);
        const bool lost = t - heard > 100'000;
        ASSERT_EQ(m.state().host_lost, lost) << "t " << t;
        ASSERT_EQ(out, lost ? 0.0f : 3000.0f) << "t " << t;
        if (m.state().host_lost_event) {
            ++events;
            EXPECT_EQ(t, 601'000);  // the first tick past 500 ms + 100 ms
        }
    }
    EXPECT_EQ(events, 1);
    EXPECT_EQ(m.state().host_losses, 1u);
    // Exactly at the timeout the host still counts as present, one µs later it does not.
    SafetyMonitor edge = configured(c);
    tick(edge, 100'000, 1000, true, 0);
    EXPECT_FALSE(edge.state().host_lost);
    tick(edge, 100'001, 1000, true, 0);
    EXPECT_TRUE(edge.state().host_lost);
    EXPECT_TRUE(edge.state().host_lost_event);
    // Heard again: forces pass at once; a second silence is a second event.
    EXPECT_EQ(tick(edge, 100'002, 1000, true, 100'002), 1000.0f);
    EXPECT_FALSE(edge.state().host_lost);
    tick(edge, 250'000, 1000, true, 100'002);
    EXPECT_TRUE(edge.state().host_lost_event);
    EXPECT_EQ(edge.state().host_losses, 2u);
}

TEST(SafetyWatchdog, ALostHostsForcesFadeOutLinearlyThenTheEventFires) {
    SafetyConfig c = ramp_only(0);
    c.host_timeout_us = 100'000;
    c.host_fade_out_us = 40'000;
    SafetyMonitor m = configured(c);
    // Heard at 0; lost from 100 001 µs on: the factor falls from 1 to 0 over 40 ms from
    // that tick, linearly, and the event fires on the tick it reaches 0.
    int events = 0;
    for (int64_t t = 0; t <= 200'000; t += 1000) {
        const float out = tick(m, t, 5000, true, 0);
        const int64_t lost_at = 101'000;  // the first 1 ms tick past the timeout
        const double factor = t < lost_at ? 1.0 : std::max(0.0, 1.0 - static_cast<double>(t - lost_at) / 40'000.0);
        ASSERT_NEAR(out, 5000.0 * factor, 0.01) << "t " << t;
        ASSERT_EQ(m.state().host_lost, t >= lost_at) << "t " << t;
        if (m.state().host_lost_event) {
            ++events;
            EXPECT_EQ(t, lost_at + 40'000);
        }
    }
    EXPECT_EQ(events, 1);
    EXPECT_EQ(m.state().host_losses, 1u);
    EXPECT_TRUE(m.state().host_faded);
    // Heard again: forces pass at once.
    EXPECT_EQ(tick(m, 201'000, 5000, true, 201'000), 5000.0f);
    EXPECT_FALSE(m.state().host_faded);
}

TEST(SafetyWatchdog, AReleasedHostFadesOutEvenWithoutAWatchdogUntilHeardAgain) {
    SafetyConfig c = ramp_only(0);  // no watchdog
    c.host_fade_out_us = 10'000;
    SafetyMonitor m = configured(c);
    EXPECT_EQ(tick(m, 0, 2000, true, 0), 2000.0f);
    m.release_host(0);  // released at the tick of t = 0, heard at 0
    EXPECT_NEAR(tick(m, 1000, 2000, true, 0), 2000.0f, 0.01);  // the fade's first tick: H = 1
    EXPECT_TRUE(m.state().host_lost);
    EXPECT_NEAR(tick(m, 6000, 2000, true, 0), 1000.0f, 0.01);  // halfway
    EXPECT_EQ(tick(m, 11'000, 2000, true, 0), 0.0f);
    EXPECT_TRUE(m.state().host_lost_event);
    EXPECT_EQ(tick(m, 12'000, 2000, true, 0), 0.0f);
    EXPECT_FALSE(m.state().host_lost_event) << "once per loss";
    // Heard after the release: present again.
    EXPECT_EQ(tick(m, 13'000, 2000, true, 13'000), 2000.0f);
    EXPECT_FALSE(m.state().host_lost);
}

TEST(SafetyWatchdog, AFadeOutTimeOutOfRangeIsRefusedByName) {
    SafetyConfig c = ramp_only(0);
    c.host_fade_out_us = -5;
    SafetyMonitor m;
    const Error e = m.configure(c);
    EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(e.field, "host_fade_out_us");
}

TEST(SafetyWatchdog, AnInfiniteTimeoutNeverTrips) {
    SafetyMonitor m = configured(ramp_only(0));
    EXPECT_EQ(tick(m, 0, 1000, true, 0), 1000.0f);
    EXPECT_EQ(tick(m, 60'000'000, 1000, true, 0), 1000.0f);
    EXPECT_FALSE(m.state().host_lost);
}

// --- hands-off detection -------------------------------------------------------------------

// A motion fed to the monitor: position and velocity of axis 0 at t (s).
struct Motion {
    double x = 0;
    double v = 0;
};

struct Episode {
    int64_t trip_us = -1;    // first tick with hands_off, -1: never
    int64_t rearm_us = -1;   // first tick after the trip without it
};

// Feeds `motion` (axis 0; axis 1 at rest) with the applied force `force(t_us)` from t0 to
// t1 at 1 kHz, the switch reading held, and records when hands-off latched and released.
Episode feed(SafetyMonitor& m, int64_t t0_us, int64_t t1_us,
         const std::function<Motion(double t_s)>& motion,
         const std::function<double(int64_t t_us)>& force) {
    Episode run;
    for (int64_t t = t0_us; t <= t1_us; t += 1000) {
        const Motion s = motion(static_cast<double>(t) * 1e-6);
        SafetyInput in;
        in.t_us = t;
        in.host_heard_us = t;
        in.position[0] = static_cast<float>(s.x);
        in.velocity[0] = static_cast<float>(s.v);
        // The force that acted over the interval that ended now.
        in.applied_force[0] = static_cast<float>(force(t - 1000));
        float f[kMaxAxes] = {static_cast<float>(force(t))};
        m.process(in, f);
        if (m.state().hands_off && run.trip_us < 0) run.trip_us = t;
        if (!m.state().hands_off && run.trip_us >= 0 && run.rearm_us < 0) run.rearm_us = t;
    }
    return run;
}

// The bare joystick handle from rest at x0 under a constant normalized force F (> f_c/k):
// v = A/c·(1 − e^(−ct)), x = x0 + A/c·(t − (1 − e^(−ct))/c), A = kF − f_c.
std::function<Motion(double)> free_handle(const FreeHandleModel& h, double force, double x0,
                                          double t0_s) {
    const double k = h.accel_per_force, c = h.damping_rate, fc = h.friction_accel;
    const double accel = k * force - fc;
    return [=](double t) {
        const double s = std::max(0.0, t - t0_s);
        const double e = std::exp(-c * s);
        return Motion{x0 + accel / c * (s - (1 - e) / c), accel / c * (1 - e)};
    };
}

// Held still under a constant force (a hand holds the handle: no motion while the bare
// handle would accelerate), then let go at 300 ms: the motion becomes exactly the bare
// handle's. Over a window W the measured gain v(t) − v(t − W) grows as (kF − f_c)·t after
// the let-go while the prediction stays (kF − f_c)·W, so it comes within max_mismatch
// when t = (1 − max_mismatch)·W; confirm_us later hands-off latches.
TEST(SafetyHandsOff, ALetGoUnderAStrongForceLatchesWithinAWindowAndTheConfirmTime) {
    const SafetyConfig c = safety_config_for(joystick());
    const FreeHandleModel& h = c.hands_off.axes[0];
    for (double force : {10000.0, 6000.0, 4000.0, -8000.0}) {
        SafetyMonitor m = configured(c);
        const double x0 = force > 0 ? -3000 : 3000;
        const auto free_run = free_handle(h, force, x0, 0.3);
        const auto motion = [&](double t) { return t < 0.3 ? Motion{x0, 0} : free_run(t); };
        const Episode run = feed(m, 0, 400'000, motion, [&](int64_t) { return force; });
        ASSERT_GE(run.trip_us, 0) << "force " << force;
        const double w = 1e-6 * static_cast<double>(c.hands_off.window_us);
        const double confirm = 1e-6 * static_cast<double>(c.hands_off.confirm_us);
        const double trip = static_cast<double>(run.trip_us) * 1e-6;
        EXPECT_GE(trip, 0.3 + (1 - c.hands_off.max_mismatch) * w + confirm - 0.002) << force;
        EXPECT_LE(trip, 0.3 + (1 - c.hands_off.max_mismatch) * w + confirm + 0.002) << force;
        EXPECT_EQ(m.state().hands_off_axes, 1u);
        EXPECT_EQ(m.state().hands_off_trips, 1u);
    }
}

// A force that starts on a handle already free is a push that must first last
// sustain_us; then the match must last confirm_us.
TEST(SafetyHandsOff, APushOnAFreeHandleIsJudgedOnceItHasLasted) {
    const SafetyConfig c = safety_config_for(joystick());
    SafetyMonitor m = configured(c);
    const double force = 6000;  // slow enough to stay below runaway_speed
    const auto motion = free_handle(c.hands_off.axes[0], force, -9500, 0.1);
    const Episode run = feed(m, 0, 200'000, motion,
                             [&](int64_t t) { return t >= 100'000 ? force : 0.0; });
    ASSERT_GE(run.trip_us, 0);
    // The first interval with the force ends at 101 ms: the push starts there; the match
    // starts at the first tick it has lasted sustain_us, and confirms confirm_us later.
    const int64_t sustained = tick_at_or_after(101'000 + c.hands_off.sustain_us);
    EXPECT_EQ(run.trip_us, tick_at_or_after(sustained + c.hands_off.confirm_us));
}

TEST(SafetyHandsOff, AWeakForceIsNotJudged) {
    const SafetyConfig c = safety_config_for(joystick());
    SafetyMonitor m = configured(c);
    const double force = 2000;  // below min_force: cannot make a free handle dangerous
    const auto motion = free_handle(c.hands_off.axes[0], force, -9000, 0.0);
    const Episode run = feed(m, 0, 300'000, motion, [&](int64_t) { return force; });
    EXPECT_LT(run.trip_us, 0);
}

// Once latched, the forces fall linearly from where they were to 0 over fade_out_us.
TEST(SafetyHandsOff, ForcesFadeOutOverTheFadeOutTime) {
    SafetyConfig c = safety_config_for(joystick());
    c.fade_in_us = 0;
    SafetyMonitor m = configured(c);
    const double force = 8000;
    const auto motion = free_handle(c.hands_off.axes[0], force, -9000, 0.0);
    int64_t trip = -1;
    for (int64_t t = 0; t <= 100'000; t += 1000) {
        const Motion s = motion(static_cast<double>(t) * 1e-6);
        SafetyInput in;
        in.t_us = t;
        in.host_heard_us = t;
        in.position[0] = static_cast<float>(s.x);
        in.velocity[0] = static_cast<float>(s.v);
        in.applied_force[0] = static_cast<float>(force);
        float f[kMaxAxes] = {static_cast<float>(force)};
        m.process(in, f);
        if (m.state().hands_off && trip < 0) trip = t;
        const double level =
            trip < 0 ? 1.0
                     : std::max(0.0, 1.0 - static_cast<double>(t - trip) /
                                           static_cast<double>(c.hands_off.fade_out_us));
        ASSERT_NEAR(f[0], force * level, 1e-2) << "t " << t;
    }
    ASSERT_GE(trip, 0);
    EXPECT_EQ(m.state().fade_level, 0.0f);
}

// The joystick held by each grip: m_total = m + m_hand, spring k_g, damping b + b_g. The
// handle's normalized motion under a force step F from rest at equilibrium is the
// underdamped step response x = x_s·(1 − e^(−ζωt)(cos ω_d t + ζω/ω_d·sin ω_d t)).
struct HeldAxis {
    double a0;     // units/s² per force unit: the motor's acceleration of the held mass
    double omega;  // rad/s
    double zeta;
};

HeldAxis held_axis(sim::Grip grip) {
    const sim::DeviceProfile& p = joystick();
    const sim::AxisModel& ax = p.axes[0];
    const sim::GripModel& g = grip == sim::Grip::loose ? p.loose
                              : grip == sim::Grip::firm ? p.firm
                                                        : p.stiff;
    const double m = ax.mass + g.added_mass;
    const double w = std::sqrt(g.stiffness / m);
    return {ax.max_force / (m * ax.half_travel), w, (ax.viscous + g.damping) / (2 * m * w)};
}

TEST(SafetyHandsOff, AHeldHandleUnderAForceStepDoesNotLatch) {
    const SafetyConfig c = safety_config_for(joystick());
    for (sim::Grip grip : {sim::Grip::loose, sim::Grip::firm, sim::Grip::stiff}) {
        for (double force : {10000.0, -10000.0, 5000.0}) {
            const HeldAxis h = held_axis(grip);
            const double xs = h.a0 * force / (h.omega * h.omega);
            const double wd = h.omega * std::sqrt(1 - h.zeta * h.zeta);
            const auto motion = [&](double t) {
                const double s = std::max(0.0, t - 0.05);
                const double e = std::exp(-h.zeta * h.omega * s);
                return Motion{xs * (1 - e * (std::cos(wd * s) + h.zeta * h.omega / wd * std::sin(wd * s))),
                              xs * h.omega * h.omega / wd * e * std::sin(wd * s)};
            };
            SafetyMonitor m = configured(c);
            const Episode run = feed(m, 0, 1'500'000, motion,
                                 [&](int64_t t) { return t >= 50'000 ? force : 0.0; });
            EXPECT_LT(run.trip_us, 0) << sim::grip_name(grip) << " " << force;
        }
    }
}

// Steady-state response of the held handle to F·sin(2πft): x = |H|·a0·F·sin(ωt − φ) with
// H = 1/(ω0² − ω² + 2iζω0ω). Firm and stiff grips never pass for free. The loose grip
// (ω0 = 3.6 Hz) is tested below its resonance and well above it; between about 1.2 and
// 2.5 times its resonance a full-force vibration drives the loosely held handle almost as
// it drives the bare one (the resonance makes up for the hand's mass), and the detector
// may take it for free: the hand is barely holding (safety.cpp, docs/runtime.md).
TEST(SafetyHandsOff, AHeldHandleUnderAVibrationDoesNotLatch) {
    const SafetyConfig c = safety_config_for(joystick());
    for (sim::Grip grip : {sim::Grip::loose, sim::Grip::firm, sim::Grip::stiff}) {
        for (double hz : {1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 20.0, 50.0, 100.0}) {
            const HeldAxis h = held_axis(grip);
            const double w = 2 * kPi * hz;
            if (grip == sim::Grip::loose && w > 1.2 * h.omega && w < 2.5 * h.omega) continue;
            const double re = h.omega * h.omega - w * w, im = 2 * h.zeta * h.omega * w;
            const double gain = 1 / std::hypot(re, im);
            const double phase = std::atan2(im, re);
            const double force = 10000;
            const auto motion = [&](double t) {
                const double amp = gain * h.a0 * force;
                return Motion{amp * std::sin(w * t - phase), amp * w * std::cos(w * t - phase)};
            };
            SafetyMonitor m = configured(c);
            const Episode run = feed(m, 0, 1'000'000, motion, [&](int64_t t) {
                return force * std::sin(w * static_cast<double>(t) * 1e-6);
            });
            EXPECT_LT(run.trip_us, 0) << sim::grip_name(grip) << " " << hz << " Hz";
        }
    }
}

// A fast handle that a sustained push keeps speeding up, if only at 75% of the bare
// handle's rate (a model that is off by more than the match allows), is free: latched as
// soon as the push has lasted sustain_us. Its speed solves v' = 0.75·(k·F − f_c − c·v):
// v(t) = A/c + (v0 − A/c)·e^(−0.75·c·t), A = k·F − f_c.
TEST(SafetyHandsOff, ARunawayWithASustainedPushAlongItLatches) {
    const SafetyConfig c = safety_config_for(joystick());
    const FreeHandleModel& h = c.hands_off.axes[0];
    const double fast = c.hands_off.runaway_speed * 1.01;
    const auto running = [&](double direction, double force) {
        const double a = h.accel_per_force * force - h.friction_accel;
        return [=](double t) {
            const double v = a / h.damping_rate +
                             (fast - a / h.damping_rate) * std::exp(-0.75 * h.damping_rate * t);
            return Motion{0, direction * v};
        };
    };
    for (double direction : {1.0, -1.0}) {
        SafetyMonitor m = configured(c);
        const Episode run = feed(m, 0, 200'000, running(direction, 8000),
                                 [&](int64_t) { return direction * 8000; });
        // The window fills at the first tick a window old; the push must then last
        // sustain_us.
        const int64_t filled = tick_at_or_after(c.hands_off.window_us);
        EXPECT_EQ(run.trip_us, tick_at_or_after(filled + c.hands_off.sustain_us)) << direction;
    }
    // Coasting as fast with the force against it is a hand (or a braking effect): no latch.
    const auto coasting = [&](double) { return Motion{0, fast}; };
    SafetyMonitor against = configured(c);
    EXPECT_LT(feed(against, 0, 200'000, coasting, [](int64_t) { return -8000.0; }).trip_us, 0);
    // So is coasting with the force along it but not speeding up: something holds it back.
    SafetyMonitor held_back = configured(c);
    EXPECT_LT(feed(held_back, 0, 200'000, coasting, [](int64_t) { return 8000.0; }).trip_us, 0);
    // Nor a weak force along it.
    SafetyMonitor weak = configured(c);
    EXPECT_LT(feed(weak, 0, 200'000, running(1, 2000), [](int64_t) { return 2000.0; }).trip_us, 0);
}

// A hand that throws the handle along a sustained push, faster than the push could speed up
// the bare handle, is a hand: a free handle gains what its motor gives it (within the
// model's tolerance), not three times that. Here the speed grows as v' = 3·(k·F − f_c − c·v)
// from past the runaway speed.
TEST(SafetyHandsOff, AHandThrowingTheHandleAlongThePushIsNoRunaway) {
    const SafetyConfig c = safety_config_for(joystick());
    const FreeHandleModel& h = c.hands_off.axes[0];
    const double fast = c.hands_off.runaway_speed * 1.01;
    const double force = 8000;
    const double a = h.accel_per_force * force - h.friction_accel;
    const auto thrown = [&](double t) {
        return Motion{0, a / h.damping_rate + (fast - a / h.damping_rate) * std::exp(-3 * h.damping_rate * t)};
    };
    SafetyMonitor m = configured(c);
    EXPECT_LT(feed(m, 0, 200'000, thrown, [&](int64_t) { return force; }).trip_us, 0);
}

// Let go while moving against a sustained push (a hand was dragging it the other way), the
// bare handle first slows down, turns, and only then does the push drive it toward a stop.
// It is judged from the turn on, as a handle let go at rest would be: hands-off latches
// after the turn, within a window and the confirm time of it. Until the turn it moves away
// from where the push throws it. The free motion, with A± = k·F ± f_c (friction opposes
// the motion): v = A+/c + (v0 − A+/c)·e^(−c·s) until v = 0 at
// s_turn = ln((A+/c − v0)/(A+/c))/c, then from rest v = A−/c·(1 − e^(−c·s')).
TEST(SafetyHandsOff, AHandleLetGoMovingAgainstThePushIsJudgedFromItsTurn) {
    const SafetyConfig c = safety_config_for(joystick());
    const FreeHandleModel& h = c.hands_off.axes[0];
    const double k = h.accel_per_force, damping = h.damping_rate, fc = h.friction_accel;
    for (double force : {10000.0, 6000.0}) {
        const double v0 = -100000;  // dragged against the push at velocity_ref, 0.5 m/s
        const double let_go = 0.3;
        const double up = (k * force + fc) / damping, down = (k * force - fc) / damping;
        const double s_turn = std::log((up - v0) / up) / damping;
        // held still at +4000 under the push, then dragged against it from 250 ms
        const double drag = 0.25;
        const double x_let_go = 4000 + v0 * (let_go - drag);
        const double x_turn = x_let_go + up * s_turn + (v0 - up) * (1 - std::exp(-damping * s_turn)) / damping;
        const auto motion = [&](double t) {
            if (t < drag) return Motion{4000, 0};
            if (t < let_go) return Motion{4000 + v0 * (t - drag), v0};
            const double s = t - let_go;
            if (s < s_turn) {
                const double e = std::exp(-damping * s);
                return Motion{x_let_go + up * s + (v0 - up) * (1 - e) / damping, up + (v0 - up) * e};
            }
            const double r = s - s_turn;
            const double e = std::exp(-damping * r);
            return Motion{x_turn + down * (r - (1 - e) / damping), down * (1 - e)};
        };
        SafetyMonitor m = configured(c);
        const Episode run = feed(m, 0, 400'000, motion, [&](int64_t) { return force; });
        ASSERT_GE(run.trip_us, 0) << force;
        const double trip = static_cast<double>(run.trip_us) * 1e-6;
        const double turn = let_go + s_turn;
        const double w = 1e-6 * static_cast<double>(c.hands_off.window_us);
        const double confirm = 1e-6 * static_cast<double>(c.hands_off.confirm_us);
        EXPECT_GT(trip, turn) << force;
        EXPECT_LE(trip, turn + w + confirm + 0.002) << force;
    }
}

// The bare handle of a FreeHandleModel axis, integrated finely (100 Euler substeps per
// tick), with a stop at ±10000 that bounces it back at half its speed: an impact the
// monitor's model knows nothing of. Optionally a hand pushes it with hand_accel.
struct BareHandle {
    FreeHandleModel model;
    double x = 0;
    double v = 0;
    double hand_accel = 0;  // units/s²
    int bounces = 0;

    void step(double force, double dt) {
        const double h = dt / 100;
        for (int i = 0; i < 100; ++i) {
            const double drive = model.accel_per_force * force - model.damping_rate * v + hand_accel;
            double v_next;
            if (v == 0 && std::fabs(drive) <= model.friction_accel) {
                v_next = 0;  // dry friction holds it
            } else {
                const double dir = v != 0 ? (v > 0 ? 1.0 : -1.0) : (drive > 0 ? 1.0 : -1.0);
                v_next = v + (drive - model.friction_accel * dir) * h;
                if (v != 0 && v_next * v < 0) v_next = 0;  // friction stops, never reverses
            }
            v = v_next;
            x += v * h;
            if (std::fabs(x) >= 10000 && x * v > 0) {
                x = std::copysign(10000.0, x);
                v = -0.5 * v;
                ++bounces;
            }
        }
    }
};

// Closes the loop between the monitor and a BareHandle at 1 kHz from t0 to t1 with the
// engine asking for `wanted` throughout; returns when hands-off latched and released.
Episode close_loop(SafetyMonitor& m, BareHandle& handle, double wanted, int64_t t0, int64_t t1,
                   float* last_output, bool held = false) {
    Episode run;
    for (int64_t t = t0; t <= t1; t += 1000) {
        SafetyInput in;
        in.t_us = t;
        in.host_heard_us = t;
        in.position[0] = static_cast<float>(std::clamp(handle.x, -10000.0, 10000.0));
        in.velocity[0] = static_cast<float>(handle.v);
        in.applied_force[0] = *last_output;
        float f[kMaxAxes] = {static_cast<float>(wanted)};
        m.process(in, f);
        *last_output = f[0];
        if (m.state().hands_off && run.trip_us < 0) run.trip_us = t;
        if (!m.state().hands_off && run.trip_us >= 0 && run.rearm_us < 0) run.rearm_us = t;
        if (!held) handle.step(f[0], 1e-3);
    }
    return run;
}

// Released under a strong force, the bare handle is caught; it coasts into the stop and
// bounces, which is not a hand; at rest, it stays off; a hand's push re-arms the monitor
// after hand_confirm_us, and the forces fade in from 0.
TEST(SafetyHandsOff, StopBouncesAreNotAHandButAHandsPushReArms) {
    SafetyConfig c = safety_config_for(joystick());
    c.fade_in_us = 200'000;
    SafetyMonitor m = configured(c);
    BareHandle handle{.model = c.hands_off.axes[0], .x = 3000};
    float applied = 0;
    // A hand holds the handle still through the fade-in, then lets go at 300 ms.
    const Episode held = close_loop(m, handle, 8000, 0, 300'000, &applied, /*held=*/true);
    EXPECT_LT(held.trip_us, 0);
    EXPECT_EQ(applied, 8000.0f);
    const Episode caught = close_loop(m, handle, 8000, 301'000, 1'000'000, &applied);
    ASSERT_GE(caught.trip_us, 0);
    EXPECT_LT(caught.rearm_us, 0) << "bounces and coasting are not a hand";
    EXPECT_GE(handle.bounces, 1);
    EXPECT_EQ(handle.v, 0.0) << "at rest";
    EXPECT_EQ(m.state().output_scale, 0.0f);
    EXPECT_EQ(m.state().hand_rearms, 0u);

    // A hand pushes it toward the centre at 6 m/s² (1.2e6 units/s²), with no motor force.
    const double push = 1.2e6;
    handle.hand_accel = handle.x > 0 ? -push : push;
    const Episode pushed = close_loop(m, handle, 5000, 1'001'000, 1'100'000, &applied);
    ASSERT_GE(pushed.rearm_us, 0);
    // Unexplained over a window W: at least the push, push·t, which reaches
    // hand_accel·W by t_seen; then hand_confirm_us.
    const double w = 1e-6 * static_cast<double>(c.hands_off.window_us);
    const double t_seen = w * c.hands_off.hand_accel / push;
    EXPECT_GE(pushed.rearm_us, 1'001'000 + c.hands_off.hand_confirm_us);
    EXPECT_LE(static_cast<double>(pushed.rearm_us) * 1e-6,
              1.001 + t_seen + 1e-6 * static_cast<double>(c.hands_off.hand_confirm_us) + 0.003);
    EXPECT_EQ(m.state().hand_rearms, 1u);
    // Forces fade in from the re-arm tick (the hand keeps the handle where it is now).
    handle.hand_accel = 0;
    const int64_t t_rearm = pushed.rearm_us;
    for (int64_t t = 1'101'000; t <= 1'400'000; t += 1000) {
        const double want = 5000.0 * std::min(1.0, static_cast<double>(t - t_rearm) / 200'000.0);
        SafetyInput in;
        in.t_us = t;
        in.host_heard_us = t;
        float f[kMaxAxes] = {5000};
        m.process(in, f);
        ASSERT_NEAR(f[0], want, 1e-2) << "t " << t;
    }
}

// A grab on the dead-man switch is a hand at once.
TEST(SafetyHandsOff, AGrabOnTheSwitchReArmsAtOnce) {
    SafetyConfig c = safety_config_for(joystick());
    c.fade_in_us = 100'000;
    SafetyMonitor m = configured(c);
    const auto free_run = free_handle(c.hands_off.axes[0], 9000, -5000, 0.2);
    const Episode run = feed(
        m, 0, 250'000, [&](double t) { return t < 0.2 ? Motion{-5000, 0} : free_run(t); },
        [](int64_t) { return 9000.0; });
    ASSERT_GE(run.trip_us, 0);
    EXPECT_EQ(tick(m, 251'000, 9000, false), 0.0f);
    EXPECT_TRUE(m.state().hands_off);  // the latch stays while not held
    EXPECT_EQ(tick(m, 252'000, 9000, true), 0.0f);
    EXPECT_FALSE(m.state().hands_off);
    EXPECT_EQ(m.state().hand_rearms, 1u);
    EXPECT_NEAR(tick(m, 302'000, 9000, true), 4500.0, 1e-2);
}

TEST(SafetyHandsOff, NotJudgedWhileTheSwitchSaysNotHeld) {
    SafetyConfig c = safety_config_for(joystick());
    SafetyMonitor m = configured(c);
    const auto motion = free_handle(c.hands_off.axes[0], 10000, -9000, 0.0);
    for (int64_t t = 0; t <= 100'000; t += 1000) {
        const Motion s = motion(static_cast<double>(t) * 1e-6);
        SafetyInput in;
        in.t_us = t;
        in.handle_held = false;
        in.position[0] = static_cast<float>(s.x);
        in.velocity[0] = static_cast<float>(s.v);
        in.applied_force[0] = 10000;
        float f[kMaxAxes] = {10000};
        m.process(in, f);
        ASSERT_FALSE(m.state().hands_off);
        ASSERT_EQ(f[0], 0.0f);
    }
}

TEST(SafetyMonitorReset, ResetIsPowerOn) {
    SafetyConfig c = ramp_only(100'000);
    c.host_timeout_us = 10'000;
    SafetyMonitor m = configured(c);
    for (int64_t t = 0; t <= 200'000; t += 1000) tick(m, t, 1000, true, 0);
    EXPECT_TRUE(m.state().host_lost);
    m.set_actuators_enabled(false);
    m.reset();
    EXPECT_FALSE(m.state().host_lost);
    EXPECT_EQ(m.state().host_losses, 0u);
    EXPECT_EQ(m.state().fade_level, 0.0f);
    EXPECT_FALSE(m.state().actuators_enabled);  // the host's enable survives a reset
}

}  // namespace
}  // namespace feel::runtime
