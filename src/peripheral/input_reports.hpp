// The runtime's reports as HID input reports: acks as CommandStatus (with Command Error
// Text), state reports as JoystickInput, DeviceStatus, Effect States pages and PidState,
// dynamics' reports as DynamicReport (by four axes).
// Every value is brought into its wire range here (rounded, and saturated where a float
// can exceed what the field holds), so that protocol::encode() never meets a value it
// refuses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "feel/engine.hpp"
#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/command_answer.hpp"
#include "feel/protocol/reports.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/status.hpp"
#include "report_translation.hpp"

namespace feel::peripheral::detail {

// Copies text into a fixed NUL-padded field of `size` bytes, keeping at most size - 1
// bytes and never cutting a UTF-8 sequence in half, so the field stays NUL-terminated.
void copy_text(char* dst, std::size_t size, std::string_view text) noexcept;

// The error part of a CommandStatus.
void fill_error(protocol::CommandAnswer& status, const Error& error) noexcept;
void fill_refusal(protocol::CommandAnswer& status, const Refusal& refusal) noexcept;
// The effect part: state, iterations (255 = infinite), progress, last end.
void fill_effect_status(protocol::CommandStatusReport& status, const EffectStatus& effect) noexcept;

[[nodiscard]] runtime::ReportedEffectState reported_state(EffectState state) noexcept;
// Whether a reported state counts as PID's "Effect Playing": started, delay included.
[[nodiscard]] bool is_playing(runtime::ReportedEffectState state) noexcept;

[[nodiscard]] protocol::JoystickInputReport joystick_input(const runtime::StateReport& state) noexcept;
[[nodiscard]] protocol::DeviceStatusReport device_status(const runtime::StateReport& state,
                                                         const LoopFigures& figures) noexcept;
// An Effect States report with everything but the page and its effects.
[[nodiscard]] protocol::EffectStatesReport effect_states(const runtime::StateReport& state) noexcept;
// The device flags of a PID State report, naming `block` (0 for none).
[[nodiscard]] protocol::PidStateReport pid_state(const runtime::StateReport& state, uint16_t block,
                                                 bool playing) noexcept;
// A dynamic's report from axis `first_axis` on (kDynamicAxesPerReport axes a report).
[[nodiscard]] protocol::DynamicReportReport dynamic_report(const DynamicReport& report, uint16_t block,
                                                           int first_axis) noexcept;

}  // namespace feel::peripheral::detail
