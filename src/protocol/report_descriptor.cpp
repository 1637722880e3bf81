// report_descriptor(): the HID report descriptor, written from the report table.
//
// Layout (HID 1.11 §6.2.2, PID 1.0 §5):
//
//   Usage Page (Generic Desktop), Usage (Joystick), Collection (Application)
//     per report:  Usage (the report's usage), Collection (Logical; Physical for the
//                  joystick's pointer), Report ID, its fields, End Collection
//   End Collection
//
// Per field: its usages (Usage Minimum/Maximum for a consecutive run, 32-bit extended
// usages when they span pages), Logical Minimum/Maximum, Unit and Unit Exponent when they
// change, Report Size, Report Count, and an Input/Output/Feature item (Data, Var, Abs; Null
// State for durations that may be infinite). A PID named array (Effect Type, Effect
// Operation, Device Control, Block Load Status) is its usage's Logical collection around an
// Array item whose value selects one of the listed usages (1 the first: hid-pidff refuses
// a list whose Logical Minimum is not 1). PID's Direction is a Logical collection (0x57)
// around a Variable field of Ordinals (FieldSpec::wrap).
//
// Global items are written only when their value changes, as HID intends: a reader keeps
// the global state from item to item.
//
// Item data: unsigned values (usages, sizes, counts, units) in the fewest bytes; logical
// limits as signed values in the fewest of 1, 2 or 4 bytes, except an unsigned 32-bit
// maximum above 2^31-1, written as its 4-byte pattern: a reader takes Logical Maximum as
// unsigned when Logical Minimum is not negative (as Linux's hid-core does, and as our own
// parser does, descriptor_parser.cpp).
#include <optional>
#include <vector>

#include <stdexcept>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/standard_pid.hpp"

#include "hid_usages.hpp"
#include "joystick_layout.hpp"
#include "report_table.hpp"
#include "standard_pid_table.hpp"

namespace feel::protocol {
namespace {

using detail::FieldSpec;
using detail::FieldUnit;
using detail::ReportSpec;

// Item prefixes without their size bits (HID 1.11 §6.2.2.4, §6.2.2.7, §6.2.2.8).
enum Prefix : uint8_t {
    kInput = 0x80, kOutput = 0x90, kFeature = 0xB0, kCollection = 0xA0, kEndCollection = 0xC0,
    kUsagePage = 0x04, kLogicalMinimum = 0x14, kLogicalMaximum = 0x24, kUnitExponent = 0x54,
    kUnit = 0x64, kReportSize = 0x74, kReportId = 0x84, kReportCount = 0x94,
    kUsage = 0x08, kUsageMinimum = 0x18, kUsageMaximum = 0x28,
};
enum CollectionType : uint8_t { kPhysical = 0x00, kApplication = 0x01, kLogical = 0x02 };
// Main item data bits.
constexpr uint32_t kConstant = 0x01;
constexpr uint32_t kVariable = 0x02;
constexpr uint32_t kNullState = 0x40;

struct UnitItems {
    uint32_t unit;
    int exponent;
};

UnitItems unit_items(FieldUnit u) noexcept {
    switch (u) {
        case FieldUnit::none: return {0, 0};
        case FieldUnit::microseconds: return {0x1001, -6};  // SI Linear, time: s
        case FieldUnit::milliseconds: return {0x1001, -3};
        case FieldUnit::centidegrees: return {0x0014, -2};  // English Rotation, "length": degrees
        case FieldUnit::hertz: return {0xF001, 0};          // SI Linear, time^-1: 1/s
        case FieldUnit::centihertz: return {0xF001, -2};
        case FieldUnit::millihertz: return {0xF001, -3};
    }
    return {0, 0};
}

class DescriptorWriter {
public:
    std::vector<uint8_t> take() { return std::move(bytes_); }

    void unsigned_item(uint8_t prefix, uint32_t value) {
        if (value <= 0xFF) {
            raw(prefix, value, 1);
        } else if (value <= 0xFFFF) {
            raw(prefix, value, 2);
        } else {
            raw(prefix, value, 4);
        }
    }

    void signed_item(uint8_t prefix, int64_t value) {
        if (value >= INT8_MIN && value <= INT8_MAX) {
            raw(prefix, static_cast<uint32_t>(value), 1);
        } else if (value >= INT16_MIN && value <= INT16_MAX) {
            raw(prefix, static_cast<uint32_t>(value), 2);
        } else {
            raw(prefix, static_cast<uint32_t>(value), 4);  // int32, or a uint32 maximum
        }
    }

    void usage_page(uint16_t page) {
        if (page_ == page) return;
        page_ = page;
        unsigned_item(kUsagePage, page);
    }

    // The usages of one main item (or collection), in order.
    void usages(std::span<const uint32_t> list) {
        bool one_page = true;
        for (uint32_t u : list) one_page = one_page && usage::page_of(u) == usage::page_of(list[0]);
        if (!one_page) {
            for (uint32_t u : list) raw(kUsage, u, 4);  // extended: page << 16 | id
            return;
        }
        usage_page(usage::page_of(list[0]));
        bool consecutive = list.size() >= 3;
        for (std::size_t k = 1; k < list.size(); ++k) consecutive = consecutive && list[k] == list[k - 1] + 1;
        if (consecutive) {
            unsigned_item(kUsageMinimum, usage::id_of(list.front()));
            unsigned_item(kUsageMaximum, usage::id_of(list.back()));
            return;
        }
        for (uint32_t u : list) unsigned_item(kUsage, usage::id_of(u));
    }
    void usage(uint32_t u) { usages(std::span<const uint32_t>(&u, 1)); }

    void logical(int64_t min, int64_t max) {
        if (min_ != min) signed_item(kLogicalMinimum, min);
        if (max_ != max) signed_item(kLogicalMaximum, max);
        min_ = min;
        max_ = max;
    }

    void unit(FieldUnit u) {
        const UnitItems items = unit_items(u);
        if (unit_ != items.unit) unsigned_item(kUnit, items.unit);
        if (exponent_ != items.exponent) {
            // Unit Exponent is a 4-bit two's-complement nibble (HID 1.11 §6.2.2.7).
            raw(kUnitExponent, static_cast<uint32_t>(items.exponent) & 0x0Fu, 1);
        }
        unit_ = items.unit;
        exponent_ = items.exponent;
    }

    void size_and_count(uint32_t bits, uint32_t count) {
        if (size_ != bits) unsigned_item(kReportSize, bits);
        if (count_ != count) unsigned_item(kReportCount, count);
        size_ = bits;
        count_ = count;
    }

    void collection(CollectionType type) { raw(kCollection, type, 1); }
    void end_collection() { bytes_.push_back(kEndCollection); }

private:
    void raw(uint8_t prefix, uint32_t value, int bytes) {
        const uint8_t size_code = bytes == 4 ? 3 : static_cast<uint8_t>(bytes);
        bytes_.push_back(static_cast<uint8_t>(prefix | size_code));
        for (int k = 0; k < bytes; ++k) bytes_.push_back(static_cast<uint8_t>(value >> (8 * k)));
    }

    std::vector<uint8_t> bytes_;
    // The global state a reader holds (std::nullopt until first written).
    std::optional<uint16_t> page_;
    std::optional<int64_t> min_, max_;
    std::optional<uint32_t> unit_;
    std::optional<int> exponent_;
    std::optional<uint32_t> size_, count_;
};

uint8_t main_prefix(ReportKind kind) noexcept {
    switch (kind) {
        case ReportKind::output: return kOutput;
        case ReportKind::feature: return kFeature;
        case ReportKind::input: return kInput;
    }
    return kInput;
}

void write_field(DescriptorWriter& w, const ReportSpec& report, const FieldSpec& field) {
    const uint8_t main = main_prefix(report.kind);
    if (field.padding) {
        w.size_and_count(field.bits, field.count);
        w.unsigned_item(main, kConstant | kVariable);  // no usage: a host ignores it
        return;
    }
    if (field.named_array != 0) {
        w.usage(field.named_array);
        w.collection(kLogical);
        w.usages(field.usage_list);
        w.logical(field.range.min, field.range.max);
        w.unit(field.unit);
        w.size_and_count(field.bits, field.count);
        w.unsigned_item(main, 0x00);  // Data, Array, Absolute
        w.end_collection();
        return;
    }
    if (field.wrap != 0) {
        w.usage(field.wrap);
        w.collection(kLogical);
    }
    if (field.usage_list.empty()) {
        w.usage(field.usage);
    } else {
        w.usages(field.usage_list);
    }
    w.unit(field.unit);
    if (field.bits == 64) {
        // Two 32-bit halves per element, low first (field_spec.hpp).
        w.logical(0, 0xFFFF'FFFFLL);
        w.size_and_count(32, 2u * field.count);
    } else {
        w.logical(field.range.min, field.range.max);
        w.size_and_count(field.bits, field.count);
    }
    w.unsigned_item(main, kVariable | (field.has_null() ? kNullState : 0u));
    if (field.wrap != 0) w.end_collection();
}

void write_report(DescriptorWriter& w, const ReportSpec& report, std::span<const FieldSpec> fields) {
    w.usage(report.usage);
    w.collection(report.usage == usage::gd::kPointer ? kPhysical : kLogical);
    w.unsigned_item(kReportId, static_cast<uint8_t>(report.id));
    for (const FieldSpec& field : fields) write_field(w, report, field);
    w.end_collection();
}

// feel's descriptor; with `standard`, the plain PID device's (standard_pid.hpp): the same
// order, only the standard reports, each with only its standard fields.
std::vector<uint8_t> build_descriptor(const JoystickLayout& layout, bool standard = false) {
    detail::JoystickSpec joystick;
    detail::build_joystick_spec(layout, joystick);
    DescriptorWriter w;
    w.usage(usage::gd::kJoystick);
    w.collection(kApplication);
    for (const ReportSpec* listed : detail::all_reports()) {
        const ReportSpec* report = listed->id == ReportId::joystick_input ? &joystick.spec : listed;
        if (!standard || report == &joystick.spec) {
            write_report(w, *report, report->fields);
            continue;
        }
        const detail::StandardReport* form = detail::find_standard_report(static_cast<uint8_t>(report->id));
        if (form == nullptr) continue;
        std::vector<FieldSpec> fields;
        for (const detail::StandardField& f : form->fields) fields.push_back(f.spec);
        write_report(w, *report, fields);
    }
    w.end_collection();
    return w.take();
}

}  // namespace

std::span<const uint8_t> report_descriptor() noexcept {
    static const std::vector<uint8_t> descriptor = build_descriptor(JoystickLayout{});  // built once
    return descriptor;
}

std::vector<uint8_t> report_descriptor(const JoystickLayout& layout) {
    if (const Error e = check_layout(layout)) {
        throw std::invalid_argument("no descriptor for this joystick layout: " + e.message());
    }
    return build_descriptor(layout);
}

std::vector<uint8_t> standard_pid_descriptor(const JoystickLayout& layout) {
    if (const Error e = check_layout(layout)) {
        throw std::invalid_argument("no standard PID descriptor for this joystick layout: " + e.message());
    }
    return build_descriptor(layout, true);
}

}  // namespace feel::protocol
