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

// The joystick inputs a device has. They fix Joystick Input's layout, and so the joystick
// part of the device's descriptor: only the axes, buttons and hats the device has are
// declared (a standard host makes exactly those its inputs). Each axis is a 16-bit Generic
// Desktop axis (X..Rz as listed), the buttons one bit each (Button 1..n), each hat a
// 4-bit Hat Switch (0x39) with 8 directions 0..7 and a null state (15, centred); fields
// are padded to whole bytes.
struct JoystickLayout {
    uint8_t axis_count = kMaxAxes;                                             // 1..6
    Axis axes[kMaxAxes] = {Axis::x, Axis::y, Axis::z, Axis::rx, Axis::ry, Axis::rz};  // in report order
    uint8_t button_count = 32;                                                 // 0..32
    uint8_t hat_count = 4;                                                     // 0..4

    friend bool operator==(const JoystickLayout&, const JoystickLayout&) = default;
};
// Whether a layout is within those limits (each axis at most once); else why not.
[[nodiscard]] Error check_layout(const JoystickLayout& layout) noexcept;

// The HID report descriptor of a feel device with every input (JoystickLayout{}: six
// axes, 32 buttons, four hats): a Joystick application collection with the joystick's
// inputs and the PID collections (usage page 0x0F), plus the vendor-defined reports (usage
// page 0xFF00). encode() and decode() of a JoystickInputReport use this layout.
[[nodiscard]] std::span<const uint8_t> report_descriptor() noexcept;
// The descriptor of a device with these inputs (check_layout must pass): what a device
// answers get_descriptor with, and what `feel descriptor --profile P` prints.
[[nodiscard]] std::vector<uint8_t> report_descriptor(const JoystickLayout& layout);

// Joystick Input in a device's own layout: its size (id byte included), encode (the
// position of axis k is position[k]) and decode (never allocates, never throws; errors as
// decode()'s). A pushed hat travels as direction 0 (north): feel's hats know pushed and
// centred only (the primer's triggers need no more); any direction decodes as pushed.
[[nodiscard]] std::size_t joystick_input_size(const JoystickLayout& layout) noexcept;
[[nodiscard]] std::vector<uint8_t> encode(const JoystickInputReport& report, const JoystickLayout& layout);
[[nodiscard]] Error decode(std::span<const uint8_t> bytes, const JoystickLayout& layout,
                           JoystickInputReport& out) noexcept;

}  // namespace feel::protocol
