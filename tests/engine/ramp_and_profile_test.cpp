// Ramp (§6.6.e) and custom force profiles (§4.3.a, §6.6.d).
#include <array>

#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using RampWave = EngineFixture;

TEST_F(RampWave, GoesLinearlyFromStartToEndOverTheDuration) {
    EffectParams p = constant_on_x(0, 500'000);
    p.type = EffectType::ramp;
    p.ramp = {-3000, 7000};
    play(p);
    expect_forces(500'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? -3000 + 10000.0 * static_cast<double>(t) / 500'000 : 0.0;
    });
    EXPECT_EQ(tick().force[0], 0.0f);
}

TEST_F(RampWave, EnvelopeShapesTheRampMagnitude) {
    EffectParams p = constant_on_x(0, 100'000);
    p.type = EffectType::ramp;
    p.ramp = {2000, 6000};
    p.has_envelope = true;
    p.envelope = {0, 0, 0, 50'000};  // fade to zero over the second half
    play(p);
    tick(75'000);
    // At 75 ms the ramp is at 5000 and the fade is half done.
    EXPECT_NEAR(tick().force[0], 2500, kForceTolerance);
}

using ForceProfile = EngineFixture;

EffectParams profile(int channels, int64_t sample_period_us, int32_t count, int64_t duration_us) {
    EffectParams p = constant_on_x(0, duration_us);
    p.type = EffectType::force_profile;
    p.custom = {channels, sample_period_us, count};
    return p;
}

TEST_F(ForceProfile, HoldsEachSampleForOnePeriodAndRepeats) {
    const std::array<int16_t, 4> samples = {1000, -2000, 3000, -10000};
    play(profile(1, 10'000, 4, 100'000), samples);
    expect_forces(100'000, 1000, [&](int64_t t, int axis) {
        if (axis != 0) return 0.0;
        return static_cast<double>(samples[static_cast<size_t>((t / 10'000) % 4)]);
    });
}

TEST_F(ForceProfile, TwoChannelsDriveTwoAxes) {
    // Interleaved frames: (x0, y0), (x1, y1), (x2, y2).
    const std::array<int16_t, 6> samples = {100, -100, 200, -200, 300, -300};
    EffectParams p = profile(2, 5'000, 6, 15'000);
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    play(p, samples);
    expect_forces(15'000, 500, [&](int64_t t, int axis) {
        const size_t frame = static_cast<size_t>(t / 5'000);
        return static_cast<double>(samples[frame * 2 + static_cast<size_t>(axis)]);
    });
}

TEST_F(ForceProfile, ChannelOrderFollowsTheAxesList) {
    const std::array<int16_t, 2> samples = {1234, -4321};
    EffectParams p = profile(2, 5'000, 2, 5'000);
    p.axis_count = 2;
    p.axes[0] = Axis::y;  // channel 0 drives y
    p.axes[1] = Axis::x;
    play(p, samples);
    const TickOutput out = tick();
    EXPECT_EQ(out.force[0], -4321.0f);
    EXPECT_EQ(out.force[1], 1234.0f);
}

TEST_F(ForceProfile, OneChannelPlaysAlongThePolarDirection) {
    const std::array<int16_t, 1> samples = {5000};
    EffectParams p = on_xy_polar(profile(1, 1'000, 1, 10'000), 27000);  // from the west
    play(p, samples);
    const TickOutput out = tick();
    EXPECT_NEAR(out.force[0], 5000, kForceTolerance);
    EXPECT_NEAR(out.force[1], 0, kForceTolerance);
}

TEST_F(ForceProfile, EnvelopeShapesEachSample) {
    const std::array<int16_t, 2> samples = {4000, -4000};
    EffectParams p = profile(1, 10'000, 2, 20'000);
    p.has_envelope = true;
    p.envelope = {0, 20'000, 0, 0};
    play(p, samples);
    tick(5'000);
    EXPECT_NEAR(tick(10'000).force[0], 4000 * 0.25, kForceTolerance);   // t = 5 ms
    EXPECT_NEAR(tick().force[0], -4000 * 0.75, kForceTolerance);        // t = 15 ms
}

}  // namespace
}  // namespace feel::test
