// feel::host::emulation — host emulation on a standard HID PID device (PidDevice).
//
// Design. A device with only PID's reports has no streaming of its own (no Download Force
// Sample, no timestamps, no answers), so the force the host renders reaches it the one way
// PID offers: a Constant Force effect the host owns, its level rewritten by Set Constant
// Force. There is one such effect per force axis (an axis that reports a position and that
// Set Effect's Axes Enable names), created once when the first host-rendered effect is made,
// with an infinite duration, gain 10000 and no direction (it plays along its own axis with
// the force's sign), and started once with Effect Operation (loop until stopped). After that
// an update costs one Set Constant Force per axis whose level changed, and nothing while the
// force holds still.
//
// Updates. Each Input report the device sends is one update: the positions in it (read by
// the descriptor's own layout, pid_layout.hpp) go through the host's engine (HostRenderer:
// the same configuration as the device's own engine would have), at the report's sense
// time. A standard report carries no time, and its arrival is no measure of it on a link
// that delivers in bursts, so the sense time is reconstructed from the report sequence
// (sense_clock.hpp: the device's report grid, anchored to the least-delayed arrivals). The
// I/O thread reads everything queued, places the drain's reports on the grid, renders each
// in order and sends once: a link slower than the report rate carries the newest force and
// never a backlog, so the update rate is the highest the link sustains. A device that
// reports only when something changes would leave time-based effects standing with the
// handle, so after a silence (kStallUs before the clock knows a report period,
// kPeriodicStallUs after: longer than a loaded link's gaps, whose reports arrive later in a
// burst) the host renders on the last positions.
//
// This class is the host's side of it without I/O: PidDevice (pid_device.cpp) owns the
// link's blocks, reads the reports and sends what due() returns. Locks: mu guards all of
// it; the caller's thread and the I/O thread both take it, never while waiting on the
// device.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "emulation/host_renderer.hpp"
#include "emulation/trigger_watch.hpp"
#include "feel/host/device.hpp"
#include "feel/protocol/pid_layout.hpp"

namespace feel::host::emulation {

// A device that reports no Input for this long gets a render on its last positions: before
// its report period is known, and once it is (sense_clock.hpp).
inline constexpr int64_t kStallUs = 10'000;
inline constexpr int64_t kPeriodicStallUs = 125'000;

class PidEmulation {
public:
    struct LinkAxis {
        Axis axis = Axis::x;
        uint16_t block = 0;       // the device's Constant Force effect for this axis
        int32_t last_sent = 0;    // the level last sent (the effect starts at 0)
    };

    PidEmulation(const EngineConfig& config, std::vector<LinkAxis> link);

    // One update at host time t_us with the positions, buttons and hats of a report: the
    // reflexes whose trigger fired start first, so that a press plays from this update on.
    void render(int64_t t_us, const protocol::pid::JoystickReading& reading);
    // Arms (or disarms, without a trigger) the reflex of host effect `handle` (renderer id
    // `id`) on the buttons and hats of the last reading. Caller holds mu.
    void arm_trigger(uint16_t handle, EffectId id, const EffectParams& params);
    // A render on the last reading at sense time t_us, for a silent device (false: no
    // reading yet).
    bool render_if_stalled(int64_t t_us);
    // The Set Constant Force levels due: (block, level) of each axis whose level changed
    // since it was last sent; they count as sent.
    void take_due(std::vector<std::pair<uint16_t, int32_t>>& out);

    [[nodiscard]] const std::vector<LinkAxis>& link() const noexcept { return link_; }
    [[nodiscard]] bool links(Axis axis) const noexcept;
    [[nodiscard]] bool has_reading() const noexcept { return has_reading_; }
    // The reading the last render used (a stall render renders on it again).
    [[nodiscard]] const protocol::pid::JoystickReading& last_reading() const noexcept { return last_; }

    std::mutex mu;
    HostRenderer renderer;                 // guarded by mu
    std::map<uint16_t, EffectId> handles;  // the caller's handle → the renderer's effect; guarded by mu
    TriggerWatch<EffectId> triggers;       // by handle: host effects' reflexes; guarded by mu
    int64_t updates = 0;                   // renders; guarded by mu
    int64_t levels_sent = 0;               // Set Constant Force reports taken; guarded by mu

private:
    std::vector<LinkAxis> link_;
    protocol::pid::JoystickReading last_{};
    bool has_reading_ = false;
    int32_t level_[kMaxAxes] = {};  // the last render's force per axis index, rounded
    std::vector<EffectId> fired_;   // render()'s reflexes to start
};

// The host engine's configuration for a PID device: feel's profile `profile` when it names
// one (sim::engine_config_for, as host_engine_config()), else the engine's defaults with the
// sensor step of the first input axis; axis_count spans the highest input axis.
[[nodiscard]] EngineConfig pid_engine_config(const std::string& profile, const protocol::pid::PidLayout& layout);

// An emulated effect's status: "emulated" while it plays (or waits in its delay).
[[nodiscard]] EffectStatusInfo emulated_status(const EffectStatus& s) noexcept;

}  // namespace feel::host::emulation
