// The impulse envelope (§4.2.a, §6.3) on constant, periodic, ramp and profile waves.
#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using EnvelopeShaping = EngineFixture;

// The envelope's level at t for steady level S, written from the primer's description:
// a straight line from the impulse level to S over the settle time, and from S to the
// fade level over the last fade time.
double level(double impulse, double settle, double steady, double fade_level, double fade,
             double duration, double t) {
    double l = steady;
    if (t < settle) l = impulse + (steady - impulse) * t / settle;
    if (t > duration - fade) l = l + (fade_level - l) * (t - (duration - fade)) / fade;
    return l;
}

TEST_F(EnvelopeShaping, RailingImpactKicksThenSettles) {
    // §4.2.a: a sharp impulse that settles to a mild steady state, then fades out.
    EffectParams p = constant_on_x(2000, 1'000'000);
    p.has_envelope = true;
    p.envelope = {9000, 30'000, 0, 200'000};
    play(p);
    expect_forces(1'000'000, 1000, [](int64_t t, int axis) {
        return axis == 0 ? level(9000, 30'000, 2000, 0, 200'000, 1'000'000, static_cast<double>(t)) : 0.0;
    });
    // Spot values from the definition: the kick, halfway settled, steady, halfway faded.
    reset(2);
    play(p);
    EXPECT_NEAR(tick(15'000).force[0], 9000, kForceTolerance);
    EXPECT_NEAR(tick(15'000).force[0], 5500, kForceTolerance);
    EXPECT_NEAR(tick(870'000).force[0], 2000, kForceTolerance);
    EXPECT_NEAR(tick().force[0], 1000, kForceTolerance);  // t = 900 ms, half way down the fade
}

TEST_F(EnvelopeShaping, NegativeMagnitudeKeepsItsSign) {
    EffectParams p = constant_on_x(-3000, 100'000);
    p.has_envelope = true;
    p.envelope = {6000, 20'000, 0, 0};
    play(p);
    EXPECT_NEAR(tick(10'000).force[0], -6000, kForceTolerance);
    EXPECT_NEAR(tick().force[0], -4500, kForceTolerance);
}

TEST_F(EnvelopeShaping, ShapesTheOscillationNotTheOffset) {
    EffectParams p = periodic_on_x(EffectType::sine, 4000, 1500, 10'000, 0, 200'000);
    p.has_envelope = true;
    p.envelope = {0, 100'000, 0, 0};  // a fade-in from zero over 100 ms
    play(p);
    expect_forces(200'000, 250, [](int64_t t, int axis) {
        if (axis != 0) return 0.0;
        const double amp = level(0, 100'000, 4000, 0, 0, 200'000, static_cast<double>(t));
        return 1500 + amp * std::sin(2 * kPi * static_cast<double>(t) / 10'000);
    }, 0.05);
}

TEST_F(EnvelopeShaping, EndlessWavesNeverFade) {
    EffectParams p = constant_on_x(5000, kInfiniteUs);
    p.type = EffectType::vector_force;
    p.has_envelope = true;
    p.envelope = {10000, 50'000, 0, 100'000};
    play(p);
    expect_forces(3'000'000, 5000, [](int64_t t, int axis) {
        return axis == 0 ? level(10000, 50'000, 5000, 5000, 1, 1e18, static_cast<double>(t)) : 0.0;
    });
}

TEST_F(EnvelopeShaping, OverlappingSettleAndFadeFadeFromTheSettlingLevel) {
    EffectParams p = constant_on_x(4000, 100'000);
    p.has_envelope = true;
    p.envelope = {10000, 80'000, 0, 50'000};
    play(p);
    // At t = 60 ms: settling level 10000 + (4000-10000)·0.75 = 5500; fade progress 0.2.
    tick(60'000);
    EXPECT_NEAR(tick().force[0], 5500 + (0 - 5500) * 0.2, kForceTolerance);
}

}  // namespace
}  // namespace feel::test
