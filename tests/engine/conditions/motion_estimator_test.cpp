// The velocity and acceleration estimator (FOAW, motion_estimator.hpp) on quantized motion
// whose true velocity and acceleration are known in closed form.
#include <algorithm>
#include <iterator>
#include <new>
#include <random>

#include "condition_fixture.hpp"
#include "motion_estimator.hpp"

namespace feel::test {
namespace {

using detail::MotionEstimator;

struct RampRun {
    double worst_error = 0;      // largest |v_est - v| / |v| once the window has filled
    int ticks = 0;               // ticks checked
    int zero_differences = 0;    // ticks where the backward difference reads 0
};

// A ramp from x0 at speed v, quantized to the joystick's sensor step, sampled every dt_us
// for duration_us; checks from settle_us on.
RampRun run_ramp(double v, double x0, int64_t dt_us, int64_t duration_us, int64_t settle_us = 110'000) {
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    RampRun r;
    float previous = 0;
    for (int64_t t = 0; t <= duration_us; t += dt_us) {
        float p[kMaxAxes] = {};
        p[0] = static_cast<float>(quantize(x0 + v * static_cast<double>(t) * 1e-6, kJoystickStep));
        m.update(t, p, 1);
        if (t >= settle_us) {
            r.worst_error = std::max(r.worst_error, std::fabs(m.velocity(0) - v) / std::fabs(v));
            ++r.ticks;
            if (p[0] == previous) ++r.zero_differences;
        }
        previous = p[0];
    }
    return r;
}

// The constructor starts every member from one zero fill (issue 14's flash): an estimator
// made where other bytes were reads no estimate yet (velocity 0, window 0: the header's
// "0: no estimate yet"), unconfigured and configured, and then estimates a motion exactly as
// one made in zeroed memory does.
TEST(MotionEstimator, AFreshEstimatorDoesNotDependOnTheBytesItWasMadeIn) {
    alignas(MotionEstimator) static unsigned char dirty[sizeof(MotionEstimator)];
    alignas(MotionEstimator) static unsigned char clean[sizeof(MotionEstimator)];
    std::fill(std::begin(dirty), std::end(dirty), static_cast<unsigned char>(0xA5));
    std::fill(std::begin(clean), std::end(clean), static_cast<unsigned char>(0));
    auto* a = new (dirty) MotionEstimator;
    auto* b = new (clean) MotionEstimator;
    for (int axis = 0; axis < kMaxAxes; ++axis) {
        EXPECT_EQ(a->velocity(axis), 0.0f);
        EXPECT_EQ(a->velocity_window(axis), 0);
        EXPECT_EQ(a->acceleration(axis), 0.0f);
        EXPECT_EQ(a->acceleration_window(axis), 0);
    }
    a->configure(static_cast<float>(kJoystickStep));
    b->configure(static_cast<float>(kJoystickStep));
    for (int64_t t = 0; t <= 300'000; t += 1000) {
        float p[kMaxAxes] = {};
        const double s = static_cast<double>(t) * 1e-6;
        p[0] = static_cast<float>(quantize(-2000.0 + 0.05 * kVelocityRef * s + 20000.0 * s * s, kJoystickStep));
        a->update(t, p, 1);
        b->update(t, p, 1);
        ASSERT_EQ(a->velocity(0), b->velocity(0)) << "t " << t;
        ASSERT_EQ(a->acceleration(0), b->acceleration(0)) << "t " << t;
        ASSERT_EQ(a->velocity_window(0), b->velocity_window(0)) << "t " << t;
    }
    EXPECT_GT(a->velocity(0), 0.0f);  // it did estimate the motion
}

TEST(MotionEstimator, QuantizedRampsAtTwoPercentAndFullReferenceSpeedAreWithinFivePercent) {
    // 2% of velocity_ref (2000 units/s, 10 mm/s at the joystick's grip, a slow careful
    // drag: 0.41 sensor count per 1 ms tick) and 100% (1e5 units/s, 0.5 m/s, the whole
    // travel in 0.2 s: 20 counts per tick), both directions, at ten sub-count phases of the
    // start. Every tick after the window has filled (100 ms) is within 5%.
    for (double sign : {1.0, -1.0}) {
        for (int phase = 0; phase < 10; ++phase) {
            const double x0 = -sign * 9500 + phase * kJoystickStep / 10;
            const RampRun slow = run_ramp(sign * 0.02 * kVelocityRef, x0, 1000, 2'000'000);
            const RampRun fast = run_ramp(sign * kVelocityRef, x0, 1000, 190'000);
            EXPECT_LT(slow.worst_error, 0.05) << "slow, sign " << sign << " phase " << phase;
            EXPECT_LT(fast.worst_error, 0.05) << "fast, sign " << sign << " phase " << phase;
            EXPECT_GT(slow.ticks, 1800);
            EXPECT_GT(fast.ticks, 70);
            // The raw difference of the same readings is 0 on most slow ticks.
            EXPECT_GT(slow.zero_differences, slow.ticks / 2);
        }
    }
}

// The fits use sums kept from tick to tick (issue 14). Integers cannot drift, and this
// checks it: after 400 000 ticks (6.7 minutes at 1 kHz) of a wandering 2-axis motion, the
// estimate on a final ramp is the one a fresh estimator computes from the same last 200
// samples, bit for bit, and within 0.5% of the ramp's true speed.
TEST(MotionEstimator, RunningSumsAfterALongRunGiveWhatAFreshEstimatorGives) {
    MotionEstimator long_run, fresh;
    long_run.configure(static_cast<float>(kJoystickStep));
    fresh.configure(static_cast<float>(kJoystickStep));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> jerk(-2e7, 2e7);
    double x = 0, y = 0, vx = 0, vy = 0;
    const int64_t wander = 400'000, ramp = 200;
    const double ramp_speed = 3000;  // units/s
    double ramp_start = 0;
    for (int64_t k = 0; k < wander + ramp; ++k) {
        const double dt = 1e-3;
        if (k < wander) {
            vx = std::clamp(vx + jerk(random) * dt * dt, -30000.0, 30000.0);
            vy = std::clamp(vy + jerk(random) * dt * dt, -30000.0, 30000.0);
            x = std::clamp(x + vx * dt, -9000.0, 9000.0);
            y = std::clamp(y + vy * dt, -9000.0, 9000.0);
            ramp_start = x;
        } else {
            x = ramp_start + ramp_speed * static_cast<double>(k - wander) * dt;
            y = 1234;
        }
        float p[kMaxAxes] = {static_cast<float>(quantize(x, kJoystickStep)), static_cast<float>(quantize(y, kJoystickStep))};
        long_run.update(k * 1000, p, 2);
        if (k >= wander) fresh.update(k * 1000, p, 2);
    }
    EXPECT_EQ(long_run.velocity(0), fresh.velocity(0));
    EXPECT_EQ(long_run.velocity(1), 0.0f);
    EXPECT_EQ(long_run.acceleration(0), fresh.acceleration(0));
    EXPECT_NEAR(long_run.velocity(0), ramp_speed, 0.005 * ramp_speed);
}

// The ring keeps each position as the float it was given (issue 14's RAM: no fixed-point
// copy beside it); the running sums work a sample's fixed-point value out when they read
// it. A position the fixed point cannot hold (beyond its range: ±16384 units on a sensor of
// 1/256 unit a count, whose unit is the finest, 2^-16) is fitted from the floats instead, as
// accurately: quantized ramps at 2% and 100% of velocity_ref that start inside the range
// and beyond it, both directions, read their speed within 0.001% once the window has
// filled (the least-squares slope's bound, q/W = 0.04 units/s over 100 ms, is 0.002% of
// the slower one).
TEST(MotionEstimator, PositionsBeyondTheFixedPointRangeAreFittedAsAccurately) {
    constexpr double kStep = 1.0 / 256;
    for (double v : {0.02 * kVelocityRef, kVelocityRef, -0.02 * kVelocityRef, -kVelocityRef}) {
        for (double x0 : {100.0, 16384.0 + 100, -16384.0 - 100, 4194304.0}) {
            MotionEstimator m;
            m.configure(static_cast<float>(kStep));
            double worst = 0;
            for (int k = 0; k <= 190; ++k) {
                float p[kMaxAxes] = {static_cast<float>(quantize(x0 + v * k * 1e-3, kStep))};
                m.update(k * 1000, p, 1);
                if (k >= 110) worst = std::max(worst, std::fabs(m.velocity(0) - v) / std::fabs(v));
            }
            EXPECT_LT(worst, 1e-5) << "speed " << v << ", from " << x0;
        }
    }
}

TEST(MotionEstimator, SpeedsBetweenAreWithinFivePercentToo) {
    for (double fraction : {0.01, 0.05, 0.2, 0.5}) {
        const double v = fraction * kVelocityRef;
        const RampRun r = run_ramp(v, -9500, 1000, static_cast<int64_t>(18000 / v * 1e6));
        EXPECT_LT(r.worst_error, 0.05) << fraction;
    }
}

TEST(MotionEstimator, AtTenKilohertzTheWindowStillSpansItsTime) {
    // Faster loops keep every few ticks so the history still covers 100 ms.
    EXPECT_LT(run_ramp(0.02 * kVelocityRef, -9500, 100, 1'000'000).worst_error, 0.05);
    EXPECT_LT(run_ramp(kVelocityRef, -9500, 100, 190'000).worst_error, 0.05);
}

TEST(MotionEstimator, AHandleAtRestReadsExactlyZero) {
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    float p[kMaxAxes] = {static_cast<float>(quantize(1234, kJoystickStep)), static_cast<float>(quantize(-50, kJoystickStep))};
    for (int k = 0; k < 300; ++k) {
        m.update(k * 1000, p, 2);
        ASSERT_EQ(m.velocity(0), 0.0f);
        ASSERT_EQ(m.velocity(1), 0.0f);
        ASSERT_EQ(m.acceleration(0), 0.0f);
    }
}

TEST(MotionEstimator, DitherBetweenTwoCountsIsNotMotion) {
    // A handle resting on a count boundary reads n or n+1 at random: one count of noise.
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    std::mt19937 random(7);
    for (int k = 0; k < 3000; ++k) {
        float p[kMaxAxes] = {static_cast<float>(kJoystickStep * (300 + static_cast<int>(random() & 1)))};
        m.update(k * 1000, p, 1);
        if (k > 110) {
            ASSERT_LT(std::fabs(m.velocity(0)), 0.002 * kVelocityRef) << k;
        }
    }
}

TEST(MotionEstimator, AStopReadsZeroOnceTheWindowHasPassedIt) {
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    int64_t t = 0;
    for (; t < 300'000; t += 1000) {
        float p[kMaxAxes] = {static_cast<float>(quantize(-4000 + 30000 * static_cast<double>(t) * 1e-6, kJoystickStep))};
        m.update(t, p, 1);
    }
    EXPECT_NEAR(m.velocity(0), 30000, 300);
    float held[kMaxAxes] = {static_cast<float>(quantize(-4000 + 30000 * 0.3, kJoystickStep))};
    for (int64_t stop = t; t < stop + 120'000; t += 1000) m.update(t, held, 1);
    EXPECT_EQ(m.velocity(0), 0.0f);
    EXPECT_EQ(m.acceleration(0), 0.0f);
}

TEST(MotionEstimator, ASineIsFollowedWithinSevenPercentOfItsPeakSpeed) {
    // The fitted slope is the speed at the window's middle: where the sine bends most the
    // window is short, so the lag stays a small fraction of the peak speed.
    for (double hz : {0.5, 2.0, 5.0}) {
        MotionEstimator m;
        m.configure(static_cast<float>(kJoystickStep));
        const double amplitude = 5000, w = 2 * kPi * hz;
        double worst = 0;
        for (int k = 0; k < 3000; ++k) {
            const double t = k * 1e-3;
            float p[kMaxAxes] = {static_cast<float>(quantize(amplitude * std::sin(w * t), kJoystickStep))};
            m.update(k * 1000, p, 1);
            if (k >= 150) worst = std::max(worst, std::fabs(m.velocity(0) - amplitude * w * std::cos(w * t)));
        }
        EXPECT_LT(worst, 0.07 * amplitude * w) << hz << " Hz";
    }
}

TEST(MotionEstimator, ASuddenStopNeverReadsTheWrongSign) {
    // A handle stopped dead from several speeds: the estimate falls to 0 without ever
    // reading a speed backwards (which would make a damper push the wrong way).
    for (double speed : {2000.0, 7000.0, 20000.0, 60000.0}) {
        for (bool quantized : {false, true}) {
            MotionEstimator m;
            m.configure(static_cast<float>(kJoystickStep));
            for (int k = 0; k < 400; ++k) {
                double x = -3000 + speed * 1e-3 * std::min(k, 200);
                if (quantized) x = quantize(x, kJoystickStep);
                float p[kMaxAxes] = {static_cast<float>(x)};
                m.update(k * 1000, p, 1);
                if (k > 200) {
                    ASSERT_GE(m.velocity(0), 0.0f) << speed << " " << k;
                    ASSERT_LE(m.velocity(0), speed * 1.01) << speed << " " << k;
                }
                if (k > 310) {
                    ASSERT_EQ(m.velocity(0), 0.0f) << speed << " " << k;
                }
            }
        }
    }
}

TEST(MotionEstimator, AConstantAccelerationIsWithinFivePercent) {
    for (double a : {2e5, 1e6, 4e6}) {  // 10%, 50% and 200% of the joystick's acceleration_ref
        MotionEstimator m;
        m.configure(static_cast<float>(kJoystickStep));
        double worst = 0;
        for (int k = 0; k < 1000; ++k) {
            const double t = k * 1e-3;
            const double x = -9500 + 0.5 * a * t * t;
            if (x > 9500) break;
            float p[kMaxAxes] = {static_cast<float>(quantize(x, kJoystickStep))};
            m.update(k * 1000, p, 1);
            if (k >= 110) {
                worst = std::max(worst, std::fabs(m.acceleration(0) - a) / a);
                // The speed is the fitted line's, half its window late; the window a
                // parabola leaves within a count of its chord is sqrt(8q/a) (x1.5: the
                // ladder of window lengths).
                const double lag_s = 1.5 * std::sqrt(8 * kJoystickStep / a) / 2;
                ASSERT_NEAR(m.velocity(0), a * t, a * lag_s) << k;
                ASSERT_LE(m.velocity(0), a * t + 1.0) << k;  // late, never early
            }
        }
        EXPECT_LT(worst, 0.05) << a;
    }
}

TEST(MotionEstimator, UnevenTicksAreFittedWithTheirOwnTimes) {
    // A render at 3000 Hz ticks at 333 or 334 µs: an exact ramp still reads its slope.
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    for (int n = 0; n < 600; ++n) {
        const int64_t t = (n * 1'000'000 + 1500) / 3000;
        float p[kMaxAxes] = {static_cast<float>(-2000 + 12000 * static_cast<double>(t) * 1e-6)};
        m.update(t, p, 1);
        if (n > 0) {
            ASSERT_NEAR(m.velocity(0), 12000, 2) << n;
        }
    }
}

// An estimator of the joystick's sensor fed position 0 at t = 0 and 10 at t = 1 ms.
MotionEstimator after_ten_units_in_a_millisecond() {
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    float p[kMaxAxes] = {0};
    m.update(0, p, 1);
    p[0] = 10;
    m.update(1000, p, 1);
    return m;
}

TEST(MotionEstimator, RepeatedAndBackwardTimes) {
    MotionEstimator m = after_ten_units_in_a_millisecond();
    float p[kMaxAxes] = {10};
    EXPECT_NEAR(m.velocity(0), 10000, 1e-2);
    p[0] = 20;
    m.update(1000, p, 1);  // the same instant again: the fresher reading replaces it
    EXPECT_NEAR(m.velocity(0), 20000, 1e-2);
    EXPECT_EQ(m.velocity_window(0), 1);
    m.update(500, p, 1);  // time went backwards: the history starts over
    EXPECT_EQ(m.velocity(0), 0.0f);
    EXPECT_EQ(m.velocity_window(0), 0);
}

// The ring keeps 32-bit times (issue 14: RAM). The fits see only times between samples, so
// the same motion at times shifted across 2^32 µs reads the same, bit for bit.
TEST(MotionEstimator, TimesAcrossTheThirtyTwoBitBoundaryReadTheSame) {
    MotionEstimator near_zero;
    MotionEstimator shifted;
    near_zero.configure(static_cast<float>(kJoystickStep));
    shifted.configure(static_cast<float>(kJoystickStep));
    constexpr int64_t kShift = (int64_t{1} << 32) - 60'000;  // the boundary 60 ms in
    for (int64_t t = 0; t <= 200'000; t += 1000) {
        float p[kMaxAxes] = {};
        p[0] = static_cast<float>(quantize(3000.0 * std::sin(static_cast<double>(t) * 2e-5), kJoystickStep));
        near_zero.update(t, p, 1);
        shifted.update(t + kShift, p, 1);
        ASSERT_EQ(near_zero.velocity(0), shifted.velocity(0)) << t;
        ASSERT_EQ(near_zero.acceleration(0), shifted.acceleration(0)) << t;
    }
}

// A tick 2^31 µs (36 minutes) or more after the previous one restarts the history, as time
// going backwards does; one a microsecond sooner is fitted across the gap.
TEST(MotionEstimator, AGapOfHalfAnHourRestartsTheHistory) {
    constexpr auto kMaxGap = static_cast<int64_t>(MotionEstimator::kMaxGapUs);
    for (const int64_t gap : {kMaxGap - 1, kMaxGap}) {
        MotionEstimator m = after_ten_units_in_a_millisecond();
        float p[kMaxAxes] = {20};
        m.update(1000 + gap, p, 1);
        if (gap < kMaxGap) {
            EXPECT_NEAR(m.velocity(0), 10.0 / (static_cast<double>(gap) * 1e-6), 1e-6) << gap;
        } else {
            EXPECT_EQ(m.velocity(0), 0.0f);
            EXPECT_EQ(m.velocity_window(0), 0);
        }
    }
}

TEST(MotionEstimator, TheWindowIsLongWhenSlowAndShortWhenTheMotionBends) {
    MotionEstimator m;
    m.configure(static_cast<float>(kJoystickStep));
    for (int k = 0; k < 200; ++k) {
        float p[kMaxAxes] = {static_cast<float>(quantize(-5000 + 2.0 * k, kJoystickStep))};
        m.update(k * 1000, p, 1);
    }
    EXPECT_EQ(m.velocity_window(0), 100);  // 100 ms at 1 kHz: the longest
    // A sharp turn: within a few ticks the window has shrunk to the new straight stretch.
    const double turn = -5000 + 2.0 * 199;
    for (int k = 1; k <= 10; ++k) {
        float p[kMaxAxes] = {static_cast<float>(quantize(turn - 40.0 * k, kJoystickStep))};
        m.update((199 + k) * 1000, p, 1);
    }
    EXPECT_LE(m.velocity_window(0), 12);
    EXPECT_NEAR(m.velocity(0), -40000, 0.05 * 40000);
}

}  // namespace
}  // namespace feel::test
