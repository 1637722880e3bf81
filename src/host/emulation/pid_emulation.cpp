// PidEmulation: host-rendered effects on a standard PID device (pid_emulation.hpp).
#include "emulation/pid_emulation.hpp"

#include <algorithm>
#include <cmath>

#include "emulation/emulation_config.hpp"

namespace feel::host::emulation {

PidEmulation::PidEmulation(const EngineConfig& config, std::vector<LinkAxis> link)
    : renderer(config), link_(std::move(link)) {}

bool PidEmulation::links(Axis axis) const noexcept {
    return std::any_of(link_.begin(), link_.end(), [&](const LinkAxis& l) { return l.axis == axis; });
}

void PidEmulation::render(int64_t t_us, const protocol::pid::JoystickReading& reading) {
    last_ = reading;
    has_reading_ = true;
    fired_.clear();
    triggers.update(t_us, reading.buttons, reading.hats, fired_);
    for (const EffectId id : fired_) (void)renderer.start(id, HostRenderer::kOwnIterations, false);
    const TickOutput& out = renderer.render(
        t_us, std::span<const float>(reading.position, static_cast<std::size_t>(renderer.axis_count())),
        reading.buttons, reading.hats);
    ++updates;
    for (int i = 0; i < kMaxAxes; ++i) {
        // The engine's force is within ±10000 and never NaN; rounding keeps it there.
        level_[i] = std::clamp(static_cast<int32_t>(std::lround(out.force[i])), -kFullScale, kFullScale);
    }
}

void PidEmulation::arm_trigger(uint16_t handle, EffectId id, const EffectParams& params) {
    triggers.arm(handle, id, params.trigger, params.trigger_repeat_interval_us, last_.buttons, last_.hats);
}

bool PidEmulation::render_if_stalled(int64_t t_us) {
    if (!has_reading_) return false;
    render(t_us, last_);
    return true;
}

void PidEmulation::take_due(std::vector<std::pair<uint16_t, int32_t>>& out) {
    out.clear();
    for (LinkAxis& l : link_) {
        const int32_t level = level_[static_cast<int>(l.axis)];
        if (level == l.last_sent) continue;
        out.emplace_back(l.block, level);
        l.last_sent = level;
        ++levels_sent;
    }
}

EngineConfig pid_engine_config(const std::string& profile, const protocol::pid::PidLayout& layout) {
    DeviceCaps caps;
    caps.device = profile;
    int32_t axes = 1;
    for (const Axis a : layout.input_axes()) axes = std::max(axes, static_cast<int32_t>(a) + 1);
    caps.axis_count = axes;
    const protocol::pid::JoystickInputLayout& j = layout.joystick_input();
    if (!j.axes.empty()) {
        const auto& f = j.fields[j.axes.front().field];
        caps.axes[0].sensor_counts = static_cast<int32_t>(std::min<int64_t>(f.logical_max - f.logical_min + 1, INT32_MAX));
    }
    EngineConfig c = host_engine_config(caps);
    c.axis_count = axes;
    return c;
}

EffectStatusInfo emulated_status(const EffectStatus& s) noexcept {
    EffectStatusInfo info;
    info.emulated = true;
    // Playing (or about to, or inside its start delay) on the host's behalf: "emulated".
    const bool playing = s.state == EffectState::pending || s.state == EffectState::delayed ||
                         s.state == EffectState::playing;
    info.state = playing ? runtime::ReportedEffectState::emulated : runtime::ReportedEffectState::stopped;
    info.iterations = s.iterations;
    info.completed_iterations = s.completed_iterations;
    info.elapsed_us = s.elapsed_us;
    info.last_end = s.last_end;
    return info;
}

}  // namespace feel::host::emulation
