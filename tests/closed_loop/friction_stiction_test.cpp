// Static friction against the engine's own push (issue 16 §1): a free handle pushed by an
// effect smaller than the friction does not move, on every profile at 500 Hz, 1 kHz and
// 10 kHz, with and without the device's mass.
//
// §3.5: friction "always resists the direction of motion", and Coulomb's static friction is
// whatever balances the push, up to f: a handle pushed by less than f does not slide. The
// issue asks that a presliding zone, if one is kept, be at most a few sensor counts, that
// there be no creep under a constant push smaller than f and no chatter at rest. These
// tests measure the handle's true position (the simulated device's, not the sensor's), so
// the zone is judged in physical travel: it must stay within one sensor count.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "friction_loop.hpp"

namespace feel::test {
namespace {

double count_of(const char* profile_name) {
    return 2.0 * 10000 / sim::find_device_profile(profile_name)->axes[0].sensor_counts;
}

// The largest distance of the true handle position on x from where it started.
double largest_travel(const std::vector<LoopRow>& rows) {
    double travel = 0;
    for (const LoopRow& row : rows) travel = std::max(travel, std::fabs(row.x[0] - rows[0].x[0]));
    return travel;
}

// A sine push on x: magnitude, period.
EffectParams sine_push_on_x(int32_t magnitude, int64_t period_us) {
    EffectParams p;
    p.type = EffectType::sine;
    p.duration_us = kInfiniteUs;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.periodic.magnitude = magnitude;
    p.periodic.period_us = period_us;
    return p;
}

TEST(FrictionStiction, AConstantPushSmallerThanTheFrictionDoesNotMoveTheHandle) {
    // §3.5 (friction resists the motion; Coulomb's stiction balances a push below f): the
    // presliding zone under an effect's push is within one sensor count on every profile and
    // rate (before: the bristle's, push/K: 30 to 409 counts), the handle does not creep, and
    // the engine's total force (push and friction) has no step and no sign change.
    const int32_t f = 6000;
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        const double count = count_of(profile_name);
        for (double rate : {500.0, 1000.0, 10000.0}) {
            for (int32_t push : {1500, 3000, 5000, 5900}) {
                for (bool mass_known : {true, false}) {
                    SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz push=" +
                                 std::to_string(push) + (mass_known ? "" : " mass unknown"));
                    const auto rows = run_loop(profile_name, sim::Grip::none, "hold:0",
                                               {friction_on({Axis::x}, f), constant_force_on_x(push)}, 1.0, rate, 0,
                                               mass_known);
                    EXPECT_LE(largest_travel(rows), count);
                    EXPECT_EQ(force_sign_changes(rows, 0, 0), 0);
                    EXPECT_LE(largest_force_step(rows, 0, 0), 1.0);
                    EXPECT_LE(std::fabs(rows.back().force[0]), 1.0);  // friction balances the push
                }
            }
        }
    }
}

TEST(FrictionStiction, AVibrationIsFeltThroughTheFrictionByAHandHoldingStill) {
    // Forces add (§3: the effects' forces are summed); friction "always resists the
    // direction of motion" (§3.5), and a handle held still has none. So a sine of 3000 at
    // 20 Hz (a rumble) played with a friction of 6000 reaches the hand in full: stiction
    // balances the engine's push, not its vibrations (the periodic and sweep waves), or a
    // strong friction would silence every rumble while the hand holds the handle.
    // Tolerance: the stiff grip yields a few counts under 3000, and the bristle answers
    // each count with at most 200 units (docs/stability.md): 20 % of the wave.
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        for (double rate : {500.0, 1000.0, 10000.0}) {
            SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz");
            const auto rows = run_loop(profile_name, sim::Grip::stiff, "hold:0",
                                       {friction_on({Axis::x}, 6000), sine_push_on_x(3000, 50'000)}, 1.0, rate, 0,
                                       true);
            double highest = 0, lowest = 0;
            for (const LoopRow& row : rows) {
                highest = std::max(highest, double(row.force[0]));
                lowest = std::min(lowest, double(row.force[0]));
            }
            EXPECT_GE(highest, 0.8 * 3000);
            EXPECT_LE(lowest, -0.8 * 3000);
        }
    }
}

TEST(FrictionStiction, APushJustLargerThanTheFrictionSlides) {
    // The other side of Coulomb's law: a push above f slides the handle (§3.5), however
    // close to f, and the stiction above does not hold it.
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        SCOPED_TRACE(profile_name);
        const auto rows = run_loop(profile_name, sim::Grip::none, "hold:0",
                                   {friction_on({Axis::x}, 6000), constant_force_on_x(6500)}, 0.5);
        EXPECT_GT(rows.back().x[0] - rows[0].x[0], 10 * count_of(profile_name));
    }
}

TEST(FrictionStiction, ALightHandsSteadyPushNeitherCreepsNorChatters) {
    // A loose hand moves its target from 0 to X in 0.3 s and holds it there: its push on the
    // free handle (the grip's spring, k·(X − x)) settles below the friction. §3.5 and issue
    // 16 §1: "no creep under a constant sub-threshold force" and no chatter. Pushes below
    // f/4 once counted as a free handle for the stop guard, which let go of the push at every
    // stop: the handle ratcheted after the hand (before this test: up to 156 units over the
    // last second and 22–68 force sign changes on every profile at 1 and 10 kHz).
    const int32_t f = 6000;
    for (int32_t X : {200, 1000, 2000}) {
        const std::string path = ::testing::TempDir() + "feel_friction_hand_push_" + std::to_string(X) + ".csv";
        {
            std::ofstream csv(path);
            csv << "0,0\n300000," << X << "\n";
        }
        for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
            const double count = count_of(profile_name);
            for (double rate : {500.0, 1000.0, 10000.0}) {
                SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz X=" + std::to_string(X));
                const auto rows =
                    run_loop(profile_name, sim::Grip::loose, "csv:" + path, {friction_on({Axis::x}, f)}, 2.0, rate);
                double peak = 0;
                for (const LoopRow& row : rows) peak = std::max(peak, std::fabs(row.force[0]));
                if (peak > 0.95 * f) continue;  // the hand's pull on its way slid the handle: not a hold
                double lo = rows.back().x[0], hi = lo;
                for (size_t i = rows.size() / 2; i < rows.size(); ++i) {
                    lo = std::min(lo, rows[i].x[0]);
                    hi = std::max(hi, rows[i].x[0]);
                }
                EXPECT_LE(hi - lo, count);                              // no creep over the last second
                EXPECT_EQ(force_sign_changes(rows, 0, 0, 0.05 * f), 0);  // no chatter
            }
        }
    }
}

}  // namespace
}  // namespace feel::test
