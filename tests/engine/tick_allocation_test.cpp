// The tick never allocates: a hooked global allocator counts every allocation made while
// a busy mix of waves plays for many ticks.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <new>

#include "feel/engine.hpp"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t n) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
// GCC cannot see that these deletes pair with the malloc-based new above.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace feel {
namespace {

TEST(TickAllocation, TheCounterSeesAllocations) {
    counting = true;
    auto* probe = new int(7);
    counting = false;
    EXPECT_GT(allocations.exchange(0), 0);
    delete probe;
}

TEST(TickAllocation, ABusyWaveMixTicksWithoutAllocating) {
    Engine engine(EngineConfig{});
    const std::array<int16_t, 8> samples = {100, 200, 300, 400, -100, -200, -300, -400};
    for (int i = 0; i < 64; ++i) {
        EffectParams p;
        p.type = static_cast<EffectType>(static_cast<int>(EffectType::vector_force) + i % 15);
        p.duration_us = 500'000;
        p.axis_count = 2;
        p.axes[0] = Axis::x;
        p.axes[1] = Axis::y;
        p.direction.kind = is_sweep(p.type) ? DirectionKind::none : DirectionKind::polar;
        p.direction.value[0] = (1000 * i) % 36000;
        p.constant.magnitude = 100;
        p.periodic = {100, 0, 10'000, 0, 0, 9000, SweepSense::clockwise};
        p.ramp = {0, 100};
        p.custom = {2, 1000, 8};
        p.iterations = kInfiniteIterations;
        if (p.type == EffectType::force_profile) p.direction.kind = DirectionKind::none;
        const CreateResult r = engine.create(p, p.type == EffectType::force_profile ? std::span<const int16_t>(samples)
                                                                                    : std::span<const int16_t>());
        ASSERT_TRUE(r.error.ok()) << effect_type_name(p.type) << ": " << r.error.message();
        ASSERT_TRUE(engine.start(r.id).ok());
    }
    TickOutput out;
    counting = true;
    for (int n = 0; n < 20'000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        engine.tick(in, out);
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    EXPECT_EQ(out.playing_effects, 64);
}

}  // namespace
}  // namespace feel
