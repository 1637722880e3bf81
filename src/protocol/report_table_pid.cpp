// The HID PID 1.0 output reports (host -> device), field by field in wire order.
//
// Each report carries the fields PID 1.0 gives it, under PID's usages (page 0x0F), laid out
// the way Linux's hid-pidff (drivers/hid/usbhid/hid-pidff.c) and Windows' PID driver read
// them: named arrays 1-based, Direction a collection of Ordinals, times in milliseconds
// (hid-pidff writes evdev's milliseconds unscaled), Device Control's list first. The
// logical ranges are feel's (units.hpp) where hid-pidff rescales to them (levels, gains,
// angles) and what hid-pidff writes where it does not (times). What feel needs beyond PID
// (the command sequence, iterations, trigger kind, the axis list, the direction's form)
// rides in the same report under vendor usages, so one report still describes one effect
// block.
#include "hid_usages.hpp"
#include "joystick_layout.hpp"
#include "report_table.hpp"

namespace feel::protocol::detail {
namespace {

using namespace usage;

// Effect Type is a PID named array, whose value is 1-based (hid-pidff refuses a list whose
// Logical Minimum is not 1): value v selects kEffectTypeUsages[v - 1], the EffectType v - 1.
constexpr Range kEffectTypeIndex{1, kEffectTypeCount};
// PID times: whole milliseconds (the unit hid-pidff writes, whatever the descriptor says),
// plus a vendor field with the microseconds below the millisecond (0 from a standard host).
constexpr Range kTimeMs{0, kMaxTimeUs / 1000};
constexpr Range kSubMillisecondUs{0, 999};
// Direction: PID's angles (Ordinals 1 and 2) in hundredths of a degree, 0..36000 so that
// hid-pidff's linear rescale of evdev's 0..0xFFFF lands on whole degrees at the compass
// points; 36000 is 360°, the same as 0 (the device reads it so). feel's vectors (cartesian,
// moments) travel in a vendor field, ±10000 per component.
constexpr Range kDirectionAngle{0, 36000};
constexpr Range kDirectionForm{0, 3};  // 0 polar / spherical angles, see direction_form
constexpr Range kTriggerButtonOrNone{0, 32};  // 0 none, button 1..32, hat 1..4
constexpr Range kTriggerKind{0, 2};
constexpr Range kAxisCountOrDefault{0, kMaxAxes};  // 0: not given (standard host), see protocol.md
constexpr Range kOffsetMode{0, 1};
constexpr Range kCustomOffset{0, 65534};
constexpr Range kDataCount{1, kSamplesPerDataReport};
constexpr Range kLoopCount{0, 255};  // or kLoopInfinite (the 16-bit null)

constexpr uint32_t kOperationUsages[] = {pid::kOpEffectStart, pid::kOpEffectStartSolo,
                                         pid::kOpEffectStop};
constexpr uint32_t kDeviceControlUsages[] = {pid::kDcEnableActuators, pid::kDcDisableActuators,
                                             pid::kDcStopAllEffects,  pid::kDcDeviceReset,
                                             pid::kDcDevicePause,     pid::kDcDeviceContinue};

#define SEQUENCE(R) FEEL_FIELD(R, sequence, u32(vendor::kSequence, kAnyU32))
#define BLOCK(R) FEEL_FIELD(R, block, u16(pid::kEffectBlockIndex, kBlock))

constexpr const char* kPastMaxTime = "makes the time (ms x 1000 + us) longer than 65000000 us";

// A time member in microseconds as two wire fields: PID's milliseconds and feel's
// microseconds below the millisecond. decode() sets the milliseconds first.
#define TIME_MS(R, member, name, usage)                                                   \
    FEEL_MAPPED(R, name, u16(usage, kTimeMs).in(FieldUnit::milliseconds),               \
                [](const R& r, int) noexcept -> int64_t { return time_ms(r.member); },  \
                [](R& r, int, int64_t v) noexcept {                                     \
                    r.member = static_cast<uint32_t>(v * 1000);                         \
                    return true;                                                        \
                })
#define TIME_FINE(R, member, name, usage)                                                 \
    FEEL_MAPPED(R, name, u16(usage, kSubMillisecondUs).in(FieldUnit::microseconds).refusing(kPastMaxTime), \
                [](const R& r, int) noexcept -> int64_t { return r.member % 1000; },    \
                [](R& r, int, int64_t v) noexcept {                                     \
                    r.member += static_cast<uint32_t>(v);                               \
                    return r.member <= kMaxTimeUs;                                      \
                })

// A time's milliseconds; past 65 s a value out of range, so that encode() refuses it.
constexpr int64_t time_ms(uint32_t us) noexcept {
    return us > kMaxTimeUs ? kTimeMs.max + 1 : static_cast<int64_t>(us / 1000);
}

// Duration may be infinite: PID's null (0xFFFF), whose fine part is 0. (Linux's evdev
// says "infinite" with 0 and hid-pidff forwards it unchanged: 0 ms with 0 µs decodes as
// duration_us 0, which the device reads as infinite; report_translation.cpp.)
constexpr int64_t duration_ms(const SetEffectReport& r, int) noexcept {
    return r.duration_us == kWireInfinite ? 0xFFFF : time_ms(r.duration_us);
}
constexpr bool set_duration_ms(SetEffectReport& r, int, int64_t v) noexcept {
    r.duration_us = v == 0xFFFF ? kWireInfinite : static_cast<uint32_t>(v * 1000);
    return true;
}
constexpr int64_t duration_fine(const SetEffectReport& r, int) noexcept {
    return r.duration_us == kWireInfinite ? 0 : r.duration_us % 1000;
}
constexpr bool set_duration_fine(SetEffectReport& r, int, int64_t v) noexcept {
    if (r.duration_us == kWireInfinite) return v == 0;
    r.duration_us += static_cast<uint32_t>(v);
    return r.duration_us <= kMaxTimeUs;
}

// Direction Enable (PID 0x56) says the effect has a direction; direction_form (vendor)
// says which: 0 polar (or none given: what a standard host means), 1 cartesian,
// 2 spherical, 3 moments. The form is read only when Direction Enable is 1.
constexpr bool has_angles(DirectionKind k) noexcept {
    return k == DirectionKind::polar || k == DirectionKind::spherical;
}
constexpr bool has_vector(DirectionKind k) noexcept {
    return k == DirectionKind::cartesian || k == DirectionKind::moments;
}
// Axes Enable: one bit per axis, X..Rz.
constexpr int64_t axis_enabled(const SetEffectReport& r, int i) noexcept { return (r.axes_enable >> i) & 1u; }
constexpr bool set_axis_enabled(SetEffectReport& r, int i, int64_t v) noexcept {
    const auto bit = static_cast<uint8_t>(1u << i);
    r.axes_enable = static_cast<uint8_t>(v != 0 ? (r.axes_enable | bit) : (r.axes_enable & ~bit));
    return true;
}
constexpr int64_t direction_enable(const SetEffectReport& r, int) noexcept {
    return r.direction_kind == DirectionKind::none ? 0 : 1;
}
constexpr bool set_direction_enable(SetEffectReport& r, int, int64_t v) noexcept {
    r.direction_kind = v != 0 ? DirectionKind::polar : DirectionKind::none;
    return true;
}
constexpr int64_t direction_form(const SetEffectReport& r, int) noexcept {
    return r.direction_kind == DirectionKind::none ? 0 : static_cast<int64_t>(r.direction_kind) - 1;
}
constexpr bool set_direction_form(SetEffectReport& r, int, int64_t v) noexcept {
    if (r.direction_kind == DirectionKind::none) return v == 0;
    r.direction_kind = static_cast<DirectionKind>(v + 1);
    return true;
}
constexpr int64_t direction_angle(const SetEffectReport& r, int i) noexcept {
    if (r.direction_kind == DirectionKind::polar && i > 0) return 0;
    return has_angles(r.direction_kind) ? r.direction[i] : 0;
}
// Slots the form does not use must be 0 (decode loses nothing). An angle of 36000 (360°,
// hid-pidff's rescale of evdev's 0xFFFF) is kept; the device reads it as 0.
constexpr bool set_direction_angle(SetEffectReport& r, int i, int64_t v) noexcept {
    if (r.direction_kind == DirectionKind::polar && i > 0) return v == 0;
    if (!has_angles(r.direction_kind)) return v == 0;
    r.direction[i] = static_cast<int32_t>(v);
    return true;
}
constexpr int64_t direction_vector(const SetEffectReport& r, int i) noexcept {
    return has_vector(r.direction_kind) ? r.direction[i] : 0;
}
constexpr bool set_direction_vector(SetEffectReport& r, int i, int64_t v) noexcept {
    if (!has_vector(r.direction_kind)) return v == 0;
    r.direction[i] = static_cast<int32_t>(v);
    return true;
}


constexpr FieldSpec kSetEffect[] = {
    SEQUENCE(SetEffectReport),
    BLOCK(SetEffectReport),
    FEEL_MAPPED(SetEffectReport, "type",
                u8(0, kEffectTypeIndex).selects(pid::kEffectType, kEffectTypeUsages),
                [](const SetEffectReport& r, int) noexcept -> int64_t { return static_cast<int64_t>(r.type) + 1; },
                [](SetEffectReport& r, int, int64_t v) noexcept {
                    r.type = static_cast<EffectType>(v - 1);
                    return true;
                }),
    FEEL_MAPPED(SetEffectReport, "duration_ms",
                u16(pid::kDuration, kTimeMs).in(FieldUnit::milliseconds).or_infinite(),
                duration_ms, set_duration_ms),
    FEEL_MAPPED(SetEffectReport, "duration_fine_us",
                u16(vendor::kDurationFine, kSubMillisecondUs)
                    .in(FieldUnit::microseconds)
                    .refusing("must be 0 when the duration is infinite, and makes the time at most 65000000 us"),
                duration_fine, set_duration_fine),
    TIME_MS(SetEffectReport, trigger_repeat_interval_us, "trigger_repeat_interval_ms",
            pid::kTriggerRepeatInterval),
    TIME_FINE(SetEffectReport, trigger_repeat_interval_us, "trigger_repeat_interval_fine_us",
              vendor::kRepeatIntervalFine),
    TIME_MS(SetEffectReport, start_delay_us, "start_delay_ms", pid::kStartDelay),
    TIME_FINE(SetEffectReport, start_delay_us, "start_delay_fine_us", vendor::kStartDelayFine),
    FEEL_FIELD(SetEffectReport, gain, u16(pid::kGain, range::kGain)),
    FEEL_FIELD(SetEffectReport, trigger_index, u16(pid::kTriggerButton, kTriggerButtonOrNone)),
    FEEL_FIELD(SetEffectReport, trigger_kind, u8(vendor::kTriggerKind, kTriggerKind)),
    // PID's Axes Enable: a Logical collection of one-bit flags named by the axes' usages
    // (PID 1.0's Set Effect; newer hid-pidff, from 2025, finds the axes there), padded to a
    // byte.
    FEEL_MAPPED(SetEffectReport, "axes_enable[i]",
                field(0, 1, kBinary).times(kMaxAxes).usages(kAxisUsages).wrapped_in(pid::kAxesEnable),
                axis_enabled, set_axis_enabled),
    padding_field(8 - kMaxAxes),
    FEEL_MAPPED(SetEffectReport, "direction_enable", flag(pid::kDirectionEnable), direction_enable,
                set_direction_enable),
    FEEL_MAPPED(SetEffectReport, "direction_form",
                u8(vendor::kDirectionKind, kDirectionForm).refusing("must be 0 when Direction Enable is 0"),
                direction_form, set_direction_form),
    FEEL_MAPPED(SetEffectReport, "direction_angle[i]",
                u16(0, kDirectionAngle)
                    .times(2)
                    .usages(kDirectionOrdinals)
                    .wrapped_in(pid::kDirection)
                    .in(FieldUnit::centidegrees)
                    .refusing("must be 0: the direction's form does not use this angle"),
                direction_angle, set_direction_angle),
    FEEL_MAPPED(SetEffectReport, "direction_vector[i]",
                i16(vendor::kDirectionVector, range::kCartesianComponent)
                    .times(3)
                    .refusing("must be 0: only cartesian and moment directions have a vector"),
                direction_vector, set_direction_vector),
    // 1..255 or kLoopInfinite; 0 is "not given" (a standard host never writes feel's vendor
    // fields): the device plays it once, as a PID effect plays once per start.
    FEEL_FIELD(SetEffectReport, iterations, u16(vendor::kIterations, kLoopCount).or_infinite()),
    FEEL_FIELD(SetEffectReport, axis_count, u8(vendor::kAxisCount, kAxisCountOrDefault)),
    FEEL_FIELD(SetEffectReport, axes[i], u8(vendor::kEffectAxis, kAxisIndex).times(kMaxAxes)),
    FEEL_MAPPED(SetEffectReport, "no_envelope", flag(vendor::kNoEnvelope),
                [](const SetEffectReport& r, int) noexcept -> int64_t { return r.has_envelope ? 0 : 1; },
                [](SetEffectReport& r, int, int64_t v) noexcept {
                    r.has_envelope = v == 0;
                    return true;
                }),
};

constexpr FieldSpec kSetEnvelope[] = {
    SEQUENCE(SetEnvelopeReport),
    BLOCK(SetEnvelopeReport),
    FEEL_FIELD(SetEnvelopeReport, impulse_level, u16(pid::kAttackLevel, range::kLevel)),
    TIME_MS(SetEnvelopeReport, settle_time_us, "settle_time_ms", pid::kAttackTime),
    TIME_FINE(SetEnvelopeReport, settle_time_us, "settle_time_fine_us", vendor::kAttackTimeFine),
    FEEL_FIELD(SetEnvelopeReport, fade_level, u16(pid::kFadeLevel, range::kLevel)),
    TIME_MS(SetEnvelopeReport, fade_time_us, "fade_time_ms", pid::kFadeTime),
    TIME_FINE(SetEnvelopeReport, fade_time_us, "fade_time_fine_us", vendor::kFadeTimeFine),
};

constexpr FieldSpec kSetCondition[] = {
    SEQUENCE(SetConditionReport),
    BLOCK(SetConditionReport),
    FEEL_FIELD(SetConditionReport, axis_index, u8(pid::kParameterBlockOffset, kAxisIndex)),
    FEEL_FIELD(SetConditionReport, center_offset, i16(pid::kCpOffset, range::kSignedLevel)),
    FEEL_FIELD(SetConditionReport, pos_coefficient, i16(pid::kPositiveCoefficient, range::kSignedLevel)),
    FEEL_FIELD(SetConditionReport, neg_coefficient, i16(pid::kNegativeCoefficient, range::kSignedLevel)),
    FEEL_FIELD(SetConditionReport, pos_saturation, u16(pid::kPositiveSaturation, range::kLevel)),
    FEEL_FIELD(SetConditionReport, neg_saturation, u16(pid::kNegativeSaturation, range::kLevel)),
    FEEL_FIELD(SetConditionReport, deadband, u16(pid::kDeadBand, range::kLevel)),
    FEEL_FIELD(SetConditionReport, offset_mode, u8(vendor::kOffsetMode, kOffsetMode)),
};

constexpr FieldSpec kSetPeriodic[] = {
    SEQUENCE(SetPeriodicReport),
    BLOCK(SetPeriodicReport),
    FEEL_FIELD(SetPeriodicReport, magnitude, i16(pid::kMagnitude, range::kSignedLevel)),
    FEEL_FIELD(SetPeriodicReport, offset, i16(pid::kOffset, range::kSignedLevel)),
    // 0..36000 like Direction (hid-pidff rescales evdev's 0..0xFFFF phase to it); the
    // device reads 36000 (360°) as 0.
    FEEL_FIELD(SetPeriodicReport, phase, u16(pid::kPhase, kDirectionAngle).in(FieldUnit::centidegrees)),
    TIME_MS(SetPeriodicReport, period_us, "period_ms", pid::kPeriod),
    TIME_FINE(SetPeriodicReport, period_us, "period_fine_us", vendor::kPeriodFine),
};

constexpr FieldSpec kSetConstantForce[] = {
    SEQUENCE(SetConstantForceReport),
    BLOCK(SetConstantForceReport),
    FEEL_FIELD(SetConstantForceReport, magnitude, i16(pid::kMagnitude, range::kSignedLevel)),
};

constexpr FieldSpec kSetRampForce[] = {
    SEQUENCE(SetRampForceReport),
    BLOCK(SetRampForceReport),
    FEEL_FIELD(SetRampForceReport, start, i16(pid::kRampStart, range::kSignedLevel)),
    FEEL_FIELD(SetRampForceReport, end, i16(pid::kRampEnd, range::kSignedLevel)),
};

constexpr FieldSpec kSetCustomForce[] = {
    SEQUENCE(SetCustomForceReport),
    BLOCK(SetCustomForceReport),
    FEEL_FIELD(SetCustomForceReport, channels, u8(vendor::kChannels, range::kChannels)),
    FEEL_FIELD(SetCustomForceReport, sample_period_us,
               u32(pid::kSamplePeriod, range::kPeriodUs).in(FieldUnit::microseconds)),
    FEEL_FIELD(SetCustomForceReport, sample_count, u16(pid::kSampleCount, range::kSampleCount)),
};

constexpr FieldSpec kCustomForceData[] = {
    SEQUENCE(CustomForceDataReport),
    BLOCK(CustomForceDataReport),
    FEEL_FIELD(CustomForceDataReport, offset, u16(pid::kCustomForceDataOffset, kCustomOffset)),
    FEEL_FIELD(CustomForceDataReport, count, u8(vendor::kDataCount, kDataCount)),
    FEEL_FIELD(CustomForceDataReport, samples[i],
               i16(pid::kCustomForceData, range::kSample).times(kSamplesPerDataReport)),
};

constexpr FieldSpec kDownloadForceSample[] = {
    SEQUENCE(DownloadForceSampleReport),
    FEEL_FIELD(DownloadForceSampleReport, axis_count, u8(vendor::kAxisCount, range::kAxisCount)),
    FEEL_FIELD(DownloadForceSampleReport, force[i],
               i16(0, range::kSignedLevel).times(kMaxAxes).usages(kAxisUsages)),
};

constexpr FieldSpec kEffectOperation[] = {
    SEQUENCE(EffectOperationReport),
    BLOCK(EffectOperationReport),
    FEEL_FIELD(EffectOperationReport, operation,
               u8(0, Range{1, 3}).selects(pid::kEffectOperation, kOperationUsages)),
    FEEL_FIELD(EffectOperationReport, loop_count, u16(pid::kLoopCount, kLoopCount).or_infinite()),
};

constexpr FieldSpec kBlockFree[] = {
    SEQUENCE(BlockFreeReport),
    BLOCK(BlockFreeReport),
};

// The list first: hid-pidff finds this report by its first field's Logical collection,
// which must be PID Device Control (0x96), not the report's 0x95.
constexpr FieldSpec kDeviceControl[] = {
    FEEL_FIELD(DeviceControlReport, control,
               u8(0, Range{1, 6}).selects(pid::kPidDeviceControl, kDeviceControlUsages)),
    SEQUENCE(DeviceControlReport),
};

constexpr FieldSpec kDeviceGain[] = {
    SEQUENCE(DeviceGainReport),
    FEEL_FIELD(DeviceGainReport, gain, u16(pid::kDeviceGain, range::kGain)),
};

#undef SEQUENCE
#undef BLOCK
#undef TIME_MS
#undef TIME_FINE

constexpr ReportKind kOut = ReportKind::output;

constexpr ReportSpec kPidReports[] = {
    report<SetEffectReport>(ReportId::set_effect, kOut, "Set Effect", "set_effect",
                            pid::kSetEffectReport, kSetEffect),
    report<SetEnvelopeReport>(ReportId::set_envelope, kOut, "Set Envelope", "set_envelope",
                              pid::kSetEnvelopeReport, kSetEnvelope),
    report<SetConditionReport>(ReportId::set_condition, kOut, "Set Condition", "set_condition",
                               pid::kSetConditionReport, kSetCondition),
    report<SetPeriodicReport>(ReportId::set_periodic, kOut, "Set Periodic", "set_periodic",
                              pid::kSetPeriodicReport, kSetPeriodic),
    report<SetConstantForceReport>(ReportId::set_constant_force, kOut, "Set Constant Force",
                                   "set_constant_force", pid::kSetConstantForceReport,
                                   kSetConstantForce),
    report<SetRampForceReport>(ReportId::set_ramp_force, kOut, "Set Ramp Force", "set_ramp_force",
                               pid::kSetRampForceReport, kSetRampForce),
    report<SetCustomForceReport>(ReportId::set_custom_force, kOut, "Set Custom Force",
                                 "set_custom_force", pid::kSetCustomForceReport, kSetCustomForce),
    report<CustomForceDataReport>(ReportId::custom_force_data, kOut, "Custom Force Data",
                                  "custom_force_data", pid::kCustomForceDataReport,
                                  kCustomForceData),
    report<DownloadForceSampleReport>(ReportId::download_force_sample, kOut,
                                      "Download Force Sample", "download_force_sample",
                                      pid::kDownloadForceSample, kDownloadForceSample),
    report<EffectOperationReport>(ReportId::effect_operation, kOut, "Effect Operation",
                                  "effect_operation", pid::kEffectOperationReport,
                                  kEffectOperation),
    report<BlockFreeReport>(ReportId::block_free, kOut, "PID Block Free", "block_free",
                            pid::kPidBlockFreeReport, kBlockFree),
    report<DeviceControlReport>(ReportId::device_control, kOut, "PID Device Control",
                                "device_control", pid::kPidDeviceControlReport, kDeviceControl),
    report<DeviceGainReport>(ReportId::device_gain, kOut, "Device Gain", "device_gain",
                             pid::kDeviceGainReport, kDeviceGain),
};

}  // namespace

std::span<const ReportSpec> pid_output_reports() noexcept { return kPidReports; }

}  // namespace feel::protocol::detail
