// feel::host::emulation — a wall in closed loop through a modelled link, for the
// measurements of docs/real-devices.md ("Host emulation") and the tests that check them.
//
// Design. The simulated device (sim::SimDevice: the profile's mass, viscous and Coulomb
// friction, quantized sensors) steps at 1 kHz. The wall is rendered one of two ways:
//
//  * device-side: the engine ticks every update period T on the position it senses now,
//    and the motor holds that force until the next tick (zero-order hold, no lag);
//  * host-emulated: HostRenderer (the host's engine, the same configuration) ticks every T
//    on the position the device reported `latency_up` ago, and its force reaches the motor
//    `latency_down` later and is held until the next one arrives. A device that accepts
//    only standard PID plays it as a Set Constant Force's level, which is exactly a held
//    value; a streaming feel device ramps to each sample over one interval instead, which
//    is no faster (runtime.md, "Force streaming").
//
// Everything runs on simulated time, so a run is deterministic. The model's loop: position
// sampled at n·T − L_up, force applied from n·T + L_down: the force the handle feels at
// time t is K·p(t − τ) with τ ∈ [L, L + T), L = L_up + L_down.
#pragma once

#include <cstdint>
#include <vector>

#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"

namespace feel::host::emulation {

struct LoopLink {
    int32_t update_period_ms = 1;  // T: 1 (1 kHz), 2 (500 Hz), 8 (125 Hz); 1..100
    int32_t latency_up_ms = 0;     // position report's trip, whole ms, 0..100
    int32_t latency_down_ms = 0;   // force's trip, whole ms, 0..100
    bool host = false;             // false: device-side rendering (the latencies are ignored)
};

struct WallRun {
    std::vector<double> position;  // the handle's true x per ms, normalized units
    std::vector<double> force;     // the motor's force on x per ms (the wall and nothing else)
    std::vector<double> sensed;    // the sensed x per ms
};

// A wall on x at 0, free for x < 0, of this hardness (the wall of the runs below).
[[nodiscard]] EffectParams wall_on_x(int32_t hardness);

// A free handle (no grip) resting on a wall at 0 (free side x < 0) with `push` of force
// toward it (a weight), started `kick_speed` units/s into the wall from the surface, run for
// `duration_s`. The push is added at the motor, outside the wall's loop.
[[nodiscard]] WallRun run_pressed_wall(const sim::DeviceProfile& profile, const EngineConfig& config,
                                       int32_t hardness, const LoopLink& link, double push, double kick_speed,
                                       double duration_s);

// The handle moved kinematically from x0 at constant speed (units/s) into a wall at 0 for
// `duration_s`: what the wall answers.
[[nodiscard]] WallRun run_ramp_into_wall(const sim::DeviceProfile& profile, const EngineConfig& config,
                                         int32_t hardness, const LoopLink& link, double x0, double speed,
                                         double duration_s);

// Whether a pressed-wall run settled: the last second's peak-to-peak swing of the handle is
// below two sensor counts (a handle at rest may sit across one count boundary).
[[nodiscard]] bool settled(const WallRun& run, const sim::DeviceProfile& profile);

// The handle's peak-to-peak swing over [from_s, to_s) of a run, normalized units.
[[nodiscard]] double swing(const WallRun& run, double from_s, double to_s);

}  // namespace feel::host::emulation
