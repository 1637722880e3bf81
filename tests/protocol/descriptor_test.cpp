// feel's report descriptor read back by the independent parser (descriptor_parser.hpp) and
// checked against independent truths: the report sizes encode() produces, the usage
// numbers of the USB HID PID 1.0 specification, and feel's ranges in units.hpp.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <stdexcept>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "feel/transport/transport.hpp"
#include "feel/units.hpp"
#include "sample_reports.hpp"

namespace feel::protocol {
namespace {

using hid::DescriptorField;
using hid::DescriptorReport;
using hid::MainItemKind;

// Usage IDs from "Device Class Definition for Physical Interface Devices (PID)" 1.0
// (USB-IF, 1999), §5 usage table, usage page 0x0F. Written out here as the standard's
// numbers, independently of src/protocol/hid_usages.hpp.
constexpr uint32_t pid(uint16_t id) { return 0x000F0000u | id; }
constexpr uint32_t gd(uint16_t id) { return 0x00010000u | id; }  // HID Usage Tables: Generic Desktop
constexpr uint32_t kPidSetEffectReport = pid(0x21), kPidEffectBlockIndex = pid(0x22),
                   kPidParameterBlockOffset = pid(0x23), kPidEffectType = pid(0x25),
                   kPidDuration = pid(0x50), kPidSamplePeriod = pid(0x51), kPidGain = pid(0x52),
                   kPidTriggerButton = pid(0x53), kPidTriggerRepeatInterval = pid(0x54),
                   kPidDirectionEnable = pid(0x56), kPidDirection = pid(0x57),
                   kPidSetEnvelopeReport = pid(0x5A), kPidAttackLevel = pid(0x5B),
                   kPidAttackTime = pid(0x5C), kPidFadeLevel = pid(0x5D), kPidFadeTime = pid(0x5E),
                   kPidSetConditionReport = pid(0x5F), kPidCpOffset = pid(0x60),
                   kPidPositiveCoefficient = pid(0x61), kPidNegativeCoefficient = pid(0x62),
                   kPidPositiveSaturation = pid(0x63), kPidNegativeSaturation = pid(0x64),
                   kPidDeadBand = pid(0x65), kPidDownloadForceSample = pid(0x66),
                   kPidCustomForceDataReport = pid(0x68), kPidCustomForceData = pid(0x69),
                   kPidSetCustomForceReport = pid(0x6B), kPidCustomForceDataOffset = pid(0x6C),
                   kPidSampleCount = pid(0x6D), kPidSetPeriodicReport = pid(0x6E),
                   kPidOffset = pid(0x6F), kPidMagnitude = pid(0x70), kPidPhase = pid(0x71),
                   kPidPeriod = pid(0x72), kPidSetConstantForceReport = pid(0x73),
                   kPidSetRampForceReport = pid(0x74), kPidRampStart = pid(0x75),
                   kPidRampEnd = pid(0x76), kPidEffectOperationReport = pid(0x77),
                   kPidEffectOperation = pid(0x78), kPidLoopCount = pid(0x7C),
                   kPidDeviceGainReport = pid(0x7D), kPidDeviceGain = pid(0x7E),
                   kPidPoolReport = pid(0x7F), kPidRamPoolSize = pid(0x80),
                   kPidSimultaneousEffectsMax = pid(0x83), kPidBlockLoadReport = pid(0x89),
                   kPidBlockLoadStatus = pid(0x8B), kPidBlockFreeReport = pid(0x90),
                   kPidStateReport = pid(0x92), kPidEffectPlaying = pid(0x94),
                   kPidDeviceControlReport = pid(0x95), kPidDeviceControl = pid(0x96),
                   kPidDevicePaused = pid(0x9F), kPidActuatorsEnabled = pid(0xA0),
                   kPidSafetySwitch = pid(0xA4), kPidActuatorOverrideSwitch = pid(0xA5),
                   kPidActuatorPower = pid(0xA6), kPidStartDelay = pid(0xA7),
                   kPidDeviceManagedPool = pid(0xA9), kPidSharedParameterBlocks = pid(0xAA),
                   kPidCreateNewEffectReport = pid(0xAB), kPidRamPoolAvailable = pid(0xAC);

// HID 1.11 units: SI Linear seconds, English Rotation degrees (§6.2.2.7).
constexpr uint32_t kUnitSeconds = 0x1001;
constexpr uint32_t kUnitDegrees = 0x0014;

const hid::ParsedDescriptor& parsed() {
    static const hid::DescriptorParse result = hid::parse_report_descriptor(report_descriptor());
    return result.descriptor;
}

MainItemKind main_kind(ReportKind k) {
    switch (k) {
        case ReportKind::output: return MainItemKind::output;
        case ReportKind::feature: return MainItemKind::feature;
        case ReportKind::input: return MainItemKind::input;
    }
    return MainItemKind::input;
}

const DescriptorReport& report(ReportId id) {
    const auto raw = static_cast<uint8_t>(id);
    const std::optional<ReportKind> kind = report_kind(raw);
    const DescriptorReport* r = kind ? parsed().find(main_kind(*kind), raw) : nullptr;
    if (r == nullptr) throw std::runtime_error("descriptor lacks report " + std::to_string(raw));
    return *r;
}

// The report's collection: the usage of the collection inside the application collection.
uint32_t report_usage(const DescriptorReport& r) {
    return r.fields.front().collections.size() >= 2 ? r.fields.front().collections[1] : 0;
}

// The data field that carries `usage` (a Var field) or sits in the named array `usage`.
const DescriptorField& field(const DescriptorReport& r, uint32_t usage) {
    for (const DescriptorField& f : r.fields) {
        if (f.is_variable() && !f.usages.empty() && f.usages.front() == usage) return f;
        if (!f.is_variable() && !f.collections.empty() && f.collections.back() == usage) return f;
    }
    throw std::runtime_error("no field with usage " + std::to_string(usage));
}

// The field inside the Logical collection `usage` (PID's Direction collection of Ordinals).
const DescriptorField& wrapped_field(const DescriptorReport& r, uint32_t usage) {
    for (const DescriptorField& f : r.fields) {
        if (f.is_variable() && !f.collections.empty() && f.collections.back() == usage) return f;
    }
    throw std::runtime_error("no field in collection " + std::to_string(usage));
}

void expect_range(const DescriptorField& f, Range r) {
    EXPECT_EQ(f.logical_min, r.min);
    EXPECT_EQ(f.logical_max, r.max);
}

TEST(Descriptor, ParsesCleanly) {
    const hid::DescriptorParse result = hid::parse_report_descriptor(report_descriptor());
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_TRUE(result.descriptor.uses_report_ids);
    EXPECT_EQ(report_descriptor().data(), report_descriptor().data()) << "built once";
}

TEST(Descriptor, TheDescriptorAndEveryReportFitOneFrame) {
    EXPECT_LE(report_descriptor().size(), transport::kMaxFramePayload);
    EXPECT_LE(max_report_size(), transport::kMaxFramePayload);
}

TEST(Descriptor, IsOneJoystickApplicationCollection) {
    for (const DescriptorReport& r : parsed().reports) {
        for (const DescriptorField& f : r.fields) {
            ASSERT_FALSE(f.collections.empty());
            EXPECT_EQ(f.collections.front(), gd(0x04)) << "Joystick application collection";
        }
    }
}

TEST(Descriptor, EveryReportsLengthMatchesTheCodec) {
    std::map<uint8_t, std::size_t> encoded;
    for (const AnyReport& r : test::sample_reports()) {
        encoded[static_cast<uint8_t>(report_id_of(r))] = encode(r).size();
    }
    int declared = 0;
    for (int id = 0; id < 256; ++id) {
        const auto raw = static_cast<uint8_t>(id);
        if (report_size(raw) == 0) continue;
        ++declared;
        SCOPED_TRACE(id);
        const DescriptorReport& r = report(static_cast<ReportId>(raw));
        EXPECT_EQ(r.bit_length % 8, 0u) << "reports are whole bytes";
        EXPECT_EQ(r.bit_length / 8 + 1, report_size(raw));
        ASSERT_TRUE(encoded.count(raw));
        EXPECT_EQ(encoded[raw], report_size(raw));
    }
    EXPECT_EQ(static_cast<std::size_t>(declared), parsed().reports.size())
        << "the descriptor declares exactly the codec's reports";
    EXPECT_EQ(static_cast<std::size_t>(declared), std::variant_size_v<AnyReport>);
}

TEST(Descriptor, PidReportsCarryThePidReportUsages) {
    const std::pair<ReportId, uint32_t> expected[] = {
        {ReportId::set_effect, kPidSetEffectReport},
        {ReportId::set_envelope, kPidSetEnvelopeReport},
        {ReportId::set_condition, kPidSetConditionReport},
        {ReportId::set_periodic, kPidSetPeriodicReport},
        {ReportId::set_constant_force, kPidSetConstantForceReport},
        {ReportId::set_ramp_force, kPidSetRampForceReport},
        {ReportId::set_custom_force, kPidSetCustomForceReport},
        {ReportId::custom_force_data, kPidCustomForceDataReport},
        {ReportId::download_force_sample, kPidDownloadForceSample},
        {ReportId::effect_operation, kPidEffectOperationReport},
        {ReportId::block_free, kPidBlockFreeReport},
        {ReportId::device_control, kPidDeviceControlReport},
        {ReportId::device_gain, kPidDeviceGainReport},
        {ReportId::create_new_effect, kPidCreateNewEffectReport},
        {ReportId::block_load, kPidBlockLoadReport},
        {ReportId::pid_pool, kPidPoolReport},
        {ReportId::pid_state, kPidStateReport},
    };
    for (const auto& [id, usage] : expected) {
        SCOPED_TRACE(std::string(report_name(id)));
        EXPECT_EQ(report_usage(report(id)), usage);
    }
}

TEST(Descriptor, VendorReportsLiveOnTheVendorPage) {
    for (ReportId id : {ReportId::set_texture, ReportId::set_wall, ReportId::set_barrier,
                        ReportId::set_sweep, ReportId::set_dynamic, ReportId::set_control_law,
                        ReportId::reflex, ReportId::idf_settings, ReportId::report_rate,
                        ReportId::keep_alive, ReportId::effect_status_request,
                        ReportId::device_info, ReportId::command_status, ReportId::device_status,
                        ReportId::dynamic_report, ReportId::command_error_text, ReportId::effect_states}) {
        EXPECT_EQ(report_usage(report(id)) >> 16, 0xFF00u) << report_name(id);
    }
    // Every field usage is on a standard page feel uses, or on the vendor page.
    for (const DescriptorReport& r : parsed().reports) {
        for (const DescriptorField& f : r.fields) {
            for (uint32_t u : f.usages) {
                const uint32_t page = u >> 16;
                EXPECT_TRUE(page == 0x01 || page == 0x09 || page == 0x0A || page == 0x0F ||
                            page == 0xFF00)
                    << "usage page " << page;
            }
        }
    }
}

TEST(Descriptor, SetEffectFieldsUsePidUsagesAndFeelRanges) {
    const DescriptorReport& r = report(ReportId::set_effect);
    expect_range(field(r, kPidEffectBlockIndex), Range{1, 65535});
    // PID's times are whole milliseconds (what Linux's hid-pidff writes): 0..65 s, feel's
    // "0 to 65 million" microseconds (§6.3) in milliseconds.
    const Range milliseconds{0, 65'000};
    const DescriptorField& duration = field(r, kPidDuration);
    expect_range(duration, milliseconds);
    EXPECT_TRUE(duration.has_null_state()) << "infinite is the null value";
    EXPECT_EQ(duration.report_size, 16u);
    EXPECT_EQ(duration.unit, kUnitSeconds);
    EXPECT_EQ(duration.unit_exponent, -3);
    for (uint32_t u : {kPidStartDelay, kPidTriggerRepeatInterval}) {
        expect_range(field(r, u), milliseconds);
        EXPECT_EQ(field(r, u).unit, kUnitSeconds);
        EXPECT_EQ(field(r, u).unit_exponent, -3);
    }
    expect_range(field(r, kPidGain), range::kGain);
    // Trigger Button is 16 bits: hid-pidff writes evdev's button code (BTN_TRIGGER is
    // 0x120), which must arrive whole to be refused, not cut to a byte.
    expect_range(field(r, kPidTriggerButton), Range{0, range::kTriggerButton.max});
    EXPECT_EQ(field(r, kPidTriggerButton).report_size, 16u);
    expect_range(field(r, kPidDirectionEnable), Range{0, 1});
    // PID 1.0: Direction is a Logical collection of Ordinals (page 0x0A), here two angles
    // in degrees with exponent -2, 0..360°.
    const DescriptorField& direction = wrapped_field(r, kPidDirection);
    EXPECT_EQ(direction.usages, (std::vector<uint32_t>{0x000A0001u, 0x000A0002u}));
    EXPECT_EQ(direction.report_count, 2u);
    expect_range(direction, Range{0, 36000});
    EXPECT_EQ(direction.unit, kUnitDegrees);
    EXPECT_EQ(direction.unit_exponent, -2);
}

TEST(Descriptor, EffectTypeIsAPidNamedArrayOfEtUsages) {
    for (ReportId id : {ReportId::set_effect, ReportId::create_new_effect}) {
        const DescriptorField& type = field(report(id), kPidEffectType);
        EXPECT_FALSE(type.is_variable()) << "an Array item";
        // HID: an Array's value v selects usage v - Logical Minimum; hid-pidff wants the
        // minimum 1. feel sends EffectType t as t + 1.
        EXPECT_EQ(type.logical_min, 1);
        EXPECT_EQ(type.logical_max, kEffectTypeCount);
        ASSERT_EQ(type.usages.size(), static_cast<std::size_t>(kEffectTypeCount));
        auto usage_of = [&](EffectType t) {
            const int64_t wire = static_cast<int64_t>(t) + 1;
            return type.usages[static_cast<std::size_t>(wire - type.logical_min)];
        };
        // PID 1.0 ET usages.
        EXPECT_EQ(usage_of(EffectType::constant), pid(0x26));
        EXPECT_EQ(usage_of(EffectType::ramp), pid(0x27));
        EXPECT_EQ(usage_of(EffectType::force_profile), pid(0x28));
        EXPECT_EQ(usage_of(EffectType::square), pid(0x30));
        EXPECT_EQ(usage_of(EffectType::sine), pid(0x31));
        EXPECT_EQ(usage_of(EffectType::triangle), pid(0x32));
        EXPECT_EQ(usage_of(EffectType::saw_up), pid(0x33));
        EXPECT_EQ(usage_of(EffectType::saw_down), pid(0x34));
        EXPECT_EQ(usage_of(EffectType::spring), pid(0x40));
        EXPECT_EQ(usage_of(EffectType::damper), pid(0x41));
        EXPECT_EQ(usage_of(EffectType::inertia), pid(0x42));
        EXPECT_EQ(usage_of(EffectType::friction), pid(0x43));
        // The rest are feel's, on the vendor page, and all distinct.
        std::set<uint32_t> distinct(type.usages.begin(), type.usages.end());
        EXPECT_EQ(distinct.size(), type.usages.size());
        int vendor = 0;
        for (uint32_t u : type.usages) vendor += (u >> 16) == 0xFF00 ? 1 : 0;
        EXPECT_EQ(vendor, kEffectTypeCount - 12);
    }
}

TEST(Descriptor, OperationControlAndBlockLoadArraysSelectPidUsages) {
    const DescriptorField& op = field(report(ReportId::effect_operation), kPidEffectOperation);
    ASSERT_EQ(op.usages.size(), 3u);
    auto op_usage = [&](EffectOperation o) { return op.usages[static_cast<std::size_t>(static_cast<int>(o) - op.logical_min)]; };
    EXPECT_EQ(op_usage(EffectOperation::start), pid(0x79));
    EXPECT_EQ(op_usage(EffectOperation::start_solo), pid(0x7A));
    EXPECT_EQ(op_usage(EffectOperation::stop), pid(0x7B));
    // Loop Count: 16 bits on a feel device, 0..255 plus the null (0xFFFF) for infinite.
    const DescriptorField& loop = field(report(ReportId::effect_operation), kPidLoopCount);
    expect_range(loop, Range{0, 255});
    EXPECT_EQ(loop.report_size, 16u);
    EXPECT_TRUE(loop.has_null_state());

    const DescriptorField& dc = field(report(ReportId::device_control), kPidDeviceControl);
    ASSERT_EQ(dc.usages.size(), 6u);
    auto dc_usage = [&](DeviceControlOp o) { return dc.usages[static_cast<std::size_t>(static_cast<int>(o) - dc.logical_min)]; };
    EXPECT_EQ(dc_usage(DeviceControlOp::enable_actuators), pid(0x97));
    EXPECT_EQ(dc_usage(DeviceControlOp::disable_actuators), pid(0x98));
    EXPECT_EQ(dc_usage(DeviceControlOp::stop_all_effects), pid(0x99));
    EXPECT_EQ(dc_usage(DeviceControlOp::device_reset), pid(0x9A));
    EXPECT_EQ(dc_usage(DeviceControlOp::device_pause), pid(0x9B));
    EXPECT_EQ(dc_usage(DeviceControlOp::device_continue), pid(0x9C));

    const DescriptorReport& load = report(ReportId::block_load);
    const DescriptorField& status = field(load, kPidBlockLoadStatus);
    ASSERT_EQ(status.usages.size(), 3u);
    auto load_usage = [&](BlockLoadStatus s) { return status.usages[static_cast<std::size_t>(static_cast<int>(s) - status.logical_min)]; };
    EXPECT_EQ(load_usage(BlockLoadStatus::success), pid(0x8C));
    EXPECT_EQ(load_usage(BlockLoadStatus::full), pid(0x8D));
    EXPECT_EQ(load_usage(BlockLoadStatus::error), pid(0x8E));
    // Block 1..65535; 0 (no block, when the load failed) is the null.
    expect_range(field(load, kPidEffectBlockIndex), Range{1, 65535});
    EXPECT_TRUE(field(load, kPidEffectBlockIndex).has_null_state());
    expect_range(field(load, kPidRamPoolAvailable), Range{0, 0xFFFFFFFFLL});
}

TEST(Descriptor, ParameterBlocksUsePidUsagesAndFeelRanges) {
    const DescriptorReport& env = report(ReportId::set_envelope);
    expect_range(field(env, kPidAttackLevel), range::kLevel);
    expect_range(field(env, kPidAttackTime), Range{0, 65'000});
    expect_range(field(env, kPidFadeLevel), range::kLevel);
    expect_range(field(env, kPidFadeTime), Range{0, 65'000});
    EXPECT_EQ(field(env, kPidFadeTime).unit, kUnitSeconds);
    EXPECT_EQ(field(env, kPidFadeTime).unit_exponent, -3);

    const DescriptorReport& cond = report(ReportId::set_condition);
    expect_range(field(cond, kPidParameterBlockOffset), Range{0, kMaxAxes - 1});
    expect_range(field(cond, kPidCpOffset), range::kSignedLevel);
    expect_range(field(cond, kPidPositiveCoefficient), range::kSignedLevel);
    expect_range(field(cond, kPidNegativeCoefficient), range::kSignedLevel);
    expect_range(field(cond, kPidPositiveSaturation), range::kLevel);
    expect_range(field(cond, kPidNegativeSaturation), range::kLevel);
    expect_range(field(cond, kPidDeadBand), range::kLevel);

    const DescriptorReport& periodic = report(ReportId::set_periodic);
    expect_range(field(periodic, kPidMagnitude), range::kSignedLevel);
    expect_range(field(periodic, kPidOffset), range::kSignedLevel);
    const DescriptorField& phase = field(periodic, kPidPhase);
    expect_range(phase, Range{0, 36000});  // 0..360°, 360° being 0°
    EXPECT_EQ(phase.unit, kUnitDegrees);
    EXPECT_EQ(phase.unit_exponent, -2);
    expect_range(field(periodic, kPidPeriod), Range{0, 65'000});
    EXPECT_EQ(field(periodic, kPidPeriod).unit_exponent, -3);

    expect_range(field(report(ReportId::set_constant_force), kPidMagnitude), range::kSignedLevel);
    expect_range(field(report(ReportId::set_ramp_force), kPidRampStart), range::kSignedLevel);
    expect_range(field(report(ReportId::set_ramp_force), kPidRampEnd), range::kSignedLevel);

    const DescriptorReport& custom = report(ReportId::set_custom_force);
    expect_range(field(custom, kPidSamplePeriod), range::kPeriodUs);
    expect_range(field(custom, kPidSampleCount), range::kSampleCount);
    const DescriptorReport& data = report(ReportId::custom_force_data);
    expect_range(field(data, kPidCustomForceDataOffset), Range{0, 65534});
    const DescriptorField& samples = field(data, kPidCustomForceData);
    expect_range(samples, range::kSample);
    EXPECT_EQ(samples.report_count, static_cast<uint32_t>(kSamplesPerDataReport));
    EXPECT_EQ(samples.report_size, 16u);

    expect_range(field(report(ReportId::device_gain), kPidDeviceGain), range::kGain);
}

TEST(Descriptor, ForceStreamAndJoystickUseGenericDesktopAxes) {
    for (ReportId id : {ReportId::download_force_sample, ReportId::joystick_input}) {
        const DescriptorField& axes = field(report(id), gd(0x30));
        EXPECT_EQ(axes.report_count, 6u);
        EXPECT_EQ(axes.report_size, 16u);
        expect_range(axes, range::kSignedLevel);
        const std::vector<uint32_t> xyz = {gd(0x30), gd(0x31), gd(0x32), gd(0x33), gd(0x34), gd(0x35)};
        EXPECT_EQ(axes.usages, xyz);
    }
    const DescriptorField& buttons = field(report(ReportId::joystick_input), 0x00090001u);
    EXPECT_EQ(buttons.report_size, 1u);
    EXPECT_EQ(buttons.report_count, 32u);
    EXPECT_EQ(buttons.usages.size(), 32u);
    EXPECT_EQ(buttons.usages.back(), 0x00090020u);
    expect_range(buttons, Range{0, 1});
    // HID Usage Tables: Hat Switch (GD 0x39), eight directions 0..7 and a null state.
    const DescriptorField& hats = field(report(ReportId::joystick_input), gd(0x39));
    EXPECT_EQ(hats.report_size, 4u);
    EXPECT_EQ(hats.report_count, 4u);
    expect_range(hats, Range{0, 7});
    EXPECT_TRUE(hats.has_null_state());
}

TEST(Descriptor, AProfilesDescriptorDeclaresOnlyItsInputs) {
    JoystickLayout layout;  // Rz, X; 3 buttons; 1 hat
    layout.axis_count = 2;
    layout.axes[0] = Axis::rz;
    layout.axes[1] = Axis::x;
    layout.button_count = 3;
    layout.hat_count = 1;
    const std::vector<uint8_t> bytes = report_descriptor(layout);
    const hid::DescriptorParse parse = hid::parse_report_descriptor(bytes);
    ASSERT_TRUE(parse.ok()) << parse.error;
    const DescriptorReport* joy = parse.descriptor.find(MainItemKind::input, static_cast<uint8_t>(ReportId::joystick_input));
    ASSERT_NE(joy, nullptr);
    std::vector<uint32_t> data_usages;
    for (const DescriptorField& f : joy->fields) {
        if (f.is_constant()) continue;
        for (uint32_t k = 0; k < f.report_count; ++k) data_usages.push_back(f.usage_of(k));
    }
    EXPECT_EQ(data_usages, (std::vector<uint32_t>{gd(0x35), gd(0x30), 0x00090001u, 0x00090002u,
                                                  0x00090003u, gd(0x39)}));
    EXPECT_EQ(joy->bit_length % 8, 0u) << "padded to whole bytes";
    EXPECT_EQ(joy->bit_length / 8 + 1, joystick_input_size(layout));
    // The rest of the descriptor is the same as the full one's.
    const DescriptorReport* effect = parse.descriptor.find(MainItemKind::output, 0x01);
    ASSERT_NE(effect, nullptr);
    EXPECT_EQ(effect->bit_length, report(ReportId::set_effect).bit_length);
    EXPECT_EQ(parse.descriptor.reports.size(), parsed().reports.size());
}

TEST(Descriptor, PoolStateAndCreateUsePidUsages) {
    const DescriptorReport& pool = report(ReportId::pid_pool);
    EXPECT_EQ(field(pool, kPidRamPoolSize).report_size, 32u);
    EXPECT_EQ(field(pool, kPidSimultaneousEffectsMax).report_size, 16u);
    expect_range(field(pool, kPidDeviceManagedPool), Range{0, 1});
    expect_range(field(pool, kPidSharedParameterBlocks), Range{0, 1});
    expect_range(field(pool, kPidRamPoolAvailable), Range{0, 0xFFFFFFFFLL});

    const DescriptorReport& state = report(ReportId::pid_state);
    for (uint32_t u : {kPidDevicePaused, kPidActuatorsEnabled, kPidSafetySwitch,
                       kPidActuatorOverrideSwitch, kPidActuatorPower, kPidEffectPlaying}) {
        expect_range(field(state, u), Range{0, 1});
    }
    expect_range(field(state, kPidEffectBlockIndex), Range{0, 65535});

    // PID 1.0 sizes a new block with Generic Desktop's Byte Count (0x3B).
    expect_range(field(report(ReportId::create_new_effect), gd(0x3B)), Range{0, 65535});
}

TEST(Descriptor, SequenceIsTheFirstFieldOfEveryHostReport) {
    for (const DescriptorReport& r : parsed().reports) {
        if (r.kind == MainItemKind::input) continue;
        if (r.id == static_cast<uint8_t>(ReportId::block_load) ||
            r.id == static_cast<uint8_t>(ReportId::pid_pool) ||
            r.id == static_cast<uint8_t>(ReportId::device_info)) {
            continue;  // feature reports the host only gets
        }
        SCOPED_TRACE(static_cast<int>(r.id));
        // Device Control's list comes first (hid-pidff finds the report by it).
        const bool list_first = r.id == static_cast<uint8_t>(ReportId::device_control);
        const DescriptorField& first = r.fields[list_first ? 1 : 0];
        EXPECT_EQ(first.bit_offset, list_first ? 8u : 0u);
        EXPECT_EQ(first.report_size, 32u);
        EXPECT_EQ(first.usages.front() >> 16, 0xFF00u);
        expect_range(first, Range{0, 0xFFFFFFFFLL});
    }
}

}  // namespace
}  // namespace feel::protocol
