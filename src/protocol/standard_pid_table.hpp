// The standard PID form of feel's reports (standard_pid.hpp): for each report a standard
// PID device has, the fields of feel's report that are not on feel's vendor page, with
// where each sits in feel's layout. Private to the protocol library (and its tests).
//
// Built from the report table (field_spec.hpp), so the standard descriptor, the translation
// and feel's own codec cannot disagree about a PID field: each standard field is the very
// FieldSpec of feel's report, minus what PID does not have. One field changes: Effect Type
// (Set Effect, Create New Effect) lists PID's eleven usages only, so its 1-based value
// indexes that list, not feel's 33 types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "feel/effect_type.hpp"
#include "field_spec.hpp"

namespace feel::protocol::detail {

struct StandardField {
    FieldSpec spec;                // as the standard descriptor declares it
    std::size_t feel_offset = 0;   // its bit offset in feel's report (the id byte is bits 0..7)
    std::size_t offset = 0;        // its bit offset in the standard report
    bool effect_type = false;      // a PID Effect Type index: mapped, not copied
};

struct StandardReport {
    const ReportSpec* feel = nullptr;  // feel's report of the same id
    std::vector<StandardField> fields;
    std::size_t bytes = 0;             // the standard report's size, id byte included
};

// Every report of the standard device but Joystick Input (its layout is the device's, and
// it has no vendor field: it travels unchanged), in descriptor order.
[[nodiscard]] std::span<const StandardReport> standard_reports() noexcept;
// The one with this id; nullptr when the standard device has no such report.
[[nodiscard]] const StandardReport* find_standard_report(uint8_t id) noexcept;
// Whether a field of feel's report is feel's own (its usage on the vendor page).
[[nodiscard]] bool is_vendor_field(const FieldSpec& field) noexcept;
// The effect types the standard device plays (PID 1.0's eleven); Effect Type's list (the
// eleven, then Custom Force, which it lists but refuses: standard_pid.cpp says why) and the
// list's usages.
[[nodiscard]] std::span<const EffectType> standard_effect_types() noexcept;
[[nodiscard]] std::span<const EffectType> listed_effect_types() noexcept;
[[nodiscard]] std::span<const uint32_t> standard_effect_type_usages() noexcept;

}  // namespace feel::protocol::detail
