// feel::host::emulation — HostRenderer: feel's engine run by the host for the effects a
// device cannot play itself (§1.2.c).
//
// Design. A device that lacks an effect type (Dynamics on an I-FORCE 1.x-class processor;
// walls, barriers, textures, sweeps, smart pops and Dynamics on a device with only the
// standard HID PID reports) still reports its positions and still plays a force the host
// streams. So the host runs the same engine the device would run, on the positions the
// device reports, and sends the summed result as one force per update: the device's own
// streaming (Download Force Sample) where it has it, else a standard Set Constant Force
// (force_link.hpp). Rendering is the engine's, so an emulated wall has the same
// hardness → stiffness, the same surface friction and the same passivity observer and
// controller as a wall on the device; only the loop around it differs: the update period
// is the link's (the device's report period, 1..10 ms) instead of the device's tick, and
// the position arrives and the force leaves with the link's latency. docs/real-devices.md,
// "Host emulation", derives how stiff a wall can then be and measures it.
//
// This class is the pure part: no threads, no clock, no transport. It is told each update's
// time and the reported positions, and returns the force. The same inputs give the same
// outputs (the engine's rule), so the closed-loop tests drive it directly with a modelled
// link. host_emulation.hpp wires it to a DeviceCore.
#pragma once

#include <cstdint>
#include <span>

#include "feel/engine.hpp"

namespace feel::host::emulation {

class HostRenderer {
public:
    // `config` describes the device (host_engine_config()): its axes, its mechanism's
    // damping and sensor step (which the passivity controller reads), the stiffness of a
    // hardness-10000 wall. The engine here plays every type.
    explicit HostRenderer(const EngineConfig& config);

    [[nodiscard]] CreateResult create(const EffectParams& params, std::span<const int16_t> samples = {}) noexcept;
    Error destroy(EffectId id) noexcept;
    // iterations: 1..255, kInfiniteIterations, or kOwnIterations for the effect's own count.
    static constexpr int32_t kOwnIterations = 0;
    Error start(EffectId id, int32_t iterations, bool solo) noexcept;
    Error stop(EffectId id) noexcept;
    void stop_all() noexcept;
    Error update(EffectId id, const EffectParams& params, uint32_t field_mask, bool restart,
                 std::span<const int16_t> samples = {}) noexcept;
    [[nodiscard]] EffectStatus status(EffectId id) const noexcept;
    void pause() noexcept;
    void resume() noexcept;

    // One update: the positions the device reported (normalized ±10000, device axis order),
    // its buttons and hats, at host time t_us (non-decreasing). Returns the force to send,
    // normalized ±10000 per device axis, physical sign, never NaN.
    const TickOutput& render(int64_t t_us, std::span<const float> position, uint32_t buttons,
                             uint32_t hats) noexcept;

    // Whether the last render() produced a force from a playing effect: when it stops
    // being true the host sends one zero force (a streaming device holds the last value).
    [[nodiscard]] bool playing() const noexcept { return last_.playing_effects > 0; }
    // The oldest interim or final report of a host-rendered dynamic, if any (the engine's
    // queue: a render may produce some).
    [[nodiscard]] bool pop_report(DynamicReport& report) noexcept { return engine_.pop_report(report); }
    [[nodiscard]] int32_t axis_count() const noexcept { return axis_count_; }
    [[nodiscard]] int64_t updates() const noexcept { return updates_; }

private:
    Engine engine_;
    int32_t axis_count_;
    TickOutput last_{};
    int64_t last_t_us_ = 0;
    int64_t updates_ = 0;
};

}  // namespace feel::host::emulation
