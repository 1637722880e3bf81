// Start delay, duration and iterations (§6.3, §6.6.i).
#include <cmath>
#include <cstdint>

#include "effect_clock.hpp"
#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using EffectClock = EngineFixture;

// The tick length the conditions and dynamics read, in float (issue 14): µs / 10⁶ must be
// the float nearest the true quotient for every tick the contexts see, which is the float
// the engine's double (float)(µs · 1e-6) gave before, so no force moved by a bit. Checked
// against both: the quotient in double (exact to 2^-53, far inside a float's half ulp) and
// the former expression, for every length from 0 to 2^24 µs (16.7 s), and in its last bit
// beyond.
TEST(TickLength, FloatSecondsAreTheNearestFloatToTheMicrosecondsOverAMillion) {
    int64_t off_nearest = 0, off_former = 0;
    for (int64_t us = 0; us <= (int64_t{1} << 24); ++us) {
        const float s = detail::tick_seconds_of(us);
        const double exact = static_cast<double>(us) / 1e6;
        const float below = std::nextafter(s, 0.0f), above = std::nextafter(s, 1e30f);
        // Nearest: neither neighbour is closer to the quotient.
        if (std::fabs(below - exact) < std::fabs(s - exact) || std::fabs(above - exact) < std::fabs(s - exact))
            ++off_nearest;
        if (s != static_cast<float>(static_cast<double>(us) * 1e-6)) ++off_former;
    }
    EXPECT_EQ(off_nearest, 0);
    EXPECT_EQ(off_former, 0);
    for (const int64_t us : {int64_t{1} << 25, int64_t{3'600'000'000}, int64_t{86'400'000'000}}) {
        const double exact = static_cast<double>(us) / 1e6;
        EXPECT_NEAR(detail::tick_seconds_of(us), exact, exact * 0x1p-23) << us << " µs";
    }
}

TEST_F(EffectClock, StartDelayHoldsTheWaveBackAndItStartsFromItsBeginning) {
    EffectParams p = periodic_on_x(EffectType::sine, 5000, 0, 20'000, 0, 60'000);
    p.start_delay_us = 40'000;
    const EffectId id = play(p);
    expect_forces(40'000, 1000, [](int64_t, int) { return 0.0; });
    EXPECT_EQ(engine_->state(id), EffectState::delayed);
    expect_forces(60'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? 5000 * std::sin(2 * kPi * static_cast<double>(t) / 20'000) : 0.0;
    }, 0.05);
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->state(id), EffectState::stopped);
}

TEST_F(EffectClock, IterationsReplayTheWholeWaveIncludingItsEnvelope) {
    EffectParams p = constant_on_x(1000, 100'000);
    p.iterations = 3;
    p.start_delay_us = 10'000;
    p.has_envelope = true;
    p.envelope = {5000, 20'000, 0, 0};
    const EffectId id = play(p);
    expect_forces(10'000, 1000, [](int64_t, int) { return 0.0; });
    expect_forces(300'000, 1000, [](int64_t t, int axis) {
        if (axis != 0) return 0.0;
        const double tau = static_cast<double>(t % 100'000);  // each play restarts τ
        return tau < 20'000 ? 5000 + (1000 - 5000) * tau / 20'000 : 1000.0;
    });
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->state(id), EffectState::stopped);
}

TEST_F(EffectClock, InfiniteIterationsNeverFinish) {
    EffectParams p = constant_on_x(1000, 1'000);
    p.iterations = kInfiniteIterations;
    play(p);
    expect_forces(5'000'000, 10'000, [](int64_t, int axis) { return axis == 0 ? 1000.0 : 0.0; });
}

TEST_F(EffectClock, RestartBeginsAgainFromTheStart) {
    EffectParams p = constant_on_x(0, 100'000);
    p.type = EffectType::ramp;
    p.ramp = {0, 10000};
    const EffectId id = play(p);
    tick(50'000);
    EXPECT_NEAR(tick().force[0], 5000, kForceTolerance);
    ASSERT_TRUE(engine_->start(id).ok());
    EXPECT_NEAR(tick().force[0], 0, kForceTolerance);
}

TEST_F(EffectClock, StopSilencesAtOnce) {
    const EffectId id = play(constant_on_x(3000, kInfiniteUs));
    EXPECT_EQ(tick().force[0], 3000.0f);
    ASSERT_TRUE(engine_->stop(id).ok());
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->state(id), EffectState::stopped);
}

TEST_F(EffectClock, EffectTimeCountsFromTheFirstTickAfterStart) {
    tick(123'456);  // the engine has been running a while
    EffectParams p = constant_on_x(0, 1'000'000);
    p.type = EffectType::ramp;
    p.ramp = {0, 10000};
    play(p);
    EXPECT_NEAR(tick(100'000).force[0], 0, kForceTolerance);
    EXPECT_NEAR(tick().force[0], 1000, kForceTolerance);
}

}  // namespace
}  // namespace feel::test
