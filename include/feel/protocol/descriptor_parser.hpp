// feel::protocol::hid — an HID report descriptor parser (HID 1.11 §6.2.2).
//
// It walks a descriptor's short items, keeps the global state (with Push/Pop) and the local
// state between main items, and returns each report — per kind (input, output, feature)
// and Report ID — with its total length in bits and its fields in order: usage(s), logical
// and physical range, unit, element size and count, and the main item's flags.
//
// It shares nothing with the code that writes feel's descriptor (report_descriptor.cpp):
// the tests use it as an independent reader, the way a host's HID stack would read the
// device. It is written for descriptors from anywhere, including a real device's, so a
// malformed one is refused with the byte offset and what is wrong (a truncated item, a
// long item, a reserved tag, an unbalanced collection or Push/Pop, Report Size or Count 0,
// Report ID 0, a main item before the first Report ID once IDs are in use, an inverted
// logical range, a Usage Minimum without its Maximum, limits on nesting and sizes), never
// with a crash; its fuzz target is fuzz/fuzz_descriptor_parser.cpp.
//
// Conventions where HID 1.11 leaves room:
//   - Logical (and Physical) Maximum is read as an unsigned value when the Minimum in
//     effect at the main item is not negative, as Linux's hid-core does, so that a 32-bit
//     unsigned field can declare 0..4294967295.
//   - Unit Exponent data 0..15 is a 4-bit two's-complement nibble (HID 1.11 §6.2.2.7).
//   - A 1- or 2-byte Usage takes the Usage Page in effect when the Usage item is read; a
//     4-byte Usage carries its own page.
//   - Inside a Delimiter set only the first usage counts (as in Linux's hid-core).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace feel::protocol::hid {

enum class MainItemKind : uint8_t { input, output, feature };

// Main item data bits (HID 1.11 §6.2.2.5).
inline constexpr uint32_t kFlagConstant = 0x01;
inline constexpr uint32_t kFlagVariable = 0x02;
inline constexpr uint32_t kFlagRelative = 0x04;
inline constexpr uint32_t kFlagNullState = 0x40;
// Collection types (HID 1.11 §6.2.2.6).
inline constexpr uint8_t kCollectionPhysical = 0x00;
inline constexpr uint8_t kCollectionApplication = 0x01;
inline constexpr uint8_t kCollectionLogical = 0x02;

struct DescriptorField {
    uint32_t bit_offset = 0;     // from the first bit after the Report ID byte (if any)
    uint32_t report_size = 0;    // bits per element, 1..256
    uint32_t report_count = 0;   // elements, 1..65535
    uint32_t flags = 0;          // the main item's data (kFlag*)
    // Extended usages (page << 16 | id) in order, Usage Minimum..Maximum expanded. A Var
    // field with fewer usages than elements repeats the last; an Array field's value
    // selects usages[value - logical_min].
    std::vector<uint32_t> usages;
    int64_t logical_min = 0, logical_max = 0;
    int64_t physical_min = 0, physical_max = 0;
    uint32_t unit = 0;
    int32_t unit_exponent = 0;
    // The usages of the collections around the field, outermost first, and their types
    // (kCollection*), one per usage.
    std::vector<uint32_t> collections;
    std::vector<uint8_t> collection_types;

    [[nodiscard]] bool is_constant() const noexcept { return (flags & kFlagConstant) != 0; }
    [[nodiscard]] bool is_variable() const noexcept { return (flags & kFlagVariable) != 0; }
    [[nodiscard]] bool has_null_state() const noexcept { return (flags & kFlagNullState) != 0; }
    [[nodiscard]] uint32_t bit_length() const noexcept { return report_size * report_count; }
    // The usage of element i (a Var field's last usage repeats); 0 if it has none.
    [[nodiscard]] uint32_t usage_of(std::size_t i) const noexcept {
        if (usages.empty()) return 0;
        return usages[i < usages.size() ? i : usages.size() - 1];
    }
};

struct DescriptorReport {
    MainItemKind kind = MainItemKind::input;
    uint8_t id = 0;             // 0 when the descriptor uses no Report IDs
    uint32_t bit_length = 0;    // all fields, without the Report ID byte
    std::vector<DescriptorField> fields;
};

struct ParsedDescriptor {
    bool uses_report_ids = false;
    std::vector<DescriptorReport> reports;  // in order of first appearance

    // The report of this kind and id; nullptr if the descriptor declares none.
    [[nodiscard]] const DescriptorReport* find(MainItemKind kind, uint8_t id) const noexcept;
};

struct DescriptorParse {
    ParsedDescriptor descriptor;  // meaningful when ok()
    std::string error;            // empty when well formed, else "byte 17: Report Size 0 ..."
    std::size_t error_offset = 0; // the offending item's first byte

    [[nodiscard]] bool ok() const noexcept { return error.empty(); }
};

// Limits a descriptor must keep; beyond them it is refused rather than trusted.
inline constexpr int kMaxCollectionDepth = 32;
inline constexpr int kMaxPushDepth = 16;
inline constexpr uint32_t kMaxReportSizeBits = 256;
inline constexpr uint32_t kMaxReportCount = 65535;
inline constexpr uint32_t kMaxReportBits = 16384 * 8;  // per report
inline constexpr std::size_t kMaxUsagesPerItem = 65536;
inline constexpr std::size_t kMaxUsagesTotal = std::size_t{1} << 20;
inline constexpr std::size_t kMaxFields = 16384;

// Parses a whole descriptor. Never throws for any input (only std::bad_alloc could escape,
// and the limits above keep its memory to tens of megabytes at worst).
[[nodiscard]] DescriptorParse parse_report_descriptor(std::span<const uint8_t> bytes);

}  // namespace feel::protocol::hid
