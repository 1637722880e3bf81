// The fixed scenario the Cortex-M4 build and the x86 build both render, so that their
// forces can be compared (make test): every effect type at once (bench/busy_mix.hpp's 64
// effects: waves with envelopes, every Spatial Condition, every Dynamic Sensation) on 2
// axes, the handle on a scripted path that moves, bends, reverses and rests.
//
// The path uses only +, -, *, / and rounding, which IEEE 754 defines exactly, so both
// builds feed the engine the same bits (libm's sin and cos differ between glibc and newlib).
#pragma once

#include <cstdint>

#include "feel/engine.hpp"

namespace feel::firmware {

inline constexpr int kScenarioTicks = 3000;  // 3 s at 1 kHz
inline constexpr int kScenarioEffects = 64;

// 64 slots and 2 axes; the rest is EngineConfig's defaults but for a small sample memory.
EngineConfig scenario_config() noexcept;
// Creates and starts the effects; false if the engine refused one.
bool load_scenario(Engine& engine) noexcept;
// The sensed handle of tick n (1 kHz): quantized like the joystick's 4096-count sensor.
void scenario_handle(TickInput& in, int64_t n) noexcept;

}  // namespace feel::firmware
