// Walls that stay passive (issue section 3), shown in closed loop on every device profile.
//
// The setup: a firm hand pushes the handle into a wall (axis_wall on x, surface at 0, free
// side x < 0) for 0.5 s, then lets go. A constant force of 40% of the motor's range keeps
// pushing the handle into the wall afterwards, like a weight resting on the handle:
// without it a released handle simply drifts off the wall and there is nothing left to
// ring. The hand pushes with 60% of the motor's range, so hand and weight together meet
// the full force the wall can resist, the hardest press the device can hold; letting go
// is then the largest disturbance the wall can receive without being pushed through.
// After the release the handle is free (no grip) for 5 s and we watch its true position;
// the last two seconds tell a sustained swing from the transient of the release (the
// wheel's light damping takes seconds to let a transient die).
//
// Thresholds, from the physics rather than from runs:
//   * settled: over the last second the handle moves less than two sensor counts peak to
//     peak (a handle at rest can at most sit across one count boundary);
//   * ringing: over the last second it swings by at least the static penetration
//     F_push/K peak to peak, i.e. it leaves the wall every cycle (the way a linearly
//     unstable contact saturates is by losing contact), and the swing has not shrunk
//     since the second before by more than the mechanism's own damping would shrink a
//     passive oscillation, e^(−b/(2m)·1 s).
//
// Stiffnesses are multiples of each profile's naive bound 2b/T (Colgate & Schenkel).
// Every profile's mechanism has Coulomb friction F_c, which takes 4F_c/K off the swing of
// every cycle; a wall above the bound grows its swing by a fraction g(K) per cycle, so a
// swing smaller than 4F_c/(K·g) dies, and a wall that saturates the motor during a bounce
// creates nothing while saturated. A wall a little above the bound can therefore sit
// still after the release, and the "well above" walls here are 20× the bound, where the
// cycle sustains itself on every profile (in this setup the joystick rings from 10×, the
// wheel, with the most friction for its inertia, from 15×, the 3-axis device from 2×;
// docs/stability.md works the numbers). The frictionless test shows that the bound
// itself is where the linear theory puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "contact_loop.hpp"

namespace feel::test::loop {
namespace {

enum class Element { wall, barrier };

struct Outcome {
    double last = 0;          // peak-to-peak of x over the last second, normalized units
    double before = 0;        // ... over the second before it
    double first = 0;         // ... over the first second after the release
    double static_depth = 0;  // the push's penetration F_push/K
    double settle_band = 0;   // two sensor counts
    double decay = 0;         // e^(−b/(2m)·1 s): the most a passive swing keeps per second
};

constexpr int32_t kPush = 4000;          // the weight, 40% of the motor's range
constexpr double kHandFraction = 0.6;    // the hand's push, fraction of max_force

Outcome press_and_release(const sim::DeviceProfile& profile, double times_bound, bool passivity,
                          Element element = Element::wall) {
    EngineConfig config = sim::engine_config_for(profile);
    config.passivity_control = passivity;
    const double k = times_bound * naive_bound(config);
    config.wall_stiffness = static_cast<float>(k);

    ClosedLoop loop(config);
    if (element == Element::wall) {
        EffectParams wall;
        wall.type = EffectType::axis_wall;
        wall.axis_count = 1;
        wall.axes[0] = Axis::x;
        wall.wall.hardness = 10000;
        wall.wall.sense = WallSense::positive;
        loop.play(wall);
    } else {
        // The barrier's negative face at 0; thickness 10000 puts the pop 5000 units in,
        // far beyond anything the press reaches, so its face is a wall here.
        EffectParams barrier;
        barrier.type = EffectType::axis_barrier;
        barrier.axis_count = 1;
        barrier.axes[0] = Axis::x;
        barrier.barrier.pos_hardness = 10000;
        barrier.barrier.neg_hardness = 10000;
        barrier.barrier.thickness = 10000;
        barrier.barrier.offset = 5000;
        loop.play(barrier);
    }
    loop.play(constant_push(Axis::x, kPush));

    const sim::AxisModel& axis = profile.axes[0];
    const double hand_depth = kHandFraction * axis.max_force / profile.firm.stiffness / axis.half_travel * 10000;
    sim::SimDevice held(profile, sim::Grip::firm, sim::TargetMotion::hold_at({hand_depth}));
    held.set_position(0, -500);  // the hand brings the handle in from the free side
    for (int n = 0; n < 500; ++n) loop.tick(held);

    sim::SimDevice free = let_go(held);
    std::vector<double> x;
    for (int n = 0; n < 5000; ++n) {
        loop.tick(free);
        x.push_back(free.position(0));
    }
    Outcome o;
    o.first = peak_to_peak(x, 0, 1000);
    o.before = peak_to_peak(x, 3000, 4000);
    o.last = peak_to_peak(x, 4000, 5000);
    o.static_depth = kPush / k;
    o.settle_band = 2 * sensor_count(profile);
    o.decay = std::exp(-axis.viscous / (2 * axis.mass) * 1.0);
    return o;
}

void expect_settled(const Outcome& o, const std::string& what) {
    EXPECT_LE(o.last, o.settle_band) << what << ": still moving " << o.last << " units peak to peak";
}

void expect_ringing(const Outcome& o, const std::string& what) {
    EXPECT_GE(o.last, o.static_depth) << what << ": swings " << o.last << ", less than the static depth "
                                      << o.static_depth;
    EXPECT_GE(o.last, o.before * o.decay) << what << ": decays like a passive contact (" << o.before << " -> "
                                          << o.last << ")";
}

TEST(WallStiffness, HardnessTenThousandIsFiveTimesEachProfilesNaiveBound) {
    // K = 2b/T in physical units (b the mechanism's damping, T = 1 ms), normalized by
    // half_travel/max_force: the hardness-to-stiffness map of docs/stability.md.
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        const sim::AxisModel& a = p.axes[0];
        const double bound_physical = 2 * a.viscous / kTickS;  // N/m or N·m/rad
        const double bound_normalized = bound_physical * a.half_travel / a.max_force;
        EXPECT_NEAR(sim::engine_config_for(p).wall_stiffness, 5 * bound_normalized, 1e-4 * bound_normalized) << p.name;
    }
}

class PassivityComparison : public ::testing::TestWithParam<const char*> {
protected:
    const sim::DeviceProfile& profile() const { return *sim::find_device_profile(GetParam()); }
};

TEST_P(PassivityComparison, NaiveWallJustBelowTheBoundSettles) {
    expect_settled(press_and_release(profile(), 0.9, false), "naive wall at 0.9x the bound");
}

TEST_P(PassivityComparison, NaiveWallWellAboveTheBoundRingsInALimitCycle) {
    expect_ringing(press_and_release(profile(), 20, false), "naive wall at 20x the bound");
}

TEST_P(PassivityComparison, ControlledWallsThreeAndFiveTimesTheBoundSettle) {
    // 5x is hardness 10000 on every built-in profile (sim::engine_config_for).
    expect_settled(press_and_release(profile(), 3, true), "controlled wall at 3x the bound");
    expect_settled(press_and_release(profile(), 5, true), "controlled wall at 5x the bound");
}

TEST(PassivityComparisonJoystick, TheWallThatRingsNaivelySettlesUnderControl) {
    // The controller removes all the energy the sensor can prove the wall made; what a
    // count's uncertainty hides (up to ½·K·q² a tick at about a count per tick) is left
    // to the mechanism's Coulomb friction. On the joystick (fine sensor, 0.15 N of
    // friction) that reaches past 20x its bound; the wheel and the 3-axis device run into
    // it sooner and keep a small cycle of a few counts at 10-20x (docs/stability.md).
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    expect_ringing(press_and_release(joystick, 20, false), "naive wall at 20x the bound");
    expect_settled(press_and_release(joystick, 20, true), "controlled wall at 20x the bound");
}

TEST_P(PassivityComparison, BarriersToo) {
    expect_ringing(press_and_release(profile(), 20, false, Element::barrier), "naive barrier at 20x the bound");
    expect_settled(press_and_release(profile(), 3, true, Element::barrier), "controlled barrier at 3x the bound");
    expect_settled(press_and_release(profile(), 5, true, Element::barrier), "controlled barrier at 5x the bound");
}

// The swing of the fourth second after a small nudge, over that of the first: a free
// handle at rest on a wall 30% deeper than the push holds it, released.
double swing_ratio(const sim::DeviceProfile& profile, double times_bound) {
    EngineConfig config = sim::engine_config_for(profile);
    config.passivity_control = false;
    const double k = times_bound * naive_bound(config);
    config.wall_stiffness = static_cast<float>(k);
    ClosedLoop loop(config);
    EffectParams wall;
    wall.type = EffectType::axis_wall;
    wall.axis_count = 1;
    wall.axes[0] = Axis::x;
    wall.wall.hardness = 10000;
    loop.play(wall);
    loop.play(constant_push(Axis::x, kPush));
    sim::SimDevice handle(profile, sim::Grip::none, sim::TargetMotion::hold_at({0.0}));
    handle.set_position(0, 1.3 * kPush / k);
    std::vector<double> x;
    for (int n = 0; n < 4000; ++n) {
        loop.tick(handle);
        x.push_back(handle.position(0));
    }
    return peak_to_peak(x, 3000, 4000) / peak_to_peak(x, 0, 1000);
}

TEST_P(PassivityComparison, WithoutFrictionTheBoundIsWhereTheTheoryPutsIt) {
    // Take away the mechanism's Coulomb friction and the contact is the linear system of
    // Colgate & Schenkel: the sampled spring feeds K·T/2 of negative damping into the
    // swing against the mechanism's b, so below 2b/T the swing decays and above it grows.
    // Near the bound the rates are tiny (a time constant of 30 s at 1.1x on the wheel),
    // so the test stays at 0.8x and 1.5x. The nudge is small enough that the handle
    // never leaves the wall in the first second: the contact stays linear.
    sim::DeviceProfile frictionless = profile();
    for (int a = 0; a < frictionless.axis_count; ++a) frictionless.axes[a].coulomb = 0;
    EXPECT_LT(swing_ratio(frictionless, 0.8), 1.0) << "0.8x the bound must decay";
    EXPECT_GT(swing_ratio(frictionless, 1.5), 1.0) << "1.5x the bound must grow";
}

INSTANTIATE_TEST_SUITE_P(Profiles, PassivityComparison, ::testing::Values("joystick", "wheel", "3axis"),
                         profile_name);

// The comparison for the README: swing over the last second (normalized units, peak to
// peak) of the naive and the controlled wall at multiples of each profile's bound. The
// assertions are the ones above; this prints the table.
TEST(PassivityComparisonTable, Print) {
    std::printf("\n%-9s %7s %9s %11s %11s %9s\n", "profile", "K/bound", "K (norm)", "naive p-p", "PO/PC p-p",
                "2 counts");
    for (const char* name : {"joystick", "wheel", "3axis"}) {
        const sim::DeviceProfile& p = *sim::find_device_profile(name);
        const double bound = naive_bound(sim::engine_config_for(p));
        for (const double times : {0.9, 2.0, 3.0, 5.0, 10.0, 20.0}) {
            const Outcome naive = press_and_release(p, times, false);
            const Outcome controlled = press_and_release(p, times, true);
            std::printf("%-9s %7.1f %9.2f %11.2f %11.2f %9.2f\n", name, times, times * bound, naive.last,
                        controlled.last, naive.settle_band);
            if (times >= 3 && times <= 5) expect_settled(controlled, std::string(name) + " controlled");
        }
    }
}

}  // namespace
}  // namespace feel::test::loop
