// The engine's memory on the Cortex-M4F for 32 effect slots on 2 axes, itemised; run by
// `make firmware` under qemu after the build (the flash figures come from the linked
// image, see firmware/CMakeLists.txt). Sample memory, the report queue and the pools of
// effect memory are sized as a small device would: 1024 force-profile samples (512 for a
// while in issue 14's RAM pass, until the estimator's pass made room: docs/firmware.md),
// 16 reports, 4 dynamics and 8 conditions with memory (friction, texture, walls, barriers)
// resident at once of the 32 effects.
#include <cstdint>
#include <cstdio>

#include "engine_impl.hpp"  // detail::Slot
#include "heap_guard.h"
#include "peer_mix.hpp"
#include "turn_trig.hpp"

namespace {

// Deepest use of the stack during a tick: the stack below the current frame is painted
// before and read after.
constexpr unsigned kPaint = 8192;

__attribute__((noinline)) void paint() {
    volatile unsigned char area[kPaint];
    for (unsigned i = 0; i < kPaint; ++i) area[i] = 0xA5;
}

// The handle of tick n: issue 14's slow circle (bench/peer_mix.hpp), in float with the
// engine's own sine, so that the size program brings no double sin or cos into the image
// (the flash report counts libm as the engine's callees; the positions only drive the
// ticks whose stack is measured).
void move_handle_in_float_circle(feel::TickInput& in, int n) {
    const float turns = 0.5f * static_cast<float>(n) * 1e-3f;
    const float step = 20000.0f / 4096.0f;
    in.t_us = int64_t{n} * 1000;
    in.position[0] = static_cast<float>(static_cast<int32_t>(6000.0f * feel::detail::cos_turns(turns) / step)) * step;
    in.position[1] = static_cast<float>(static_cast<int32_t>(6000.0f * feel::detail::sin_turns(turns) / step)) * step;
}

__attribute__((noinline)) unsigned untouched() {
    volatile unsigned char area[kPaint];
    unsigned i = 0;
    while (i < kPaint && area[i] == 0xA5) ++i;
    return i;
}

}  // namespace

// Force-profile samples: a small device's profile memory (§2.2, "Local Memory Limitations").
constexpr int kSamples = 1024;

int main() {
    using namespace feel;
    EngineConfig c;
    c.axis_count = 2;
    c.max_effects = 32;
    c.max_samples = kSamples;
    c.report_capacity = 16;
    c.max_dynamics = 4;
    c.max_stateful_conditions = 8;
    std::printf("feel-m4-size\n");  // stdio takes its buffer now, before the count
    const size_t before = heap_guard_requested_bytes();
    Engine engine(c);
    const unsigned heap = static_cast<unsigned>(heap_guard_requested_bytes() - before);
    heap_guard_lock();
    for (int i = 0; i < 32; ++i) {  // the first 32 of issue 14's mix fill the slots
        const CreateResult r = engine.create(bench::peer_mix_effect(i), {});
        if (!r.error.ok() || !engine.start(r.id).ok()) return 2;
    }
    TickInput in;
    TickOutput out;
    paint();
    for (int n = 1; n <= 200; ++n) {
        move_handle_in_float_circle(in, n);
        engine.tick(in, out);
    }
    const unsigned stack = kPaint - untouched();

    // What a slot holds: the effect's parameters (SlotParams: the header and its type's
    // block; a dynamic's block is in its record) and the rest (per-tick constants, clock,
    // command bookkeeping, the index of its memory). The memory between ticks is in two pools.
    const unsigned slot = sizeof(detail::Slot);
    const unsigned slot_params = sizeof(detail::SlotParams);
    const unsigned slots = 32 * slot;
    const unsigned dynamic_record = sizeof(detail::DynamicRecord);
    const unsigned condition_record = sizeof(detail::ConditionState);
    // A record and its entry in the pool's stack of free indices.
    const unsigned memory = static_cast<unsigned>(c.max_dynamics) * (dynamic_record + 2) +
                            static_cast<unsigned>(c.max_stateful_conditions) * (condition_record + 2);
    const unsigned samples = kSamples * sizeof(int16_t);
    const unsigned estimator = sizeof(detail::MotionEstimator);
    const unsigned reports = 16 * sizeof(detail::QueuedReport);
    const unsigned rest = heap - slots - memory - samples - reports - estimator;
    // The 16 KB goal split over the items: a budget each, so that each figure has a goal.
    // (A dynamic's parameter block moved from its slot into its record, and 2 KB of budget
    // with it; issue 14's RAM pass gave the sample memory's halved capacity to the effect
    // memory, the reports and the rest; the estimator's pass gave 1 KB of the estimator's
    // budget back to the samples.)
    constexpr unsigned kSlotBudget = 5120, kMemoryBudget = 4608, kSampleBudget = 2048, kEstimatorBudget = 3072,
                       kReportBudget = 640, kRestBudget = 896;
    static_assert(kSlotBudget + kMemoryBudget + kSampleBudget + kEstimatorBudget + kReportBudget + kRestBudget ==
                  16384);
    std::printf("RAM for 32 slots on 2 axes (bytes; goal: the 16384-byte goal split over the items):\n");
    std::printf("  slots            %6u  goal %5u  (32 x %u: parameters %u (the header and one block), "
                "constants, clock and commands %u)\n",
                slots, kSlotBudget, slot, slot_params, slot - slot_params);
    std::printf("  effect memory    %6u  goal %5u  (%d dynamics x %u with their block of %u, %d conditions with memory "
                "x %u, 2 bytes each to index them)\n",
                memory, kMemoryBudget, c.max_dynamics, dynamic_record, static_cast<unsigned>(sizeof(detail::SlotDynamicBlock)),
                c.max_stateful_conditions, condition_record);
    std::printf("  sample memory    %6u  goal %5u  (%d force-profile samples)\n", samples, kSampleBudget, kSamples);
    // The estimator's ring: a 32-bit time per sample and a float position per sample and axis.
    constexpr unsigned kHistory = detail::MotionEstimator::kHistory;
    const unsigned ring_times = kHistory * sizeof(uint32_t), ring_positions = kMaxAxes * kHistory * sizeof(float);
    std::printf("  estimator        %6u  goal %5u  (velocity and acceleration history, %d axes: %u samples of time %u "
                "and position %u; the fits' time pattern, running sums and state %u)\n",
                estimator, kEstimatorBudget, kMaxAxes, kHistory, ring_times, ring_positions,
                estimator - ring_times - ring_positions);
    std::printf("  reports          %6u  goal %5u  (16 dynamic reports of %u in the queue's record; the host's is %u)\n",
                reports, kReportBudget, static_cast<unsigned>(sizeof(detail::QueuedReport)),
                static_cast<unsigned>(sizeof(DynamicReport)));
    std::printf("  engine, rest     %6u  goal %5u  (the engine's own fields, friction's and texture's render-last list, the sample memory's index)\n", rest,
                kRestBudget);
    std::printf("  total            %6u  goal %5u  (all allocated once, by the constructor)\n", heap, 16384u);
    std::printf("  stack in a tick  %6u              (deepest, measured)\n", stack);
    return 0;
}
