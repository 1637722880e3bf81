// The feature reports: Create New Effect (set), PID Block Load and PID Pool (get), and
// feel's Device Info (get).
#include "feel/sim/device_profile.hpp"
#include "hid_usages.hpp"
#include "report_table.hpp"

namespace feel::protocol::detail {
namespace {

using namespace usage;

// Effect Type: a 1-based PID named array (report_table_pid.cpp): v selects EffectType v - 1.
constexpr Range kNewEffectTypeIndex{1, kEffectTypeCount};
constexpr Range kBlockLoadStatus{1, 3};
constexpr Range kDeviceClass{1, 2};  // sim::DeviceClass: 1 I-FORCE 1.x, 2 I-FORCE 2.0
static_assert(static_cast<int>(sim::DeviceClass::iforce1) == kDeviceClass.min, "DeviceClass's first");
static_assert(static_cast<int>(sim::DeviceClass::iforce2) == kDeviceClass.max, "DeviceClass's last");
constexpr Range kPhysical{0, INT32_MAX};         // 0 for an axis the device lacks
constexpr Range kSensorCounts{0, 1 << 24};       // 0 for an axis the device lacks
constexpr Range kButtonCount{0, 32};
constexpr Range kHatCount{0, 4};

constexpr uint32_t kBlockLoadUsages[] = {pid::kBlockLoadSuccess, pid::kBlockLoadFull,
                                         pid::kBlockLoadError};

constexpr FieldSpec kCreateNewEffect[] = {
    FEEL_FIELD(CreateNewEffectReport, sequence, u32(vendor::kSequence, kAnyU32)),
    FEEL_MAPPED(CreateNewEffectReport, "type",
                u8(0, kNewEffectTypeIndex).selects(pid::kEffectType, kEffectTypeUsages),
                [](const CreateNewEffectReport& r, int) noexcept -> int64_t {
                    return static_cast<int64_t>(r.type) + 1;
                },
                [](CreateNewEffectReport& r, int, int64_t v) noexcept {
                    r.type = static_cast<EffectType>(v - 1);
                    return true;
                }),
    // PID 1.0 declares the parameter block's size with Generic Desktop's Byte Count; feel
    // counts force-profile samples in it (the device knows a sample's size).
    FEEL_FIELD(CreateNewEffectReport, sample_count, u16(gd::kByteCount, kAnyU16)),
};

constexpr FieldSpec kBlockLoad[] = {
    // 1..65535, or 0 (the null) when no block was allocated. Logical Minimum 1 matters:
    // hid-pidff takes it as the first block and max_effects = max - min + 1.
    FEEL_FIELD(BlockLoadReport, block, u16(pid::kEffectBlockIndex, kBlock).or_none()),
    FEEL_FIELD(BlockLoadReport, status,
               u8(0, kBlockLoadStatus).selects(pid::kBlockLoadStatus, kBlockLoadUsages)),
    FEEL_FIELD(BlockLoadReport, ram_pool_available, u32(pid::kRamPoolAvailable, kAnyU32)),
};

constexpr FieldSpec kPidPool[] = {
    FEEL_FIELD(PidPoolReport, ram_pool_size, u32(pid::kRamPoolSize, kAnyU32)),
    FEEL_FIELD(PidPoolReport, simultaneous_effects_max, u16(pid::kSimultaneousEffectsMax, kAnyU16)),
    FEEL_FIELD(PidPoolReport, device_managed_pool, flag(pid::kDeviceManagedPool)),
    FEEL_FIELD(PidPoolReport, shared_parameter_blocks, flag(pid::kSharedParameterBlocks)),
    FEEL_FIELD(PidPoolReport, ram_pool_available, u32(pid::kRamPoolAvailable, kAnyU32)),
    FEEL_FIELD(PidPoolReport, free_effects, u16(vendor::kFreeEffects, kAnyU16)),
    FEEL_FIELD(PidPoolReport, sample_memory, u32(vendor::kSampleMemory, kAnyU32)),
    FEEL_FIELD(PidPoolReport, free_samples, u32(vendor::kFreeSamples, kAnyU32)),
};

// The six AxisInfo entries travel field by field (all six axis ids, then all six rotary
// flags, ...), so that each is one HID field of six elements.
constexpr FieldSpec kDeviceInfo[] = {
    FEEL_FIELD(DeviceInfoReport, device[i], text(vendor::kDeviceName, kNameBytes)),
    FEEL_FIELD(DeviceInfoReport, description[i], text(vendor::kDescription, 192)),
    FEEL_FIELD(DeviceInfoReport, device_class, u8(vendor::kDeviceClass, kDeviceClass)),
    FEEL_FIELD(DeviceInfoReport, axis_count, u8(vendor::kAxisCount, range::kAxisCount)),
    FEEL_FIELD(DeviceInfoReport, axes[i].axis, u8(vendor::kAxisId, kAxisIndex).times(kMaxAxes)),
    FEEL_FIELD(DeviceInfoReport, axes[i].rotary, u8(vendor::kAxisRotary, Range{0, 1}).times(kMaxAxes)),
    FEEL_FIELD(DeviceInfoReport, axes[i].half_travel_micro,
               u32(vendor::kHalfTravel, kPhysical).times(kMaxAxes)),
    FEEL_FIELD(DeviceInfoReport, axes[i].max_force_milli,
               u32(vendor::kMaxForceMilli, kPhysical).times(kMaxAxes)),
    FEEL_FIELD(DeviceInfoReport, axes[i].sensor_counts,
               u32(vendor::kSensorCounts, kSensorCounts).times(kMaxAxes)),
    FEEL_FIELD(DeviceInfoReport, button_count, u8(vendor::kButtonCount, kButtonCount)),
    FEEL_FIELD(DeviceInfoReport, hat_count, u8(vendor::kHatCount, kHatCount)),
    FEEL_FIELD(DeviceInfoReport, dead_man_switch, flag(vendor::kDeadManSwitch)),
    FEEL_FIELD(DeviceInfoReport, max_force, u16(vendor::kMaxForce, range::kLevel)),
    FEEL_FIELD(DeviceInfoReport, supported_types, x64(vendor::kSupportedTypes)),
    FEEL_FIELD(DeviceInfoReport, effect_slots, u16(vendor::kEffectSlots, kAnyU16)),
    FEEL_FIELD(DeviceInfoReport, pool_bytes, u32(vendor::kPoolBytes, kAnyU32)),
    FEEL_FIELD(DeviceInfoReport, sample_memory, u32(vendor::kSampleMemory, kAnyU32)),
    FEEL_FIELD(DeviceInfoReport, local_reflexes, flag(vendor::kLocalReflexes)),
    FEEL_FIELD(DeviceInfoReport, interim_reports, flag(vendor::kInterimReports)),
    FEEL_FIELD(DeviceInfoReport, loop_rate_hz, u16(vendor::kLoopRate, kAnyU16).in(FieldUnit::hertz)),
    FEEL_FIELD(DeviceInfoReport, max_loop_rate_hz,
               u16(vendor::kMaxLoopRate, kAnyU16).in(FieldUnit::hertz)),
    FEEL_FIELD(DeviceInfoReport, interim_report_centihz,
               u16(vendor::kInterimReportRate, kAnyU16).in(FieldUnit::centihertz)),
    FEEL_FIELD(DeviceInfoReport, report_rate_hz, u16(vendor::kReportRate, kAnyU16).in(FieldUnit::hertz)),
    FEEL_FIELD(DeviceInfoReport, firmware_version[i], text(vendor::kFirmwareVersion, kNameBytes)),
    FEEL_FIELD(DeviceInfoReport, vendor_revision, u8(vendor::kVendorRevision, kAnyU8)),
};

constexpr ReportKind kFeature = ReportKind::feature;

constexpr ReportSpec kFeatureReports[] = {
    report<CreateNewEffectReport>(ReportId::create_new_effect, kFeature, "Create New Effect",
                                  "create_new_effect", pid::kCreateNewEffectReport,
                                  kCreateNewEffect),
    report<BlockLoadReport>(ReportId::block_load, kFeature, "PID Block Load", "block_load",
                            pid::kPidBlockLoadReport, kBlockLoad),
    report<PidPoolReport>(ReportId::pid_pool, kFeature, "PID Pool", "pid_pool",
                          pid::kPidPoolReport, kPidPool),
    report<DeviceInfoReport>(ReportId::device_info, kFeature, "Device Info", "device_info",
                             vendor::kDeviceInfoReport, kDeviceInfo),
};

}  // namespace

std::span<const ReportSpec> feature_reports() noexcept { return kFeatureReports; }

}  // namespace feel::protocol::detail
