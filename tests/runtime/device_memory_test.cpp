// The simulated devices' local memory (§2.2, issue 5 §3): an I-FORCE 2.0-class budget of
// 32 effect slots and 16 KiB of parameter memory, fixed at init (the 1.x class's smaller
// budget: capabilities_test.cpp). Costs are summed by hand from the table in docs/runtime.md.
#include <gtest/gtest.h>

#include <vector>

#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel {
namespace {

TEST(DeviceMemory, EveryIforce2ClassProfileHas32SlotsAnd16KiB) {
    for (const sim::DeviceProfile& profile : sim::device_profiles()) {
        if (profile.device_class != sim::DeviceClass::iforce2) continue;
        Engine engine(sim::engine_config_for(profile));
        const PoolInfo p = engine.pool();
        EXPECT_EQ(p.total_bytes, 16'384) << profile.name;
        EXPECT_EQ(p.free_bytes, 16'384) << profile.name;
        EXPECT_EQ(p.max_effects, 32) << profile.name;
        EXPECT_EQ(p.total_samples, 8192) << profile.name;  // the whole pool, at 2 bytes a sample
    }
}

TEST(DeviceMemory, TheJoystickHoldsAFullSetOfEnvelopedSweepsAndStillHasRoomForAProfile) {
    Engine engine(sim::engine_config_for(*sim::find_device_profile("joystick")));
    EffectParams sweep;
    sweep.type = EffectType::sweep_sine;
    sweep.duration_us = 500'000;
    sweep.axis_count = 2;
    sweep.periodic = {5000, 0, 20'000, 0, 0, 18'000, SweepSense::clockwise};
    sweep.has_envelope = true;
    for (int i = 0; i < 31; ++i) ASSERT_TRUE(engine.create(sweep).error.ok()) << i;
    const int32_t used = 31 * (14 + 14 + 16);
    EXPECT_EQ(engine.pool().free_bytes, 16'384 - used);
    // The last slot: the largest profile that fits is (free - 14 - 8) / 2 samples.
    const int32_t fits = (16'384 - used - 14 - 8) / 2;
    EffectParams profile;
    profile.type = EffectType::force_profile;
    profile.duration_us = kInfiniteUs;
    profile.axis_count = 1;
    profile.custom = {1, 1000, fits + 1};
    const CreateResult too_big = engine.create(profile, std::vector<int16_t>(static_cast<size_t>(fits + 1), 1));
    EXPECT_EQ(too_big.error.code, ErrorCode::device_full);
    profile.custom.sample_count = fits;
    EXPECT_TRUE(engine.create(profile, std::vector<int16_t>(static_cast<size_t>(fits), 1)).error.ok());
    EXPECT_EQ(engine.pool().free_effects, 0);
    EXPECT_LE(engine.pool().free_bytes, 1);
}

}  // namespace
}  // namespace feel
