// Runtime reports -> HID input reports (input_reports.hpp).
#include "input_reports.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace feel::peripheral::detail {
namespace {

// Rounds to the nearest integer within [lo, hi]; NaN reads as 0 (the runtime never posts
// one, and a report must still encode if it did).
template <class T>
T saturate(double v, double lo, double hi) noexcept {
    if (std::isnan(v)) return T{0};
    return static_cast<T>(std::llround(std::clamp(v, lo, hi)));
}

int16_t level(float v) noexcept { return saturate<int16_t>(v, -kFullScale, kFullScale); }

int32_t centi(float v) noexcept {
    return saturate<int32_t>(static_cast<double>(v) * 100.0, std::numeric_limits<int32_t>::min(),
                             std::numeric_limits<int32_t>::max());
}

}  // namespace

void copy_text(char* dst, std::size_t size, std::string_view text) noexcept {
    if (size == 0) return;
    std::size_t n = std::min(text.size(), size - 1);
    // Back off to the start of a UTF-8 sequence when the cut falls inside one: the byte
    // after the cut is a continuation byte (10xxxxxx).
    if (n < text.size()) {
        while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0u) == 0x80u) --n;
    }
    std::memset(dst, 0, size);
    std::memcpy(dst, text.data(), n);
}

void fill_error(protocol::CommandAnswer& status, const Error& error) noexcept {
    status.code = error.code;
    copy_text(status.field, sizeof status.field, std::string_view(error.field, strnlen(error.field, sizeof error.field)));
    status.has_range = error.has_range;
    status.value = error.has_range ? error.value : 0;
    status.allowed_min = error.has_range ? error.allowed.min : 0;
    status.allowed_max = error.has_range ? error.allowed.max : 0;
    copy_text(status.rule, sizeof status.rule, error.rule != nullptr ? std::string_view(error.rule) : std::string_view());
}

void fill_refusal(protocol::CommandAnswer& status, const Refusal& refusal) noexcept {
    status.code = refusal.code;
    copy_text(status.field, sizeof status.field, refusal.field);
    status.has_range = refusal.has_range;
    status.value = refusal.value;  // also without a range: an unknown report id, a hole in an enum
    status.allowed_min = refusal.has_range ? refusal.allowed.min : 0;
    status.allowed_max = refusal.has_range ? refusal.allowed.max : 0;
    copy_text(status.rule, sizeof status.rule, refusal.rule);
}

runtime::ReportedEffectState reported_state(EffectState state) noexcept {
    switch (state) {
        case EffectState::delayed: return runtime::ReportedEffectState::delayed;
        case EffectState::pending:
        case EffectState::playing: return runtime::ReportedEffectState::playing;
        case EffectState::free:
        case EffectState::stopped: break;
    }
    return runtime::ReportedEffectState::stopped;
}

bool is_playing(runtime::ReportedEffectState state) noexcept {
    return state == runtime::ReportedEffectState::playing || state == runtime::ReportedEffectState::delayed;
}

void fill_effect_status(protocol::CommandStatusReport& status, const EffectStatus& effect) noexcept {
    status.effect_state = static_cast<uint8_t>(reported_state(effect.state));
    status.iterations = effect.iterations == kInfiniteIterations
                            ? protocol::kLoopInfinite
                            : static_cast<uint16_t>(std::clamp<int32_t>(effect.iterations, 0, 255));
    status.completed_iterations = static_cast<uint8_t>(std::clamp<int32_t>(effect.completed_iterations, 0, 255));
    status.elapsed_us = static_cast<uint32_t>(
        std::clamp<int64_t>(effect.elapsed_us, 0, std::numeric_limits<uint32_t>::max()));
    status.last_end = static_cast<uint8_t>(effect.last_end);
}

protocol::JoystickInputReport joystick_input(const runtime::StateReport& state) noexcept {
    protocol::JoystickInputReport r;
    const int axes = std::clamp(state.axis_count, 0, kMaxAxes);
    for (int a = 0; a < axes; ++a) r.position[a] = level(state.position[a]);
    r.buttons = state.buttons;
    r.hats = static_cast<uint8_t>(state.hats & 0x0Fu);  // four hat switches at most
    return r;
}

protocol::DeviceStatusReport device_status(const runtime::StateReport& state, const LoopFigures& figures) noexcept {
    protocol::DeviceStatusReport r;
    r.t_us = static_cast<uint64_t>(std::max<int64_t>(state.t_us, 0));
    r.report_number = state.report_number;
    const int axes = std::clamp(state.axis_count, 0, kMaxAxes);
    for (int a = 0; a < axes; ++a) {
        r.force[a] = level(state.force[a]);
        r.velocity[a] = saturate<int32_t>(state.velocity[a], std::numeric_limits<int32_t>::min(),
                                          std::numeric_limits<int32_t>::max());
    }
    r.fade_level = saturate<uint16_t>(static_cast<double>(state.safety.fade_level) * kFullScale, 0, kFullScale);
    uint8_t flags = 0;
    if (state.safety.handle_held) flags |= 1u << 0;
    if (state.safety.hands_off) flags |= 1u << 1;
    if (state.safety.host_lost) flags |= 1u << 2;
    if (state.paused) flags |= 1u << 3;
    if (state.actuators_enabled) flags |= 1u << 4;
    r.safety_flags = flags;
    r.gain = static_cast<uint16_t>(std::clamp(state.gain, 0, kFullScale));
    r.loop_rate_hz = static_cast<uint16_t>(std::clamp(figures.loop_rate_hz, 0, 65535));
    r.overruns = static_cast<uint32_t>(std::clamp<int64_t>(figures.overruns, 0, std::numeric_limits<uint32_t>::max()));
    r.measured_rate_millihz = static_cast<uint32_t>(
        std::clamp<int64_t>(figures.measured_rate_millihz, 0, std::numeric_limits<uint32_t>::max()));
    return r;
}

protocol::EffectStatesReport effect_states(const runtime::StateReport& state) noexcept {
    protocol::EffectStatesReport r;
    r.report_number = state.report_number;
    r.playing_effects = static_cast<uint16_t>(std::clamp(state.playing_effects, 0, 65535));
    r.resident_effects = static_cast<uint16_t>(std::clamp(state.resident_effects, 0, 65535));
    r.dropped_reports = state.dropped_reports;
    return r;
}

protocol::PidStateReport pid_state(const runtime::StateReport& state, uint16_t block, bool playing) noexcept {
    protocol::PidStateReport r;
    r.device_paused = state.paused;
    r.actuators_enabled = state.actuators_enabled;
    r.safety_switch = state.safety.handle_held;
    r.actuator_override = state.safety.hands_off || state.safety.host_lost;
    r.actuator_power = true;  // the simulated motors are always powered; the flags above say why no force
    r.effect_playing = block != 0 && playing;
    r.block = block;
    return r;
}

protocol::DynamicReportReport dynamic_report(const DynamicReport& report, uint16_t block, int first_axis) noexcept {
    protocol::DynamicReportReport r;
    r.block = block;
    r.final_report = report.kind == DynamicReport::Kind::final ? 1 : 0;
    r.t_us = static_cast<uint64_t>(std::max<int64_t>(report.t_us, 0));
    const int axes = std::clamp(report.axis_count, 0, kMaxAxes);
    r.axis_count = static_cast<uint8_t>(axes);
    first_axis = std::clamp(first_axis, 0, kMaxAxes - 1);
    r.first_axis = static_cast<uint8_t>(first_axis);
    for (int slot = 0; slot < protocol::kDynamicAxesPerReport && first_axis + slot < axes; ++slot) {
        const int a = first_axis + slot;
        r.position_centi[slot] = centi(report.position[a]);
        r.velocity_centi[slot] = centi(report.velocity[a]);
        r.handle_velocity_centi[slot] = centi(report.handle_velocity[a]);
    }
    return r;
}

}  // namespace feel::peripheral::detail
