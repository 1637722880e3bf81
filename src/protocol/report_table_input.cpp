// The input reports (device -> host): the joystick's state (Generic Desktop), PID State, and
// feel's Command Status (with Command Error Text), Device Status (with Effect States) and
// Dynamic Report. Each fits one 64-byte interrupt packet (kInterruptPacketBytes).
#include "feel/engine.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "hid_usages.hpp"
#include "joystick_layout.hpp"
#include "report_table.hpp"

namespace feel::protocol::detail {
namespace {

using namespace usage;

constexpr Range kErrorCode{0, 4};               // feel::ErrorCode
constexpr Range kReportedState{0, 3};           // runtime::ReportedEffectState
constexpr Range kPlayEnd{0, 2};                 // feel::PlayEnd
constexpr Range kSafetyFlags{0, 0x1F};          // five flag bits
constexpr Range kPages{1, 0xFF};
constexpr Range kStatusEffects{0, kEffectsPerStatusReport};
constexpr Range kAxisCountOrNone{0, kMaxAxes};
constexpr Range kFirstAxis{0, kMaxAxes - 1};
constexpr Range kErrorTextPart{0, 2};
// Command Status's `command`: kNoReportId (0) or a ReportId up to the highest.
constexpr Range kAnsweredIds{0x00, 0x46};
static_assert(static_cast<int>(ErrorCode::invalid_handle) == kErrorCode.max, "ErrorCode's last");
static_assert(static_cast<int>(runtime::ReportedEffectState::emulated) == kReportedState.max,
              "ReportedEffectState's last");
static_assert(static_cast<int>(PlayEnd::finished) == kPlayEnd.max, "PlayEnd's last");
static_assert(static_cast<int>(ReportId::effect_states) == kAnsweredIds.max, "the highest ReportId");

constexpr uint32_t kButtonUsages[32] = {
    button(1),  button(2),  button(3),  button(4),  button(5),  button(6),  button(7),
    button(8),  button(9),  button(10), button(11), button(12), button(13), button(14),
    button(15), button(16), button(17), button(18), button(19), button(20), button(21),
    button(22), button(23), button(24), button(25), button(26), button(27), button(28),
    button(29), button(30), button(31), button(32),
};

// The full layout (JoystickLayout{}): six axes, 32 buttons, four hats, whole bytes without
// padding. A device's own layout is built by build_joystick_spec (joystick_layout.cpp).
constexpr FieldSpec kJoystickInput[] = {
    FEEL_FIELD(JoystickInputReport, position[i],
               i16(0, range::kSignedLevel).times(kMaxAxes).usages(kAxisUsages)),
    button_field(32, kButtonUsages),
    hat_field(4),
};

constexpr FieldSpec kPidState[] = {
    FEEL_FIELD(PidStateReport, device_paused, flag(pid::kDevicePaused)),
    FEEL_FIELD(PidStateReport, actuators_enabled, flag(pid::kActuatorsEnabled)),
    FEEL_FIELD(PidStateReport, safety_switch, flag(pid::kSafetySwitch)),
    FEEL_FIELD(PidStateReport, actuator_override, flag(pid::kActuatorOverrideSwitch)),
    FEEL_FIELD(PidStateReport, actuator_power, flag(pid::kActuatorPower)),
    FEEL_FIELD(PidStateReport, effect_playing, flag(pid::kEffectPlaying)),
    FEEL_FIELD(PidStateReport, block, u16(pid::kEffectBlockIndex, kBlockOrNone)),
};

bool answers_a_report(int64_t v) noexcept {
    return v == static_cast<int64_t>(kNoReportId) || (v > 0 && v <= 0xFF && find_report(static_cast<uint8_t>(v)) != nullptr);
}

constexpr FieldSpec kCommandStatus[] = {
    FEEL_FIELD(CommandStatusReport, sequence, u32(vendor::kSequence, kAnyU32)),
    FEEL_FIELD(CommandStatusReport, command,
               u8(vendor::kCommand, kAnsweredIds).only(&answers_a_report, "is not a report id (nor 0, no report)")),
    FEEL_FIELD(CommandStatusReport, block, u16(pid::kEffectBlockIndex, kBlockOrNone)),
    FEEL_FIELD(CommandStatusReport, code, u8(vendor::kErrorCode, kErrorCode)),
    FEEL_FIELD(CommandStatusReport, value, x64(vendor::kErrorValue)),
    FEEL_FIELD(CommandStatusReport, allowed_min, x64(vendor::kAllowedMin)),
    FEEL_FIELD(CommandStatusReport, allowed_max, x64(vendor::kAllowedMax)),
    FEEL_FIELD(CommandStatusReport, has_range, flag(vendor::kHasRange)),
    FEEL_FIELD(CommandStatusReport, effect_state, u8(vendor::kEffectState, kReportedState)),
    FEEL_FIELD(CommandStatusReport, iterations, u16(vendor::kIterations, kAnyU8).or_infinite()),
    FEEL_FIELD(CommandStatusReport, completed_iterations, u8(vendor::kCompletedIterations, kAnyU8)),
    FEEL_FIELD(CommandStatusReport, elapsed_us,
               u32(vendor::kElapsed, kAnyU32).in(FieldUnit::microseconds)),
    FEEL_FIELD(CommandStatusReport, last_end, u8(vendor::kLastEnd, kPlayEnd)),
};

constexpr FieldSpec kCommandErrorText[] = {
    FEEL_FIELD(CommandErrorTextReport, sequence, u32(vendor::kSequence, kAnyU32)),
    FEEL_FIELD(CommandErrorTextReport, command,
               u8(vendor::kCommand, kAnsweredIds).only(&answers_a_report, "is not a report id (nor 0, no report)")),
    FEEL_FIELD(CommandErrorTextReport, part, u8(vendor::kErrorTextPart, kErrorTextPart)),
    FEEL_FIELD(CommandErrorTextReport, text[i], text(vendor::kErrorText, kErrorTextPartBytes)),
};

constexpr FieldSpec kDeviceStatus[] = {
    FEEL_FIELD(DeviceStatusReport, t_us, x64(vendor::kDeviceTime).in(FieldUnit::microseconds)),
    FEEL_FIELD(DeviceStatusReport, report_number, u32(vendor::kReportNumber, kAnyU32)),
    FEEL_FIELD(DeviceStatusReport, force[i],
               i16(vendor::kMotorForce, range::kSignedLevel).times(kMaxAxes)),
    FEEL_FIELD(DeviceStatusReport, velocity[i],
               i32(vendor::kHandleVelocity, kAnyI32).times(kMaxAxes)),
    FEEL_FIELD(DeviceStatusReport, fade_level, u16(vendor::kSafetyFade, range::kLevel)),
    FEEL_FIELD(DeviceStatusReport, safety_flags, u8(vendor::kSafetyFlags, kSafetyFlags)),
    FEEL_FIELD(DeviceStatusReport, gain, u16(pid::kDeviceGain, range::kGain)),
    FEEL_FIELD(DeviceStatusReport, loop_rate_hz, u16(vendor::kLoopRate, kAnyU16).in(FieldUnit::hertz)),
    FEEL_FIELD(DeviceStatusReport, overruns, u32(vendor::kOverruns, kAnyU32)),
    FEEL_FIELD(DeviceStatusReport, measured_rate_millihz,
               u32(vendor::kMeasuredRate, kAnyU32).in(FieldUnit::millihertz)),
};

constexpr FieldSpec kEffectStates[] = {
    FEEL_FIELD(EffectStatesReport, report_number, u32(vendor::kReportNumber, kAnyU32)),
    FEEL_FIELD(EffectStatesReport, playing_effects, u16(vendor::kPlayingEffects, kAnyU16)),
    FEEL_FIELD(EffectStatesReport, resident_effects, u16(vendor::kResidentEffects, kAnyU16)),
    FEEL_FIELD(EffectStatesReport, dropped_reports, x64(vendor::kDroppedReports)),
    FEEL_FIELD(EffectStatesReport, page, u8(vendor::kPage, kAnyU8)),
    FEEL_FIELD(EffectStatesReport, pages, u8(vendor::kPages, kPages)),
    FEEL_FIELD(EffectStatesReport, effect_count, u8(vendor::kEffectCount, kStatusEffects)),
    FEEL_FIELD(EffectStatesReport, effect_block[i],
               u16(pid::kEffectBlockIndex, kBlockOrNone).times(kEffectsPerStatusReport)),
    FEEL_FIELD(EffectStatesReport, effect_state[i],
               u8(vendor::kEffectState, kReportedState).times(kEffectsPerStatusReport)),
};

constexpr FieldSpec kDynamicReport[] = {
    FEEL_FIELD(DynamicReportReport, block, u16(pid::kEffectBlockIndex, kBlockOrNone)),
    FEEL_FIELD(DynamicReportReport, final_report, flag(vendor::kFinalReport)),
    FEEL_FIELD(DynamicReportReport, t_us, x64(vendor::kDeviceTime).in(FieldUnit::microseconds)),
    FEEL_FIELD(DynamicReportReport, axis_count, u8(vendor::kAxisCount, kAxisCountOrNone)),
    FEEL_FIELD(DynamicReportReport, first_axis, u8(vendor::kFirstAxis, kFirstAxis)),
    FEEL_FIELD(DynamicReportReport, position_centi[i],
               i32(vendor::kMassPosition, kAnyI32).times(kDynamicAxesPerReport)),
    FEEL_FIELD(DynamicReportReport, velocity_centi[i],
               i32(vendor::kMassVelocity, kAnyI32).times(kDynamicAxesPerReport)),
    FEEL_FIELD(DynamicReportReport, handle_velocity_centi[i],
               i32(vendor::kHandleVelocity, kAnyI32).times(kDynamicAxesPerReport)),
};

constexpr ReportKind kIn = ReportKind::input;

constexpr ReportSpec kInputReports[] = {
    report<JoystickInputReport>(ReportId::joystick_input, kIn, "Joystick Input", "joystick_input",
                                gd::kPointer, kJoystickInput),
    report<PidStateReport>(ReportId::pid_state, kIn, "PID State", "pid_state",
                           pid::kPidStateReport, kPidState),
    report<CommandStatusReport>(ReportId::command_status, kIn, "Command Status",
                                "command_status", vendor::kCommandStatusReport, kCommandStatus),
    report<DeviceStatusReport>(ReportId::device_status, kIn, "Device Status", "device_status",
                               vendor::kDeviceStatusReport, kDeviceStatus),
    report<DynamicReportReport>(ReportId::dynamic_report, kIn, "Dynamic Report",
                                "dynamic_report", vendor::kDynamicReportReport, kDynamicReport),
    report<CommandErrorTextReport>(ReportId::command_error_text, kIn, "Command Error Text",
                                   "command_error_text", vendor::kCommandErrorTextReport, kCommandErrorText),
    report<EffectStatesReport>(ReportId::effect_states, kIn, "Effect States", "effect_states",
                               vendor::kEffectStatesReport, kEffectStates),
};

}  // namespace

std::span<const ReportSpec> input_reports() noexcept { return kInputReports; }

}  // namespace feel::protocol::detail
