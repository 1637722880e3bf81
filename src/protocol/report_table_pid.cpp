// The HID PID 1.0 output reports (host -> device), field by field in wire order.
//
// Each report carries the fields PID 1.0 gives it, under PID's usages (page 0x0F), with
// feel's units and ranges (units.hpp) as the logical range. What feel needs beyond PID
// (the command sequence, iterations, trigger kind, the axis list, the direction's form)
// rides in the same report under vendor usages, so one report still describes one effect
// block.
#include "hid_usages.hpp"
#include "report_table.hpp"

namespace feel::protocol::detail {
namespace {

using namespace usage;

constexpr Range kEffectTypeRange{0, kEffectTypeCount - 1};
// Set Effect's direction slots: polar and spherical angles 0..35999, cartesian and
// moment components ±10000 (feel::Direction; the engine checks each form's own range).
constexpr Range kDirectionValue{-kFullScale, 35999};
constexpr Range kTriggerIndex{0, 32};  // 0 none, button 1..32, hat 1..4
constexpr Range kTriggerKind{0, 2};
constexpr Range kDirectionKind{0, 4};
constexpr Range kOffsetMode{0, 1};
constexpr Range kCustomOffset{0, 65534};
constexpr Range kDataCount{1, kSamplesPerDataReport};

constexpr uint32_t kOperationUsages[] = {pid::kOpEffectStart, pid::kOpEffectStartSolo,
                                         pid::kOpEffectStop};
constexpr uint32_t kDeviceControlUsages[] = {pid::kDcEnableActuators, pid::kDcDisableActuators,
                                             pid::kDcStopAllEffects,  pid::kDcDeviceReset,
                                             pid::kDcDevicePause,     pid::kDcDeviceContinue};

#define SEQUENCE(R) FEEL_FIELD(R, sequence, u32(vendor::kSequence, kAnyU32))
#define BLOCK(R) FEEL_FIELD(R, block, u16(pid::kEffectBlockIndex, kBlock))

constexpr FieldSpec kSetEffect[] = {
    SEQUENCE(SetEffectReport),
    BLOCK(SetEffectReport),
    FEEL_FIELD(SetEffectReport, type,
               u8(0, kEffectTypeRange).selects(pid::kEffectType, kEffectTypeUsages)),
    FEEL_FIELD(SetEffectReport, duration_us,
               u32(pid::kDuration, range::kDurationUs).in(FieldUnit::microseconds).or_infinite()),
    FEEL_FIELD(SetEffectReport, start_delay_us,
               u32(pid::kStartDelay, range::kDelayUs).in(FieldUnit::microseconds)),
    FEEL_FIELD(SetEffectReport, trigger_repeat_interval_us,
               u32(pid::kTriggerRepeatInterval, range::kRepeatIntervalUs).in(FieldUnit::microseconds)),
    FEEL_FIELD(SetEffectReport, gain, u16(pid::kGain, range::kGain)),
    FEEL_FIELD(SetEffectReport, iterations, u8(vendor::kIterations, range::kIterations)),
    FEEL_FIELD(SetEffectReport, trigger_kind, u8(vendor::kTriggerKind, kTriggerKind)),
    FEEL_FIELD(SetEffectReport, trigger_index, u8(pid::kTriggerButton, kTriggerIndex)),
    FEEL_FIELD(SetEffectReport, axis_count, u8(pid::kAxesEnable, range::kAxisCount)),
    FEEL_FIELD(SetEffectReport, axes[i], u8(vendor::kEffectAxis, kAxisIndex).times(kMaxAxes)),
    FEEL_FIELD(SetEffectReport, direction_kind, u8(vendor::kDirectionKind, kDirectionKind)),
    FEEL_FIELD(SetEffectReport, direction[i], i32(pid::kDirection, kDirectionValue).times(3)),
    FEEL_FIELD(SetEffectReport, has_envelope, flag(vendor::kHasEnvelope)),
};

constexpr FieldSpec kSetEnvelope[] = {
    SEQUENCE(SetEnvelopeReport),
    BLOCK(SetEnvelopeReport),
    FEEL_FIELD(SetEnvelopeReport, impulse_level, u16(pid::kAttackLevel, range::kLevel)),
    FEEL_FIELD(SetEnvelopeReport, settle_time_us,
               u32(pid::kAttackTime, range::kDelayUs).in(FieldUnit::microseconds)),
    FEEL_FIELD(SetEnvelopeReport, fade_level, u16(pid::kFadeLevel, range::kLevel)),
    FEEL_FIELD(SetEnvelopeReport, fade_time_us,
               u32(pid::kFadeTime, range::kDelayUs).in(FieldUnit::microseconds)),
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
    FEEL_FIELD(SetPeriodicReport, phase, u16(pid::kPhase, range::kAngle).in(FieldUnit::centidegrees)),
    FEEL_FIELD(SetPeriodicReport, period_us,
               u32(pid::kPeriod, range::kPeriodUs).in(FieldUnit::microseconds)),
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
    FEEL_FIELD(EffectOperationReport, loop_count, u8(pid::kLoopCount, kAnyU8)),
};

constexpr FieldSpec kBlockFree[] = {
    SEQUENCE(BlockFreeReport),
    BLOCK(BlockFreeReport),
};

constexpr FieldSpec kDeviceControl[] = {
    SEQUENCE(DeviceControlReport),
    FEEL_FIELD(DeviceControlReport, control,
               u8(0, Range{1, 6}).selects(pid::kPidDeviceControl, kDeviceControlUsages)),
};

constexpr FieldSpec kDeviceGain[] = {
    SEQUENCE(DeviceGainReport),
    FEEL_FIELD(DeviceGainReport, gain, u16(pid::kDeviceGain, range::kGain)),
};

#undef SEQUENCE
#undef BLOCK

constexpr ReportKind kOut = ReportKind::output;

constexpr ReportSpec kReports[] = {
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

std::span<const ReportSpec> pid_output_reports() noexcept { return kReports; }

}  // namespace feel::protocol::detail
