// The safety features of §2.2 in closed loop: engine, simulated device and hand, and the
// SafetyMonitor between the engine and the motors, as the runtime's tick runs them:
//
//   schedule.apply(device, t)   the hand grabs or lets go (InputSchedule)
//   device.sense(in)            positions, buttons, the dead-man switch
//   engine.tick(in, out)        the effects' forces
//   safety.process(...)         dead-man, fade-in, hands-off, watchdog
//   if host_lost_event: engine.stop_all()
//   device.step(force, dt)
//
// Against the rules: no force at all while the switch says "not held"; after each grab the
// force is the engine's times (t − t_grab)/fade_in_us; a handle let go under a strong force
// on a device without a switch is caught, faded out and left alone, and reaches far less
// speed than the bare handle would under that force (closed form below); the hand that
// grabs it again re-arms the monitor and the force ramps back; a silent host stops every
// effect on the first tick past its timeout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "engine_fixture.hpp"
#include "feel/runtime/safety.hpp"
#include "feel/sim/input_schedule.hpp"
#include "feel/sim/sim_device.hpp"
#include "runtime_tick.hpp"

namespace feel::runtime {
namespace {

using test_support::kTickUs;

// One tick's record.
struct Tick {
    int64_t t_us = 0;
    float wanted = 0;        // the engine's force on x
    float output = 0;        // what the motor got on x
    float output_y = 0;
    double velocity = 0;     // the handle's true speed on x, normalized units/s
    double position = 0;     // the handle's true position on x
    SafetyState safety{};
};

// The runtime's per-tick pipeline around an engine, a simulated device and a monitor.
class Rig {
public:
    Rig(const sim::DeviceProfile& profile, sim::Grip grip, SafetyConfig config,
        sim::TargetMotion motion = sim::TargetMotion::hold_at({0}))
        : engine_(sim::engine_config_for(profile)),
          device_(profile, grip, std::move(motion)),
          schedule_(profile) {
        const Error e = safety_.configure(config);
        EXPECT_TRUE(e.ok()) << e.message();
    }

    EffectId play(const EffectParams& p) {
        const CreateResult r = engine_.create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(engine_.start(r.id).ok());
        return r.id;
    }

    Tick step() {
        schedule_.apply(device_, t_us_);
        TickInput in;
        in.t_us = t_us_;
        device_.sense(in);
        TickOutput out;
        engine_.tick(in, out);
        float force[kMaxAxes];
        std::copy(std::begin(out.force), std::end(out.force), force);
        const SafetyState& s = safety_.process(safety_input(in, out, applied_, host_heard_us_), force);
        if (s.host_lost_event) engine_.stop_all();
        device_.step(force, static_cast<double>(kTickUs) * 1e-6);
        std::copy(force, force + kMaxAxes, applied_);
        Tick tick{t_us_, out.force[0], force[0], force[1], device_.velocity(0), device_.position(0), s};
        t_us_ += kTickUs;
        return tick;
    }

    // Steps until t_us (exclusive) and returns every tick.
    std::vector<Tick> run_until(int64_t t_us) {
        std::vector<Tick> ticks;
        while (t_us_ < t_us) ticks.push_back(step());
        return ticks;
    }

    Engine& engine() { return engine_; }
    sim::SimDevice& device() { return device_; }
    sim::InputSchedule& schedule() { return schedule_; }
    SafetyMonitor& safety() { return safety_; }
    void hear_host() { host_heard_us_ = t_us_; }

private:
    Engine engine_;
    sim::SimDevice device_;
    sim::InputSchedule schedule_;
    SafetyMonitor safety_;
    float applied_[kMaxAxes] = {};
    int64_t host_heard_us_ = 0;
    int64_t t_us_ = 0;
};

SafetyConfig no_watchdog(const sim::DeviceProfile& profile, int64_t fade_in_us) {
    SafetyConfig c = safety_config_for(profile);
    c.fade_in_us = fade_in_us;
    c.host_timeout_us = kInfiniteUs;
    return c;
}

// The safety ramp after a grab at t_grab.
double ramp(int64_t t_us, int64_t t_grab_us, int64_t fade_in_us) {
    return std::clamp(static_cast<double>(t_us - t_grab_us) / static_cast<double>(fade_in_us), 0.0, 1.0);
}

// --- the dead-man switch and the safety fade-in -------------------------------------------

// The joystick has a switch. Grab (power-on), let go, grab again, let go, grab again.
TEST(SafetyClosedLoop, GrabLetGoGrabWithTheDeadManSwitch) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const int64_t fade_in = 300'000;
    Rig rig(joystick, sim::Grip::firm, no_watchdog(joystick, fade_in));
    rig.play(feel::test::constant_on_x(6000, kInfiniteUs));
    rig.play(feel::test::on_xy_polar(feel::test::constant_on_x(4000, kInfiniteUs), 0));  // pushes +y
    rig.schedule().let_go(1'000'000).grab(1'500'000).let_go(2'200'000).grab(2'350'000);

    const std::vector<Tick> ticks = rig.run_until(4'000'000);
    double x_at_let_go = 0;
    double max_drift = 0;
    for (const Tick& t : ticks) {
        const bool held = rig.schedule().hand_present_at(t.t_us);
        ASSERT_EQ(t.safety.handle_held, held) << t.t_us;
        ASSERT_LE(std::fabs(t.output), 10000.0f);
        ASSERT_FALSE(t.safety.hands_off) << t.t_us;
        if (!held) {
            // Nothing at all, on every axis.
            ASSERT_EQ(t.output, 0.0f) << t.t_us;
            ASSERT_EQ(t.output_y, 0.0f) << t.t_us;
            if (t.t_us == 1'000'000) x_at_let_go = t.position;
            if (t.t_us < 1'500'000) max_drift = std::max(max_drift, std::fabs(t.position - x_at_let_go));
            continue;
        }
        const int64_t grab = t.t_us >= 2'350'000 ? 2'350'000 : t.t_us >= 1'500'000 ? 1'500'000 : 0;
        ASSERT_NEAR(t.output, t.wanted * ramp(t.t_us, grab, fade_in), 0.01) << t.t_us;
    }
    // The engine asked for its force all along, and got it in full between the ramps.
    EXPECT_EQ(ticks[999].wanted, 6000.0f);
    EXPECT_EQ(ticks[999].output, 6000.0f);
    // Unattended, with no force, the handle does not move around: it stays where the hand
    // left it (it was at rest, held at the balance of motor and grip).
    EXPECT_LT(max_drift, 10.0);
    // Held again, the grip and the motor balance again at F/k_g (statics, within friction)
    // from where the hand wants the handle: it took it where it was at the grab and brings
    // it back to its target, d0·(1 + s/τ)·e^(−s/τ) of the way left.
    const sim::AxisModel& ax = joystick.axes[0];
    const double statics = 0.6 * ax.max_force / joystick.firm.stiffness * 10000 / ax.half_travel;
    const double band = ax.coulomb / joystick.firm.stiffness * 10000 / ax.half_travel;
    const double d0 = ticks[2'349].position;
    const double s = (4.0 - 2.35) / sim::kRegrabReturnS;
    EXPECT_NEAR(ticks.back().position, statics + d0 * (1 + s) * std::exp(-s), band + 5);
}

// --- hands-off protection ----------------------------------------------------------------

struct HandsOffCase {
    const char* device;
    int32_t force;       // the constant force, normalized
    const char* motion;  // what the hand does: a deliberate wiggle it keeps up throughout
    friend void PrintTo(const HandsOffCase& c, std::ostream* os) {
        *os << c.device << " under " << c.force << ", hand " << c.motion;
    }
};

// The speed the bare handle reaches at the end stop +10000, let go at x0 with speed v0
// (> −A/c) under a constant force F > 0: with A = k·F − f_c,
//   v(t) = A/c + (v0 − A/c)·e^(−ct),  x(t) = x0 + A/c·t + (v0 − A/c)·(1 − e^(−ct))/c,
// solved for x(t) = 10000 by bisection.
double unprotected_impact_speed(const FreeHandleModel& h, double force, double x0, double v0) {
    const double k = h.accel_per_force, c = h.damping_rate, fc = h.friction_accel;
    const double a = k * force - fc;
    const auto v = [&](double t) { return a / c + (v0 - a / c) * std::exp(-c * t); };
    const auto x = [&](double t) {
        return x0 + a / c * t + (v0 - a / c) * (1 - std::exp(-c * t)) / c;
    };
    double lo = 0, hi = 10;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (x(mid) < 10000 ? lo : hi) = mid;
    }
    return v(lo);
}

class HandsOffClosedLoop : public ::testing::TestWithParam<HandsOffCase> {};

// A device without a dead-man switch: a firm hand holds the handle against a strong
// constant force, moving it about, lets go at 1 s and grabs again at 2.5 s.
TEST_P(HandsOffClosedLoop, AFreeHandleIsCaughtLeftAloneAndReArmedByTheHand) {
    const HandsOffCase c = GetParam();
    sim::DeviceProfile profile = *sim::find_device_profile(c.device);
    profile.dead_man_switch = false;  // the joystick's is taken off; the others have none
    const int64_t fade_in = 400'000;
    const SafetyConfig config = no_watchdog(profile, fade_in);
    const HandsOffConfig& h = config.hands_off;
    Rig rig(profile, sim::Grip::firm, config,
            sim::TargetMotion::parse(c.motion, 4.0, profile.axis_count));
    rig.play(feel::test::constant_on_x(c.force, kInfiniteUs));
    rig.schedule().let_go(1'000'000).grab(3'500'000);

    // Held: the fade-in completes and nothing trips.
    const std::vector<Tick> held = rig.run_until(1'000'000);
    for (const Tick& t : held) {
        ASSERT_TRUE(t.safety.handle_held);  // no switch: always "held"
        ASSERT_FALSE(t.safety.hands_off) << t.t_us;
        ASSERT_NEAR(t.output, t.wanted * ramp(t.t_us, 0, fade_in), 0.01) << t.t_us;
    }
    const double x_let_go = rig.device().position(0);
    const double v_let_go = rig.device().velocity(0);

    // Let go: caught within a window, the confirm time and a few ticks of estimator lag.
    const std::vector<Tick> free = rig.run_until(3'500'000);
    int64_t trip = -1;
    double impact_speed = 0;  // the speed at which it first reaches the stop, if it does
    bool reached_stop = false;
    for (const Tick& t : free) {
        ASSERT_LE(std::fabs(t.output), 10000.0f);
        if (!reached_stop && std::fabs(t.position) >= 10000) reached_stop = true;
        if (!reached_stop) impact_speed = std::fabs(t.velocity);
        if (t.safety.hands_off && trip < 0) trip = t.t_us;
        if (trip >= 0) {
            ASSERT_TRUE(t.safety.hands_off) << "re-armed without a hand at " << t.t_us;
            // Fading from full force to 0 over fade_out_us, then nothing.
            const double level = std::max(0.0, 1.0 - static_cast<double>(t.t_us - trip) /
                                                         static_cast<double>(h.fade_out_us));
            ASSERT_NEAR(t.output, t.wanted * level, 0.01) << t.t_us;
        }
    }
    ASSERT_GE(trip, 0) << "the free handle was not caught";
    EXPECT_LE(trip - 1'000'000, 2 * h.window_us + h.confirm_us);
    EXPECT_EQ(rig.safety().state().hands_off_trips, 1u);
    // It does not slam: if it reaches the stop at all, it is at less than half the speed
    // the bare handle would have there under the force (a quarter of the kinetic energy),
    // and it comes to rest.
    const double unprotected = unprotected_impact_speed(h.axes[0], c.force, x_let_go, v_let_go);
    EXPECT_LT(reached_stop ? impact_speed : 0.0, 0.5 * unprotected) << "unprotected " << unprotected;
    EXPECT_EQ(free.back().velocity, 0.0);
    EXPECT_EQ(free.back().output, 0.0f);

    // Grabbed again: the hand pulls the handle toward its target, which the bare handle's
    // model cannot explain; the monitor re-arms and the force ramps back over fade_in_us.
    const std::vector<Tick> regrab = rig.run_until(5'500'000);
    int64_t rearm = -1;
    for (const Tick& t : regrab) {
        ASSERT_LE(std::fabs(t.output), 10000.0f);
        if (!t.safety.hands_off && rearm < 0) rearm = t.t_us;
        if (rearm >= 0) {
            ASSERT_FALSE(t.safety.hands_off) << "tripped again, held, at " << t.t_us;
            ASSERT_NEAR(t.output, t.wanted * ramp(t.t_us, rearm, fade_in), 0.01) << t.t_us;
        } else {
            ASSERT_EQ(t.output, 0.0f);
        }
    }
    ASSERT_GE(rearm, 0) << "the hand was not seen";
    EXPECT_LE(rearm - 3'500'000, 500'000);
    EXPECT_EQ(regrab.back().output, static_cast<float>(c.force));
    EXPECT_EQ(rig.safety().state().hand_rearms, 1u);
}

INSTANTIATE_TEST_SUITE_P(Profiles, HandsOffClosedLoop,
                         ::testing::Values(HandsOffCase{"joystick", 10000, "sine:x:2500:2"},
                                           HandsOffCase{"joystick", 5000, "sine:x:2500:2"},
                                           HandsOffCase{"wheel", 10000, "sine:x:200:1"},
                                           HandsOffCase{"wheel", 6000, "sine:x:200:1"},
                                           HandsOffCase{"3axis", 6000, "sine:x:2500:2"},
                                           HandsOffCase{"3axis", 4000, "sine:x:2500:2"}));

// Held by a firm or stiff hand, a device without a switch never trips under the usual
// loads: a strong constant force, a stiff spring, full-force sines and squares.
TEST(SafetyClosedLoop, AFirmHandNeverTrips) {
    for (const char* name : {"joystick", "wheel", "3axis"}) {
        sim::DeviceProfile profile = *sim::find_device_profile(name);
        profile.dead_man_switch = false;
        for (sim::Grip grip : {sim::Grip::firm, sim::Grip::stiff}) {
            std::vector<EffectParams> loads;
            loads.push_back(feel::test::constant_on_x(10000, kInfiniteUs));
            EffectParams spring;
            spring.type = EffectType::spring;
            spring.conditions[0].pos_coefficient = 10000;
            spring.conditions[0].neg_coefficient = 10000;
            loads.push_back(spring);
            for (int64_t period : {1'000'000, 333'333, 200'000, 100'000, 50'000, 20'000}) {
                loads.push_back(feel::test::periodic_on_x(EffectType::sine, 10000, 0, period, 0, kInfiniteUs));
                loads.push_back(feel::test::periodic_on_x(EffectType::square, 10000, 0, period, 0, kInfiniteUs));
            }
            for (const EffectParams& load : loads) {
                Rig rig(profile, grip, no_watchdog(profile, 100'000));
                rig.play(load);
                rig.run_until(2'000'000);
                EXPECT_EQ(rig.safety().state().hands_off_trips, 0u)
                    << name << " " << sim::grip_name(grip) << " "
                    << effect_type_name(load.type) << " period " << load.periodic.period_us;
            }
        }
    }
}

// --- a hand that yanks the handle -------------------------------------------------------

// The Studio's pointer: a stiff hand whose target jumps between two points, back and forth,
// the handle snapping after it at several times velocity_ref. With an effect pushing the
// handle one way, half of each yank goes with the force, but far faster than the force
// could speed up the bare handle (the hand's spring pulls ~20 times harder than the motor
// can); the other half goes against it. Neither is a free handle: no trip, no fade.
struct Yank {
    const char* what;
    EffectParams load;
    double from;  // the two targets on x
    double to;
};

std::vector<Yank> yanks() {
    std::vector<Yank> out;
    EffectParams spring;
    spring.type = EffectType::spring;
    spring.conditions[0].pos_coefficient = 5000;
    spring.conditions[0].neg_coefficient = 5000;
    out.push_back({"spring 5000, -6000 <-> +6000", spring, -6000, 6000});
    spring.conditions[0].pos_coefficient = 10000;
    spring.conditions[0].neg_coefficient = 10000;
    out.push_back({"spring 10000, -9000 <-> +9000", spring, -9000, 9000});
    EffectParams wall;
    wall.type = EffectType::axis_wall;
    wall.axis_count = 1;
    wall.axes[0] = Axis::x;
    wall.wall = {8000, WallSense::positive, 5000, OffsetMode::absolute, 0, 0, 0, true};
    out.push_back({"wall at +5000, 0 <-> +9500", wall, 0, 9500});
    out.push_back({"wall at +5000, -6000 <-> +9500", wall, -6000, 9500});
    return out;
}

TEST(SafetyClosedLoop, AStiffHandYankingTheHandleAcrossASpringOrAWallNeverTrips) {
    for (const char* name : {"iforce2", "3axis", "wheel"}) {
        const sim::DeviceProfile& profile = *sim::find_device_profile(name);
        for (const Yank& yank : yanks()) {
            for (int64_t every_us : {30'000, 60'000, 120'000, 400'000}) {
                Rig rig(profile, sim::Grip::stiff, no_watchdog(profile, 100'000));
                rig.play(yank.load);
                double target[kMaxAxes] = {yank.from};
                ASSERT_TRUE(rig.device().set_live_target(target, profile.axis_count));
                rig.run_until(500'000);  // faded in, at rest at the first point
                double fastest = 0;
                float lowest_fade = 1;
                for (int i = 0; i < 40; ++i) {
                    target[0] = i % 2 ? yank.from : yank.to;
                    ASSERT_TRUE(rig.device().set_live_target(target, profile.axis_count));
                    for (const Tick& t : rig.run_until(500'000 + (i + 1) * every_us)) {
                        fastest = std::max(fastest, std::fabs(t.velocity));
                        lowest_fade = std::min(lowest_fade, t.safety.fade_level);
                    }
                }
                const std::string what = std::string(name) + ", " + yank.what + ", every " +
                                         std::to_string(every_us / 1000) + " ms";
                // A yank, not a nudge: the handle runs past the runaway speed.
                EXPECT_GT(fastest, rig.safety().config().hands_off.runaway_speed) << what;
                EXPECT_EQ(rig.safety().state().hands_off_trips, 0u) << what;
                EXPECT_EQ(lowest_fade, 1.0f) << what;
            }
        }
    }
}

// --- the host-link watchdog ----------------------------------------------------------------

TEST(SafetyClosedLoop, ASilentHostStopsEveryEffect) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    SafetyConfig config = safety_config_for(joystick);
    config.fade_in_us = 0;
    config.host_timeout_us = 100'000;
    config.host_fade_out_us = 0;  // cut at once (the fade has its own tests)
    Rig rig(joystick, sim::Grip::firm, config);
    const EffectId push = rig.play(feel::test::constant_on_x(3000, kInfiniteUs));
    const EffectId buzz = rig.play(feel::test::periodic_on_x(EffectType::sine, 2000, 0, 50'000, 9000, kInfiniteUs));
    // The host talks every 10 ms (its ~100 Hz game loop) until 1 s, then falls silent.
    int64_t tripped = -1;
    for (int64_t t = 0; t < 1'500'000; t += kTickUs) {
        if (t <= 1'000'000 && t % 10'000 == 0) rig.hear_host();
        const Tick tick = rig.step();
        if (tick.safety.host_lost_event) {
            EXPECT_LT(tripped, 0) << "one event per loss";
            tripped = tick.t_us;
        }
        if (t <= 1'100'000) {
            ASSERT_FALSE(tick.safety.host_lost) << t;  // exactly at the timeout: still there
            ASSERT_EQ(tick.output, tick.wanted) << t;
        } else {
            ASSERT_TRUE(tick.safety.host_lost) << t;
            ASSERT_EQ(tick.output, 0.0f) << t;
        }
        if (t > 1'101'000) {
            ASSERT_EQ(tick.wanted, 0.0f) << "the engine still plays at " << t;
        }
    }
    EXPECT_EQ(tripped, 1'101'000);
    EXPECT_EQ(rig.engine().state(push), EffectState::stopped);
    EXPECT_EQ(rig.engine().state(buzz), EffectState::stopped);
    EXPECT_EQ(rig.safety().state().host_losses, 1u);

    // The host is back: nothing plays until it starts something again.
    rig.hear_host();
    EXPECT_EQ(rig.step().output, 0.0f);
    EXPECT_FALSE(rig.safety().state().host_lost);
    ASSERT_TRUE(rig.engine().start(push).ok());
    rig.hear_host();
    rig.step();  // the start takes effect at the next tick
    rig.hear_host();
    EXPECT_EQ(rig.step().output, 3000.0f);
}

}  // namespace
}  // namespace feel::runtime
