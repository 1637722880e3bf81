// Constant force, vector force and smart pop against their definitions (§6.6.c).
#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using ConstantWave = EngineFixture;

TEST_F(ConstantWave, HoldsItsMagnitudeForItsDurationThenStops) {
    const EffectId id = play(constant_on_x(4321, 50'000));
    expect_forces(50'000, 1000, [](int64_t, int axis) { return axis == 0 ? 4321.0 : 0.0; });
    EXPECT_EQ(tick().force[0], 0.0f);
    EXPECT_EQ(engine_->state(id), EffectState::stopped);
}

TEST_F(ConstantWave, NegativeMagnitudePushesTowardMinusAxis) {
    play(constant_on_x(-2500, 10'000));
    expect_forces(10'000, 1000, [](int64_t, int axis) { return axis == 0 ? -2500.0 : 0.0; });
}

TEST_F(ConstantWave, VectorForceIsEndless) {
    EffectParams p = constant_on_x(1000, kInfiniteUs);
    p.type = EffectType::vector_force;
    play(p);
    expect_forces(2'000'000, 10'000, [](int64_t, int axis) { return axis == 0 ? 1000.0 : 0.0; });
}

TEST_F(ConstantWave, SmartPopIsOneHalfSinePulse) {
    EffectParams p = constant_on_x(6000, 40'000);
    p.type = EffectType::smart_pop;
    play(p);
    expect_forces(40'000, 500, [](int64_t t, int axis) {
        return axis == 0 ? 6000.0 * std::sin(kPi * static_cast<double>(t) / 40'000.0) : 0.0;
    });
    EXPECT_EQ(tick().force[0], 0.0f);
}

}  // namespace
}  // namespace feel::test
