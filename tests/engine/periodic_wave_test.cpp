// The five periodic sources against independent formulas of their definitions (§4.2,
// §6.6.b): magnitude, offset, period and phase.
#include <algorithm>

#include "engine_fixture.hpp"

namespace feel::test {
namespace {

// Independent definitions, written from the shapes rather than from the engine's code:
// the triangle as the arcsine of a sine, the square as the sign of a sine, the saws from
// the fractional part of time.
double sine_of(double p) { return std::sin(2 * kPi * p); }
double square_of(double p) { return std::sin(2 * kPi * p) >= 0 ? 1.0 : -1.0; }
double triangle_of(double p) { return (2.0 / kPi) * std::asin(std::sin(2 * kPi * p)); }
double saw_up_of(double p) { return 2.0 * (p - std::floor(p)) - 1.0; }
double saw_down_of(double p) { return -saw_up_of(p); }

struct PeriodicCase {
    EffectType type;
    double (*shape)(double);
    const char* name;
};

class PeriodicWave : public EngineFixture, public ::testing::WithParamInterface<PeriodicCase> {};

TEST_P(PeriodicWave, MatchesItsFormulaWithMagnitudeOffsetAndPhase) {
    const PeriodicCase c = GetParam();
    const int32_t magnitudes[] = {10000, 3500};
    const int32_t offsets[] = {0, -2000};
    const int32_t phases[] = {0, 9000, 27350};
    for (int32_t m : magnitudes) {
        for (int32_t off : offsets) {
            for (int32_t ph : phases) {
                reset(2);
                const int64_t period = 20'000;  // 50 Hz
                play(periodic_on_x(c.type, m, off, period, ph, 100'000));
                // Sample away from the square's and saws' jumps, where float rounding of
                // the time could pick either side.
                expect_forces(100'000, 250, [&](int64_t t, int axis) {
                    if (axis != 0) return 0.0;
                    const double p = static_cast<double>(t) / period + ph / 36000.0;
                    const double frac = p - std::floor(p);
                    const bool near_jump = std::fabs(frac) < 1e-6 || std::fabs(frac - 0.5) < 1e-6 || frac > 1 - 1e-6;
                    if (near_jump && c.type != EffectType::sine && c.type != EffectType::triangle) {
                        // At a discontinuity the definition picks the new side; skip.
                        return static_cast<double>(NAN);
                    }
                    // The device clamps the sum to its maximum, ±10000.
                    return std::clamp(off + m * c.shape(p), -10000.0, 10000.0);
                }, 0.05);
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllSources, PeriodicWave,
                         ::testing::Values(PeriodicCase{EffectType::sine, sine_of, "sine"},
                                           PeriodicCase{EffectType::square, square_of, "square"},
                                           PeriodicCase{EffectType::triangle, triangle_of, "triangle"},
                                           PeriodicCase{EffectType::saw_up, saw_up_of, "saw_up"},
                                           PeriodicCase{EffectType::saw_down, saw_down_of, "saw_down"}),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

using PeriodicShape = EngineFixture;

TEST_F(PeriodicShape, SineAndTriangleStartAtZeroRising) {
    // §4.2: "Sine and Triangle are such that forces always start at zero and follow a
    // mathematical profile to a peak".
    for (EffectType t : {EffectType::sine, EffectType::triangle}) {
        reset(2);
        play(periodic_on_x(t, 8000, 0, 40'000, 0, 40'000));
        EXPECT_NEAR(tick(10'000).force[0], 0.0, kForceTolerance);     // t = 0
        EXPECT_NEAR(tick(10'000).force[0], 8000.0, kForceTolerance);  // t = T/4: the peak
        EXPECT_NEAR(tick(10'000).force[0], 0.0, kForceTolerance);     // t = T/2
        EXPECT_NEAR(tick(10'000).force[0], -8000.0, kForceTolerance); // t = 3T/4
    }
}

TEST_F(PeriodicShape, PhaseOf90DegreesStartsAQuarterCycleIn) {
    play(periodic_on_x(EffectType::sine, 5000, 0, 10'000, 9000, kInfiniteUs));
    EXPECT_NEAR(tick().force[0], 5000.0, kForceTolerance);
}

TEST_F(PeriodicShape, SquareFrequencyIsOneOverPeriod) {
    // The §1.2.c machine gun: 10 Hz square at 70%. Count sign changes over one second.
    play(periodic_on_x(EffectType::square, 7000, 0, 100'000, 0, 1'000'000));
    int rising = 0;
    float last = 0;
    for (int i = 0; i < 1000; ++i) {
        const float f = tick().force[0];
        if (last < 0 && f > 0) ++rising;
        last = f;
        EXPECT_EQ(std::fabs(f), 7000.0f);
    }
    EXPECT_EQ(rising, 9);  // 10 cycles, the first starts high
}

// The time into the cycle follows the wave time however the ticks come: at irregular lengths,
// with jumps of several periods, with the host's time going back, through a restart and a
// change of the period mid-play (on x86 the tick advances the last tick's remainder instead
// of dividing, and must divide again whenever that would not be τ mod period). Each tick
// against the saw's definition at that τ.
TEST_F(PeriodicShape, SawFollowsItsTimeThroughJitterJumpsTimeGoingBackARestartAndANewPeriod) {
    const int32_t magnitude = 6000;
    const int32_t phase = 4500;  // an eighth of a cycle
    EffectParams p = periodic_on_x(EffectType::saw_up, magnitude, 0, 7'000, phase, kInfiniteUs);
    const EffectId id = play(p);
    int64_t period = p.periodic.period_us;
    int64_t t_us = 0;
    int64_t tau = 0;  // the wave time of the next tick
    uint32_t seed = 12345;
    const auto next_random = [&seed](uint32_t below) {
        seed = seed * 1664525u + 1013904223u;
        return (seed >> 8) % below;
    };
    for (int i = 0; i < 2000; ++i) {
        TickInput in;
        in.t_us = t_us;
        TickOutput out;
        engine_->tick(in, out);
        const double cycles = static_cast<double>(tau) / static_cast<double>(period) + phase / 36000.0;
        const double frac = cycles - std::floor(cycles);
        if (frac > 1e-6 && frac < 1 - 1e-6) {  // away from the saw's drop
            ASSERT_NEAR(out.force[0], magnitude * (2.0 * frac - 1.0), 0.05) << "tick " << i << " tau " << tau;
        }
        int64_t dt = 300 + static_cast<int64_t>(next_random(1400));  // 0.3 to 1.7 ms
        if (i % 97 == 96) dt = 3 * period + 123;                      // a jump of more than a period
        if (i % 151 == 150 && tau > 2'000) dt = -1 - static_cast<int64_t>(next_random(2'000));  // the host's time goes back
        t_us += dt;
        tau += dt;
        if (i == 700) {  // a restart: the next tick is the wave's first again
            ASSERT_TRUE(engine_->start(id).ok());
            tau = 0;
        }
        if (i == 1300) {  // a new period mid-play, without a restart: the time runs on
            p.periodic.period_us = 5'300;
            ASSERT_TRUE(engine_->update(id, p, effect_field::kTypeSpecific, false).ok());
            period = p.periodic.period_us;
        }
    }
}

}  // namespace
}  // namespace feel::test
