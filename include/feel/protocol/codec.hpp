// feel::protocol — reports to bytes and back, and the HID report descriptor.
//
// One table (src/protocol/report_table.cpp) lists every report's fields in wire order with
// their HID usage, size and logical range. The descriptor is built from it, and so are
// encode() and decode(): they cannot disagree. The tests parse the descriptor with an
// independent HID item parser (descriptor_parser.hpp) and check it against the PID 1.0
// usage tables and against the encoded sizes.
//
// Wire format: a report is [report id][fields...], each field little-endian in the width
// the descriptor gives it, packed with no padding. Every report has a fixed size.
//
// decode() is the device's first line of defence against a hostile host: it never reads
// past the bytes given, never allocates, and rejects (with an Error naming the report, the
// field, the value and the allowed range) an unknown id, a wrong length, a field outside
// its logical range or an enum value that names nothing. It checks one report on its own;
// what a report means for the device's effects is the device session's to check.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "feel/protocol/reports.hpp"
#include "feel/status.hpp"

namespace feel::protocol {

// The report's id, kind and name ("Set Effect"); std::nullopt / empty for an unknown id.
[[nodiscard]] ReportId report_id_of(const AnyReport& report) noexcept;
[[nodiscard]] std::optional<ReportKind> report_kind(uint8_t id) noexcept;
[[nodiscard]] std::string_view report_name(ReportId id) noexcept;
// Bytes of the report on the wire, its id byte included; 0 for an unknown id.
[[nodiscard]] std::size_t report_size(uint8_t id) noexcept;
// The largest report_size of all reports.
[[nodiscard]] std::size_t max_report_size() noexcept;

// Encodes a report: exactly report_size(id) bytes. Values outside a field's wire range
// are the caller's bug: encode() throws std::invalid_argument naming the field and range
// (the host validates before encoding, the device only encodes what it made).
[[nodiscard]] std::vector<uint8_t> encode(const AnyReport& report);

// Decodes one report. On success `out` holds it and the Error is ok; otherwise `out` is
// unspecified and the Error says what is wrong (code invalid_parameter; field like
// "set_effect.gain" or "report.id"/"report.length"). Never allocates, never throws.
[[nodiscard]] Error decode(std::span<const uint8_t> bytes, AnyReport& out) noexcept;

// The HID report descriptor of a feel device: a Joystick application collection (axes,
// buttons, hats and the PID collections, usage page 0x0F) plus the vendor-defined reports
// (usage page 0xFF00). Every feel device has the same descriptor: six axes, 32 buttons and
// four hats are declared, and a device with fewer reports the rest as 0 (its capabilities,
// DeviceInfoReport, say which it has).
[[nodiscard]] std::span<const uint8_t> report_descriptor() noexcept;

}  // namespace feel::protocol
