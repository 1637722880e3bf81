// The hid-pidff model of pidff_acceptance.hpp.
#include "pidff_acceptance.hpp"

#include <array>
#include <map>
#include <optional>

namespace feel::protocol::test {
namespace {

using hid::DescriptorField;
using hid::DescriptorReport;
using hid::MainItemKind;

constexpr uint32_t pid(uint16_t id) { return 0x000F0000u | id; }

// hid-pidff's report table, in its order; the first eight are required.
constexpr std::array<uint16_t, 13> kPidffReports = {0x21, 0x77, 0x7D, 0x7F, 0x89, 0x90, 0x96,
                                                    0xAB, 0x5A, 0x5F, 0x6E, 0x73, 0x74};
constexpr std::size_t kRequiredReports = 8;
enum : std::size_t {
    kSetEffect, kEffectOperation, kDeviceGain, kPool, kBlockLoad, kBlockFree, kDeviceControl,
    kCreateNewEffect, kSetEnvelope, kSetCondition, kSetPeriodic, kSetConstant, kSetRamp,
};
// The effect types it knows, in its order (constant, ramp, square, sine, triangle, saw up,
// saw down, spring, damper, inertia, friction).
constexpr std::array<uint16_t, 11> kPidffEffectTypes = {0x26, 0x27, 0x30, 0x31, 0x32, 0x33,
                                                        0x34, 0x40, 0x41, 0x42, 0x43};

// hid-core's field->logical: the innermost Logical collection's usage, 0 if none.
uint32_t logical_of(const DescriptorField& f) {
    for (std::size_t k = f.collections.size(); k-- > 0;) {
        if (k < f.collection_types.size() && f.collection_types[k] == hid::kCollectionLogical) {
            return f.collections[k];
        }
    }
    return 0;
}

// hid-core drops fields without usages (padding); hid-pidff sees the rest in order.
std::vector<const DescriptorField*> kernel_fields(const DescriptorReport& r) {
    std::vector<const DescriptorField*> out;
    for (const DescriptorField& f : r.fields) {
        if (!f.usages.empty()) out.push_back(&f);
    }
    return out;
}

std::string hex(uint32_t v) {
    static const char* digits = "0123456789ABCDEF";
    std::string s;
    do {
        s.insert(s.begin(), digits[v & 0xF]);
        v >>= 4;
    } while (v != 0);
    return "0x" + s;
}

// pidff_find_fields: every usage of `wanted` in a field whose maxusage equals its Report
// Count (hid-core's maxusage is max(usages, Report Count)).
bool find_fields(const DescriptorReport* r, std::initializer_list<uint16_t> wanted,
                 std::vector<std::string>& missing) {
    if (r == nullptr) return false;
    bool all = true;
    for (uint16_t u : wanted) {
        bool found = false;
        for (const DescriptorField* f : kernel_fields(*r)) {
            const std::size_t maxusage = std::max<std::size_t>(f->usages.size(), f->report_count);
            if (maxusage != f->report_count) continue;
            for (uint32_t fu : f->usages) found = found || fu == pid(u);
            if (found) break;
        }
        if (!found) {
            missing.push_back(hex(pid(u) & 0xFFFFu));
            all = false;
        }
    }
    return all;
}

// pidff_find_special_field: the first field whose logical usage is `usage`.
const DescriptorField* special_field(const DescriptorReport* r, uint16_t usage, bool enforce_min,
                                     std::vector<std::string>& problems, const char* where) {
    if (r == nullptr) return nullptr;
    for (const DescriptorField* f : kernel_fields(*r)) {
        if (logical_of(*f) != pid(usage) || f->report_count == 0) continue;
        if (enforce_min && f->logical_min != 1) {
            problems.push_back(std::string(where) + ": list " + hex(usage) +
                               " has Logical Minimum " + std::to_string(f->logical_min) +
                               " (hid-pidff: \"logical_minimum is not 1 as it should be\")");
            return nullptr;
        }
        return f;
    }
    problems.push_back(std::string(where) + ": no field in a Logical collection " + hex(usage));
    return nullptr;
}

// pidff_find_special_keys: 1-based positions of `wanted` in the field's usages (0: absent).
std::vector<int> special_keys(const DescriptorField& f, std::initializer_list<uint16_t> wanted) {
    std::vector<int> keys;
    for (uint16_t u : wanted) {
        int key = 0;
        for (std::size_t j = 0; j < f.usages.size() && key == 0; ++j) {
            if (f.usages[j] == pid(u)) key = static_cast<int>(j) + 1;
        }
        keys.push_back(key);
    }
    return keys;
}

}  // namespace

PidffVerdict pidff_check(const hid::ParsedDescriptor& descriptor) {
    PidffVerdict v;
    std::array<const DescriptorReport*, kPidffReports.size()> reports{};
    bool has_output = false;
    for (MainItemKind kind : {MainItemKind::output, MainItemKind::feature}) {
        for (const DescriptorReport& r : descriptor.reports) {
            if (r.kind != kind) continue;
            has_output = has_output || kind == MainItemKind::output;
            const auto fields = kernel_fields(r);
            if (fields.empty()) continue;
            const uint32_t logical = logical_of(*fields.front());
            for (std::size_t k = 0; k < kPidffReports.size(); ++k) {
                if (logical == pid(kPidffReports[k])) reports[k] = &r;
            }
        }
    }
    if (!has_output) v.problems.emplace_back("no output report: \"not a PID device\"");
    for (std::size_t k = 0; k < kRequiredReports; ++k) {
        if (reports[k] == nullptr) {
            v.problems.push_back("report " + hex(kPidffReports[k]) +
                                 " not found by its first field's Logical collection");
        }
    }
    if (!v.problems.empty()) return v;

    std::vector<std::string> missing;
    auto require = [&](std::size_t report, std::initializer_list<uint16_t> usages, const char* name) {
        missing.clear();
        if (!find_fields(reports[report], usages, missing)) {
            std::string list;
            for (const std::string& m : missing) list += " " + m;
            v.problems.push_back(std::string("unknown ") + name + " report layout: missing" + list);
        }
    };
    require(kSetEffect, {0x22, 0x50, 0x52, 0x53, 0x54, 0x56, 0xA7}, "set_effect");
    require(kBlockLoad, {0x22}, "pid_block_load");
    require(kEffectOperation, {0x22, 0x7C}, "effect_operation");
    require(kBlockFree, {0x22}, "pid_block_free");
    // Optional for the kernel, required for feel: without them it drops effect types.
    require(kSetEnvelope, {0x22, 0x5B, 0x5C, 0x5D, 0x5E}, "set_envelope");
    require(kSetConstant, {0x22, 0x70}, "constant effect");
    require(kSetRamp, {0x22, 0x75, 0x76}, "ramp effect");
    require(kSetCondition, {0x22, 0x23, 0x60, 0x61, 0x62, 0x63, 0x64, 0x65}, "condition effect");
    require(kSetPeriodic, {0x22, 0x70, 0x6F, 0x71, 0x72}, "periodic effect");
    missing.clear();
    v.gain = find_fields(reports[kDeviceGain], {0x7E}, missing);
    if (!v.gain) v.problems.emplace_back("device gain: no 0x7E field (no FF_GAIN)");

    const DescriptorField* create_type =
        special_field(reports[kCreateNewEffect], 0x25, true, v.problems, "create_new_effect");
    const DescriptorField* set_type = special_field(reports[kSetEffect], 0x25, true, v.problems, "set_effect");
    special_field(reports[kSetEffect], 0x57, false, v.problems, "set_effect direction");
    const DescriptorField* control =
        special_field(reports[kDeviceControl], 0x96, true, v.problems, "device_control");
    const DescriptorField* load_status =
        special_field(reports[kBlockLoad], 0x8B, true, v.problems, "block_load");
    const DescriptorField* operation =
        special_field(reports[kEffectOperation], 0x78, true, v.problems, "effect_operation");
    if (!v.problems.empty()) return v;

    const auto control_keys = special_keys(*control, {0x97, 0x9A});
    if (control_keys[0] == 0 || control_keys[1] == 0) {
        v.problems.emplace_back("device control lacks DC Enable Actuators or DC Device Reset");
    }
    const auto status_keys = special_keys(*load_status, {0x8C, 0x8D});
    if (status_keys[0] == 0 || status_keys[1] == 0) {
        v.problems.emplace_back("block load status identifiers not found");
    }
    const auto op_keys = special_keys(*operation, {0x79, 0x7B});
    if (op_keys[0] == 0 || op_keys[1] == 0) {
        v.problems.emplace_back("effect operation identifiers not found");
    }
    int types_found = 0;
    for (uint16_t type : kPidffEffectTypes) {
        const int key = special_keys(*create_type, {type})[0];
        const auto index = static_cast<std::size_t>(key);
        if (key != 0) ++types_found;
        // pidff_find_effects compares usage[key] of both lists (key is 1-based).
        if (index >= create_type->usages.size() || index >= set_type->usages.size()) {
            if (key != 0) {
                v.problems.push_back("effect type " + hex(type) +
                                     " is the last of its list: hid-pidff reads one past it");
            }
            continue;
        }
        if (create_type->usages[index] != set_type->usages[index]) {
            v.problems.push_back("effect type number for " + hex(type) + " is invalid: the two lists differ");
        }
        if (key != 0) v.ff_effects.push_back(type);
    }
    if (types_found == 0) v.problems.emplace_back("no effect types found");

    // PID Pool: Device Managed Pool, when declared, must be able to say 1.
    missing.clear();
    if (find_fields(reports[kPool], {0xA9}, missing)) {
        for (const DescriptorField* f : kernel_fields(*reports[kPool])) {
            for (uint32_t u : f->usages) {
                if (u == pid(0xA9) && (f->logical_min > 1 || f->logical_max < 1)) {
                    v.problems.emplace_back("PID Pool's Device Managed Pool cannot be 1");
                }
            }
        }
    }
    for (const DescriptorField* f : kernel_fields(*reports[kBlockLoad])) {
        if (f->usages.front() != pid(0x22)) continue;
        v.first_block = f->logical_min;
        v.max_effects = static_cast<int>(std::min<int64_t>(f->logical_max - f->logical_min + 1, 64));
        break;
    }
    if (v.max_effects < 1) v.problems.emplace_back("Block Load's Effect Block Index range is empty");
    return v;
}

}  // namespace feel::protocol::test
