// docs/protocol.md documents every report, and its field tables are the report table's:
// the section between the GENERATED markers is written from src/protocol's table, so it
// cannot fall behind the code. After a protocol change run the test with
// FEEL_UPDATE_PROTOCOL_DOCS=1 to rewrite that section, and review the diff.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "feel/effect_type.hpp"
#include "feel/protocol/codec.hpp"
#include "hid_usages.hpp"
#include "report_table.hpp"

namespace feel::protocol {
namespace {

using detail::FieldSpec;
using detail::FieldUnit;
using detail::ReportSpec;

constexpr std::string_view kBegin = "<!-- BEGIN GENERATED report tables (tests/protocol/protocol_doc_test.cpp) -->";
constexpr std::string_view kEnd = "<!-- END GENERATED report tables -->";

const std::string kDocPath = std::string(FEEL_SOURCE_DIR) + "/docs/protocol.md";

std::string read_doc() {
    std::ifstream in(kDocPath);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Names of the standard usages the tables mention (PID 1.0 §5; HID Usage Tables).
std::string usage_text(uint32_t u) {
    static const std::map<uint32_t, std::string> names = {
        {usage::pid::kEffectBlockIndex, "Effect Block Index"},
        {usage::pid::kParameterBlockOffset, "Parameter Block Offset"},
        {usage::pid::kEffectType, "Effect Type"},
        {usage::pid::kDuration, "Duration"},
        {usage::pid::kSamplePeriod, "Sample Period"},
        {usage::pid::kGain, "Gain"},
        {usage::pid::kTriggerButton, "Trigger Button"},
        {usage::pid::kTriggerRepeatInterval, "Trigger Repeat Interval"},
        {usage::pid::kAxesEnable, "Axes Enable"},
        {usage::pid::kDirection, "Direction"},
        {usage::pid::kDirectionEnable, "Direction Enable"},
        {usage::gd::kHatSwitch, "Hat Switch"},
        {usage::pid::kAttackLevel, "Attack Level"},
        {usage::pid::kAttackTime, "Attack Time"},
        {usage::pid::kFadeLevel, "Fade Level"},
        {usage::pid::kFadeTime, "Fade Time"},
        {usage::pid::kCpOffset, "CP Offset"},
        {usage::pid::kPositiveCoefficient, "Positive Coefficient"},
        {usage::pid::kNegativeCoefficient, "Negative Coefficient"},
        {usage::pid::kPositiveSaturation, "Positive Saturation"},
        {usage::pid::kNegativeSaturation, "Negative Saturation"},
        {usage::pid::kDeadBand, "Dead Band"},
        {usage::pid::kCustomForceData, "Custom Force Data"},
        {usage::pid::kCustomForceDataOffset, "Custom Force Data Offset"},
        {usage::pid::kSampleCount, "Sample Count"},
        {usage::pid::kOffset, "Offset"},
        {usage::pid::kMagnitude, "Magnitude"},
        {usage::pid::kPhase, "Phase"},
        {usage::pid::kPeriod, "Period"},
        {usage::pid::kRampStart, "Ramp Start"},
        {usage::pid::kRampEnd, "Ramp End"},
        {usage::pid::kEffectOperation, "Effect Operation"},
        {usage::pid::kLoopCount, "Loop Count"},
        {usage::pid::kDeviceGain, "Device Gain"},
        {usage::pid::kRamPoolSize, "RAM Pool Size"},
        {usage::pid::kSimultaneousEffectsMax, "Simultaneous Effects Max"},
        {usage::pid::kBlockLoadStatus, "Block Load Status"},
        {usage::pid::kEffectPlaying, "Effect Playing"},
        {usage::pid::kPidDeviceControl, "PID Device Control"},
        {usage::pid::kDevicePaused, "Device Paused"},
        {usage::pid::kActuatorsEnabled, "Actuators Enabled"},
        {usage::pid::kSafetySwitch, "Safety Switch"},
        {usage::pid::kActuatorOverrideSwitch, "Actuator Override Switch"},
        {usage::pid::kActuatorPower, "Actuator Power"},
        {usage::pid::kStartDelay, "Start Delay"},
        {usage::pid::kDeviceManagedPool, "Device Managed Pool"},
        {usage::pid::kSharedParameterBlocks, "Shared Parameter Blocks"},
        {usage::pid::kRamPoolAvailable, "RAM Pool Available"},
        {usage::pid::kSetEffectReport, "Set Effect Report"},
        {usage::pid::kSetEnvelopeReport, "Set Envelope Report"},
        {usage::pid::kSetConditionReport, "Set Condition Report"},
        {usage::pid::kSetPeriodicReport, "Set Periodic Report"},
        {usage::pid::kSetConstantForceReport, "Set Constant Force Report"},
        {usage::pid::kSetRampForceReport, "Set Ramp Force Report"},
        {usage::pid::kSetCustomForceReport, "Set Custom Force Report"},
        {usage::pid::kCustomForceDataReport, "Custom Force Data Report"},
        {usage::pid::kDownloadForceSample, "Download Force Sample"},
        {usage::pid::kEffectOperationReport, "Effect Operation Report"},
        {usage::pid::kPidBlockFreeReport, "PID Block Free Report"},
        {usage::pid::kPidDeviceControlReport, "PID Device Control Report"},
        {usage::pid::kDeviceGainReport, "Device Gain Report"},
        {usage::pid::kCreateNewEffectReport, "Create New Effect Report"},
        {usage::pid::kPidBlockLoadReport, "PID Block Load Report"},
        {usage::pid::kPidPoolReport, "PID Pool Report"},
        {usage::pid::kPidStateReport, "PID State Report"},
        {usage::pid::kOpEffectStart, "Op Effect Start"},
        {usage::pid::kOpEffectStartSolo, "Op Effect Start Solo"},
        {usage::pid::kOpEffectStop, "Op Effect Stop"},
        {usage::pid::kBlockLoadSuccess, "Block Load Success"},
        {usage::pid::kBlockLoadFull, "Block Load Full"},
        {usage::pid::kBlockLoadError, "Block Load Error"},
        {usage::pid::kDcEnableActuators, "DC Enable Actuators"},
        {usage::pid::kDcDisableActuators, "DC Disable Actuators"},
        {usage::pid::kDcStopAllEffects, "DC Stop All Effects"},
        {usage::pid::kDcDeviceReset, "DC Device Reset"},
        {usage::pid::kDcDevicePause, "DC Device Pause"},
        {usage::pid::kDcDeviceContinue, "DC Device Continue"},
        {usage::gd::kPointer, "Pointer"},
        {usage::gd::kByteCount, "Byte Count"},
    };
    char hex[16];
    const uint16_t page = usage::page_of(u), id = usage::id_of(u);
    if (page == usage::kPageVendor) {
        std::snprintf(hex, sizeof hex, "0x%04X", id);
        return std::string("vendor ") + hex;
    }
    std::snprintf(hex, sizeof hex, "0x%02X", id);
    const char* page_name = page == usage::kPagePid ? "PID " : page == usage::kPageGenericDesktop ? "GD " : "Button ";
    const auto it = names.find(u);
    return std::string(page_name) + hex + (it != names.end() ? " " + it->second : "");
}

std::string field_usage_text(const FieldSpec& f) {
    if (f.padding) return "(constant padding)";
    if (f.named_array != 0) return usage_text(f.named_array) + " (named array)";
    if (f.wrap != 0 && !f.usage_list.empty() && f.usage_list.front() == usage::gd::kX) {
        return usage_text(f.wrap) + " (collection of GD X, Y, Z, Rx, Ry, Rz)";
    }
    if (f.wrap != 0) return usage_text(f.wrap) + " (collection of Ordinals 1, 2)";
    if (f.usage_list.empty()) return usage_text(f.usage);
    if (usage::page_of(f.usage_list.front()) == usage::kPageButton) return "Button 1..32";
    if (f.usage_list.front() == usage::gd::kX) return "GD X, Y, Z, Rx, Ry, Rz";
    return usage_text(f.usage_list.front()) + " ...";
}

std::string range_text(const FieldSpec& f) {
    if (f.bits == 64) return "any (64-bit)";
    if (f.usage == usage::gd::kHatSwitch) return "0..7 declared; a feel device sends 0 (pushed, north) or 15 (centred, null)";
    std::string s = std::to_string(f.range.min) + "..";
    s += std::to_string(f.range.max);
    if (f.null == FieldSpec::Null::all_ones) s += ", or " + std::to_string(f.null_value()) + " = infinite (null)";
    if (f.null == FieldSpec::Null::zero) s += ", or 0 = none (null)";
    if (f.valid != nullptr) s += ", a report id";
    return s;
}

std::string unit_text(FieldUnit u) {
    switch (u) {
        case FieldUnit::none: return "";
        case FieldUnit::microseconds: return "µs";
        case FieldUnit::milliseconds: return "ms";
        case FieldUnit::centidegrees: return "0.01°";
        case FieldUnit::hertz: return "Hz";
        case FieldUnit::centihertz: return "0.01 Hz";
        case FieldUnit::millihertz: return "mHz";
    }
    return "";
}

std::string path_text(const FieldSpec& f) {
    std::string p(f.path);
    const std::size_t at = p.find("[i]");
    if (at != std::string::npos) p.replace(at, 3, "[0.." + std::to_string(f.count - 1) + "]");
    return "`" + p + "`";
}

const char* kind_text(ReportKind k) {
    switch (k) {
        case ReportKind::output: return "output";
        case ReportKind::feature: return "feature";
        case ReportKind::input: return "input";
    }
    return "";
}

// Which USB pipe the report travels on, and whether it fits one full-speed packet (every
// input and output report does: tests/usb/report_fit_test.cpp checks it on the descriptor).
std::string pipe_text(const ReportSpec& r) {
    if (r.kind == ReportKind::feature) return "control pipe (GET/SET_REPORT)";
    const char* pipe = r.kind == ReportKind::output ? "interrupt OUT" : "interrupt IN";
    return std::string(pipe) + (r.size() <= kInterruptPacketBytes ? " (fits a 64-byte packet)"
                                                                  : " (does NOT fit a 64-byte packet)");
}

// Who sends it: a feature report is set by the host (Create New Effect) or got from the device.
const char* direction_text(const ReportSpec& r) {
    switch (r.kind) {
        case ReportKind::output: return "host → device";
        case ReportKind::input: return "device → host";
        case ReportKind::feature:
            return r.id == ReportId::create_new_effect ? "host → device (SET_REPORT)" : "device → host (GET_REPORT)";
    }
    return "";
}

std::string pipe_column(const ReportSpec& r) {
    switch (r.kind) {
        case ReportKind::output: return "interrupt OUT";
        case ReportKind::input: return "interrupt IN";
        case ReportKind::feature: return "control (feature)";
    }
    return "";
}

std::string generated_tables() {
    std::ostringstream md;
    md << kBegin << "\n";
    md << "\n### Reports by pipe\n\nOn USB (docs/usb-device.md). Sizes include the report id byte; a "
          "full-speed interrupt packet is 64 bytes.\n\n| id | report | direction | bytes | pipe |\n|---|---|---|---|---|\n";
    for (const ReportSpec* r : detail::all_reports()) {
        char id[8];
        std::snprintf(id, sizeof id, "0x%02X", static_cast<unsigned>(r->id));
        md << "| " << id << " | " << r->name << " | " << direction_text(*r) << " | " << r->size() << " | "
           << pipe_column(*r) << " |\n";
    }
    for (const ReportSpec* r : detail::all_reports()) {
        char id[8];
        std::snprintf(id, sizeof id, "0x%02X", static_cast<unsigned>(r->id));
        md << "\n### " << id << " " << r->name << "\n\n";
        md << kind_text(r->kind) << ", " << r->size() << " bytes, " << pipe_text(*r) << ", collection "
           << usage_text(r->usage) << "; errors name its fields `" << r->key << ".<field>`\n\n";
        md << "| byte | field | usage | bits | range | unit |\n|---|---|---|---|---|---|\n";
        std::size_t bit = 8;
        for (const FieldSpec& f : r->fields) {
            md << "| " << bit / 8 << " | " << path_text(f) << " | " << field_usage_text(f) << " | "
               << static_cast<int>(f.bits) << (f.count > 1 ? " × " + std::to_string(f.count) : "")
               << " | " << range_text(f) << " | " << unit_text(f.unit) << " |\n";
            bit += f.total_bits();
        }
    }
    md << "\n### Effect types\n\nThe Effect Type named array (Set Effect, Create New Effect): "
          "value = `feel::EffectType` + 1 (the list is 1-based, as hid-pidff requires), selecting this "
          "usage.\n\n| value | type | usage |\n|---|---|---|\n";
    for (int t = 0; t < kEffectTypeCount; ++t) {
        md << "| " << t + 1 << " | `" << effect_type_name(static_cast<EffectType>(t)) << "` | "
           << usage_text(usage::kEffectTypeUsages[t]) << " |\n";
    }
    md << "\n" << kEnd;
    return md.str();
}

TEST(ProtocolDoc, NamesEveryReport) {
    const std::string doc = read_doc();
    ASSERT_FALSE(doc.empty()) << kDocPath;
    for (const ReportSpec* r : detail::all_reports()) {
        EXPECT_NE(doc.find(std::string(r->name)), std::string::npos) << r->name;
    }
}

TEST(ProtocolDoc, FieldTablesMatchTheReportTable) {
    std::string doc = read_doc();
    const std::size_t begin = doc.find(kBegin);
    const std::size_t end = doc.find(kEnd);
    ASSERT_NE(begin, std::string::npos) << "docs/protocol.md lacks " << kBegin;
    ASSERT_NE(end, std::string::npos) << "docs/protocol.md lacks " << kEnd;
    const std::string current = doc.substr(begin, end + kEnd.size() - begin);
    const std::string expected = generated_tables();
    if (current != expected && std::getenv("FEEL_UPDATE_PROTOCOL_DOCS") != nullptr) {
        doc.replace(begin, current.size(), expected);
        std::ofstream(kDocPath, std::ios::trunc) << doc;
        return;
    }
    EXPECT_EQ(current, expected) << "docs/protocol.md's report tables are stale: rerun with "
                                    "FEEL_UPDATE_PROTOCOL_DOCS=1 and review the diff";
}

}  // namespace
}  // namespace feel::protocol
