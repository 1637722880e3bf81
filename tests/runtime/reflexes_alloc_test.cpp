// The loop's command path never allocates: a hooked global allocator counts every
// allocation while reflexes fire on a busy button pattern and the engine takes every
// real-time command (start with iterations and solo, update with and without restart,
// status, pause/resume, actuators, stop all, pool) between ticks of a busy mix.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "feel/engine.hpp"
#include "feel/runtime/reflexes.hpp"
#include "support/counting_allocator.hpp"

namespace feel::runtime {
namespace {

TEST(ReflexAllocation, TheCounterSeesAllocations) {
    counting = true;
    auto* probe = new int(7);
    counting = false;
    EXPECT_GT(allocations.exchange(0), 0);
    delete probe;
}

TEST(ReflexAllocation, ReflexesAndCommandsRunWithoutAllocating) {
    Engine engine(EngineConfig{});
    ReflexTable reflexes(64);
    std::vector<EffectId> ids;
    const std::array<int16_t, 4> samples = {100, -200, 300, -400};
    for (int i = 0; i < 40; ++i) {
        EffectParams p;
        p.type = i % 4 == 0 ? EffectType::sine : i % 4 == 1 ? EffectType::constant
               : i % 4 == 2 ? EffectType::ramp : EffectType::force_profile;
        p.duration_us = 20'000 + 1000 * i;
        p.axis_count = 1;
        p.constant.magnitude = 300;
        p.periodic = {300, 0, 10'000, 0, 0, 0, SweepSense::clockwise};
        p.ramp = {-300, 300};
        p.custom = {1, 1000, 4};
        p.trigger = i < 36 ? Trigger{TriggerKind::button, i % 32 + 1} : Trigger{TriggerKind::hat, i - 35};
        p.trigger_repeat_interval_us = i % 3 == 0 ? 0 : 7000 + 1000 * i;
        const CreateResult r = engine.create(p, p.type == EffectType::force_profile
                                                    ? std::span<const int16_t>(samples)
                                                    : std::span<const int16_t>());
        ASSERT_TRUE(r.error.ok()) << r.error.message();
        ids.push_back(r.id);
    }
    ASSERT_TRUE(reflexes.assign_all(engine, ids).ok());
    ASSERT_EQ(reflexes.size(), 40);

    TickOutput out;
    EffectParams update;
    uint64_t status_sum = 0;
    counting = true;
    for (int n = 0; n < 20'000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        // Each button toggles at its own rate; hats in longer holds.
        for (int b = 0; b < 32; ++b) {
            if ((n / (3 + b)) % 2 == 1) in.buttons |= 1u << b;
        }
        for (int h = 0; h < 4; ++h) {
            if ((n / (50 + 10 * h)) % 2 == 1) in.hats |= 1u << h;
        }
        // Commands between ticks, as the command queue would deliver them.
        const EffectId id = ids[static_cast<size_t>(n % 40)];
        switch (n % 7) {
            case 0: (void)engine.start(id, 1 + n % 5, n % 700 == 0); break;
            case 1:
                (void)engine.params(id, update);
                update.gain = 5000 + n % 5000;
                (void)engine.update(id, update, effect_field::kGain, n % 2 == 0);
                break;
            case 2: status_sum += engine.status(id).starts; break;
            case 3: (void)engine.stop(id); break;
            case 4: status_sum += static_cast<uint64_t>(engine.pool().free_bytes); break;
            default: break;
        }
        if (n % 1000 == 500) engine.pause();
        if (n % 1000 == 600) engine.resume();
        if (n % 2000 == 1200) engine.set_actuators_enabled(false);
        if (n % 2000 == 1300) engine.set_actuators_enabled(true);
        if (n % 5000 == 4999) engine.stop_all();
        reflexes.on_tick(in, engine);
        engine.tick(in, out);
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    EXPECT_GT(reflexes.fired(), 1000u);
    EXPECT_GT(status_sum, 0u);
}

}  // namespace
}  // namespace feel::runtime
