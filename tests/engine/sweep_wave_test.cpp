// Angle Sweep waves (§4.2.c, §6.6.i): the direction moves linearly from the start angle to
// the end angle over the duration, clockwise or counter-clockwise.
#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using SweepWave = EngineFixture;

// A sweep whose source stays at +magnitude for the whole play (a square whose first half
// cycle outlasts the duration), so the force is the magnitude along the swept direction.
EffectParams steady_sweep(int32_t start, int32_t end, SweepSense sense, int64_t duration_us) {
    EffectParams p = periodic_on_x(EffectType::sweep_square, 6000, 0, 4 * duration_us, 0, duration_us);
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.periodic.sweep_start_angle = start;
    p.periodic.sweep_end_angle = end;
    p.periodic.sweep_sense = sense;
    return p;
}

double from_compass_x(double deg, double m) { return -m * std::sin(deg * kPi / 180); }
double from_compass_y(double deg, double m) { return -m * std::cos(deg * kPi / 180); }

TEST_F(SweepWave, ClockwiseSweepsThroughIncreasingCompassAngles) {
    play(steady_sweep(0, 9000, SweepSense::clockwise, 1'000'000));
    expect_forces(1'000'000, 1000, [](int64_t t, int axis) {
        const double deg = 90.0 * static_cast<double>(t) / 1e6;
        return axis == 0 ? from_compass_x(deg, 6000) : from_compass_y(deg, 6000);
    });
}

TEST_F(SweepWave, CounterClockwiseGoesTheOtherWayRound) {
    // From 0 to 270 counter-clockwise is a quarter turn through 315.
    play(steady_sweep(0, 27000, SweepSense::counterclockwise, 1'000'000));
    expect_forces(1'000'000, 1000, [](int64_t t, int axis) {
        const double deg = -90.0 * static_cast<double>(t) / 1e6;
        return axis == 0 ? from_compass_x(deg, 6000) : from_compass_y(deg, 6000);
    });
}

TEST_F(SweepWave, ClockwiseAcrossNorthWraps) {
    // 350° → 10° clockwise is a 20° sweep through north, not 340° the long way.
    play(steady_sweep(35000, 1000, SweepSense::clockwise, 200'000));
    tick(100'000);
    const TickOutput mid = tick();
    EXPECT_NEAR(mid.force[0], from_compass_x(0, 6000), kForceTolerance);
    EXPECT_NEAR(mid.force[1], from_compass_y(0, 6000), kForceTolerance);
}

TEST_F(SweepWave, SweepStartsAfterTheStartDelay) {
    EffectParams p = steady_sweep(9000, 18000, SweepSense::clockwise, 100'000);
    p.start_delay_us = 50'000;
    play(p);
    expect_forces(50'000, 1000, [](int64_t, int) { return 0.0; });
    expect_forces(100'000, 1000, [](int64_t t, int axis) {
        const double deg = 90.0 + 90.0 * static_cast<double>(t) / 1e5;
        return axis == 0 ? from_compass_x(deg, 6000) : from_compass_y(deg, 6000);
    });
}

TEST_F(SweepWave, SweptSineCombinesSourceAndAngle) {
    EffectParams p = steady_sweep(0, 18000, SweepSense::clockwise, 500'000);
    p.type = EffectType::sweep_sine;
    p.periodic.period_us = 20'000;
    play(p);
    expect_forces(500'000, 500, [](int64_t t, int axis) {
        const double td = static_cast<double>(t);
        const double deg = 180.0 * td / 5e5;
        const double value = 6000 * std::sin(2 * kPi * td / 20'000);
        return axis == 0 ? from_compass_x(deg, value) : from_compass_y(deg, value);
    }, 0.05);
}

}  // namespace
}  // namespace feel::test
