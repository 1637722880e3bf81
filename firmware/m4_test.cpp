// The engine on the emulated Cortex-M4F (qemu-system-arm -M mps2-an386, semihosting).
//
// 1. Renders the fixed scenario (scenario.hpp: every effect type on a scripted handle) and
//    prints every tick's forces as the bits of their floats, "F n x y" in hex; the x86
//    side (tests/firmware/firmware_compare.cpp) renders the same and compares.
// 2. Counts the instructions of a tick (instruction_counter.hpp) for issue 14's 40-effect
//    mix with the handle moving and at rest, for the velocity estimator alone, and for the
//    scenario's 64 effects and for its mix class by class (waves, conditions, dynamics);
//    prints "count NAME ticks=N instructions_per_tick=I".
// Nothing is allocated after the engines are built: heap_guard ends the run if it is.
#include <cstdio>
#include <cstring>

#include "heap_guard.h"
#include "instruction_counter.hpp"
#include "motion_estimator.hpp"
#include "busy_mix.hpp"
#include "peer_mix.hpp"
#include "scenario.hpp"

namespace {

using namespace feel;

uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

// Ticks an engine n times on precomputed inputs, counting the instructions of the ticks only.
template <typename Tick>
void count(const char* name, int n, Tick tick) {
    uint64_t counts = 0;
    for (int k = 0; k < n; ++k) {
        const uint32_t before = firmware::InstructionCounter::now();
        tick(k);
        counts += firmware::InstructionCounter::counts_since(before);
    }
    const uint64_t instructions = counts * firmware::InstructionCounter::kInstructionsPerCount;
    std::printf("count %s ticks=%d instructions_per_tick=%lu\n", name, n,
                static_cast<unsigned long>(instructions / static_cast<uint64_t>(n)));
}

constexpr int kCountedTicks = 1000;
TickInput g_inputs[kCountedTicks];  // precomputed: the motion's double sin/cos are not counted

}  // namespace

int main() {
    std::printf("feel-m4-test ticks=%d effects=%d\n", firmware::kScenarioTicks, firmware::kScenarioEffects);
    static Engine scenario(firmware::scenario_config());
    static Engine peer(EngineConfig{});
    static Engine peer_at_rest(EngineConfig{});
    if (!firmware::load_scenario(scenario) || !bench::load_peer_mix(peer) || !bench::load_peer_mix(peer_at_rest)) {
        std::printf("error: an engine refused the mix\n");
        return 2;
    }
    // The scenario's mix by class (bench/busy_mix.hpp's 64 effects: 24 waves, 24 conditions,
    // 16 dynamics), each on an engine of its own, on the mix's motion (a circle with a
    // 40 Hz wiggle); "none" is the engine and the estimator alone.
    static Engine by_class[4] = {Engine(EngineConfig{}), Engine(EngineConfig{}), Engine(EngineConfig{}),
                                 Engine(EngineConfig{})};
    const char* class_names[4] = {"busy_none", "busy_waves_24", "busy_conditions_24", "busy_dynamics_16"};
    for (int i = 0; i < 64; ++i) {
        const int kind = i % 8;
        Engine& e = by_class[kind < 3 ? 1 : (kind < 6 ? 2 : 3)];
        if (!bench::load_busy_mix_effect(e, i).ok()) {
            std::printf("error: an engine refused effect %d of the busy mix\n", i);
            return 2;
        }
    }
    static detail::MotionEstimator estimator;
    estimator.configure(20000.0f / 4096.0f);
    std::printf("heap at start-up: %u bytes\n", static_cast<unsigned>(heap_guard_requested_bytes()));
    // The board's engine is built for 2 axes (FEEL_MAX_AXES=2): a device or an effect with
    // more is refused with the range it allows, not stored past its arrays. (After the heap
    // figure, which counts only the engines the test runs.)
    {
        EngineConfig three_axes;
        three_axes.axis_count = 3;
        Engine too_wide(three_axes);
        const Error device = too_wide.create(EffectParams{}, {}).error;
        EffectParams effect = bench::peer_mix_effect(0);
        effect.axis_count = 3;
        const Error wide_effect = scenario.create(effect, {}).error;
        const bool device_refused = std::strcmp(device.field, "axis_count") == 0 && device.allowed.max == 2;
        const bool effect_refused = std::strcmp(wide_effect.field, "axes") == 0 && wide_effect.allowed.max == 2;
        std::printf("refuses 3 axes: device %s, effect %s\n", device_refused ? "yes" : "NO",
                    effect_refused ? "yes" : "NO");
        if (!device_refused || !effect_refused) return 2;
    }
    heap_guard_lock();

    firmware::InstructionCounter counter;
    TickInput in;
    TickOutput out;
    DynamicReport report;
    uint64_t scenario_counts = 0;
    for (int n = 1; n <= firmware::kScenarioTicks; ++n) {
        firmware::scenario_handle(in, n);
        const uint32_t before = firmware::InstructionCounter::now();
        scenario.tick(in, out);
        scenario_counts += firmware::InstructionCounter::counts_since(before);
        while (scenario.pop_report(report)) {
        }
        std::printf("F %d %08lx %08lx\n", n, static_cast<unsigned long>(bits(out.force[0])),
                    static_cast<unsigned long>(bits(out.force[1])));
    }
    std::printf("count scenario_64_effects ticks=%d instructions_per_tick=%lu\n", firmware::kScenarioTicks,
                static_cast<unsigned long>(scenario_counts * firmware::InstructionCounter::kInstructionsPerCount /
                                           firmware::kScenarioTicks));

    // Issue 14's mix: 1 s of the slow circle after a first second that fills the history.
    for (int k = 0; k < kCountedTicks; ++k) bench::move_handle_in_slow_circle(g_inputs[k], k + 1);
    for (int k = 0; k < kCountedTicks; ++k) peer.tick(g_inputs[k], out);
    for (int k = 0; k < kCountedTicks; ++k) bench::move_handle_in_slow_circle(g_inputs[k], kCountedTicks + k + 1);
    count("peer_mix_40_moving", kCountedTicks, [&](int k) { peer.tick(g_inputs[k], out); });
    count("estimator_2_axes_moving", kCountedTicks,
          [&](int k) { estimator.update(g_inputs[k].t_us, g_inputs[k].position, 2); });
    TickInput still;
    bench::move_handle_in_slow_circle(still, 0);
    for (int k = 0; k < kCountedTicks; ++k) {
        still.t_us = (k + 1) * 1000;
        peer_at_rest.tick(still, out);
    }
    count("peer_mix_40_at_rest", kCountedTicks, [&](int k) {
        still.t_us = (kCountedTicks + k + 1) * 1000;
        peer_at_rest.tick(still, out);
    });
    for (int c = 0; c < 4; ++c) {
        for (int k = 0; k < kCountedTicks; ++k) {
            bench::move_handle(g_inputs[k], k + 1);
            g_inputs[k].t_us = (k + 1) * 1000;
        }
        for (int k = 0; k < kCountedTicks; ++k) {
            by_class[c].tick(g_inputs[k], out);
            while (by_class[c].pop_report(report)) {
            }
        }
        for (int k = 0; k < kCountedTicks; ++k) {
            bench::move_handle(g_inputs[k], kCountedTicks + k + 1);
            g_inputs[k].t_us = (kCountedTicks + k + 1) * 1000;
        }
        count(class_names[c], kCountedTicks, [&](int k) {
            by_class[c].tick(g_inputs[k], out);
            while (by_class[c].pop_report(report)) {
            }
        });
    }
    std::printf("done\n");
    return 0;
}
