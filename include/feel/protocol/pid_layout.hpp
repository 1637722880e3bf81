// feel::protocol::pid — any HID PID device's reports, mapped from its own report descriptor.
//
// feel's codec (codec.hpp) speaks one fixed layout: feel's. A force-feedback wheel or stick
// from anywhere declares the same PID 1.0 reports (USB "Device Class Definition for Physical
// Interface Devices", usage page 0x0F) with its own report IDs, field order, sizes and
// logical ranges: one device sends magnitudes as 8 bits 0..255, another as 16 bits
// -10000..10000; one numbers Set Effect 1, another 0x11. A host that is to drive any of them
// must read the layout from the device's descriptor, as Linux's hid-pidff does.
//
// PidLayout is that reading. It takes the descriptor as parsed by the independent parser
// (descriptor_parser.hpp) and finds each PID report by the usage of its collection (Set
// Effect Report 0x21, Set Periodic Report 0x6E, ...), and in it each field by its usage
// (Magnitude 0x70, Duration 0x50, ...), keeping its place (bit offset, size) and its logical
// range. Named arrays (Effect Type, Effect Operation, Device Control, Block Load Status) keep
// their usage list: the value written is the 1-based index of the usage. The effect types
// the device plays are the usages of its Set Effect's Effect Type array that have a report
// for their parameters; the rest are listed as unusable with the reason.
//
// PidReportWriter then fills a report of that layout: values in feel's units (normalized
// levels ±10000, µs, hundredths of a degree) are scaled into the field's logical range the
// way the PID specification defines them (a level's full scale is the logical maximum, a
// full turn the logical range, a time counts units of the field's Unit Exponent, seconds;
// milliseconds when the descriptor says nothing). A value a field cannot hold is an error
// naming the report, the field, the value and what it can hold — never clamped.
//
// Portable: no platform code, no I/O. The host's generic PID device (feel/host/pid_device.hpp)
// uses it over any transport (hidraw, or feel's own sockets).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "feel/effect.hpp"
#include "feel/effect_type.hpp"
#include "feel/engine.hpp"
#include "feel/protocol/descriptor_parser.hpp"

namespace feel::protocol::pid {

// The PID reports a host uses, by the usage of their collection (PID 1.0 §5).
enum class PidReport : uint8_t {
    set_effect,         // Output 0x21
    set_envelope,       // Output 0x5A
    set_condition,      // Output 0x5F
    set_periodic,       // Output 0x6E
    set_constant_force, // Output 0x73
    set_ramp_force,     // Output 0x74
    effect_operation,   // Output 0x77
    block_free,         // Output 0x90
    device_control,     // Output 0x96 (its collection: PID Device Control, or the 0x95 report)
    device_gain,        // Output 0x7D
    create_new_effect,  // Feature 0xAB
    block_load,         // Feature 0x89
    pool,               // Feature 0x7F
    state,              // Input 0x92
    set_custom_force,   // Output 0x6B
    custom_force_data,  // Output 0x68
    download_force_sample,  // Output 0x66: the format of one sample (one value per axis)
};
inline constexpr int kPidReportCount = 17;
[[nodiscard]] std::string_view pid_report_name(PidReport report) noexcept;
// PID 1.0's Effect Type usage for one of feel's types; std::nullopt for feel's types PID has
// no usage for (walls, textures, sweeps, dynamics, ...).
[[nodiscard]] std::optional<uint32_t> pid_type_usage(EffectType type) noexcept;

// One report of the device, as its descriptor declares it.
struct ReportLayout {
    bool present = false;
    hid::MainItemKind kind = hid::MainItemKind::output;
    uint8_t id = 0;                     // 0 when the device numbers no reports
    std::size_t bytes = 0;              // the whole report with its ID byte (hidraw's buffer)
    std::vector<hid::DescriptorField> fields;
};

// Where one value goes: a field's element.
struct FieldPlace {
    const hid::DescriptorField* field = nullptr;
    uint32_t element = 0;  // which element of a Var field
    [[nodiscard]] explicit operator bool() const noexcept { return field != nullptr; }
};

// An effect type the device lists and whether this host can play it there.
struct EffectTypeEntry {
    uint32_t usage = 0;            // the PID (or vendor) usage in Effect Type
    std::optional<EffectType> type;  // feel's type, when the usage is one of PID's eleven
    bool usable = false;
    std::string why_not;           // when !usable: what is missing
};

// The joystick's inputs in the device's own Input report (the first Input report with a
// Generic Desktop axis X..Rz): where each axis, button and hat is. What a host emulation
// layer reads the handle's positions from (a standard PID device reports them there).
struct JoystickInputLayout {
    bool present = false;
    uint8_t id = 0;
    std::size_t bytes = 0;  // with the ID byte
    struct Place {
        uint32_t usage = 0;      // Generic Desktop X..Rz, Button n, Hat Switch
        std::size_t field = 0;   // index into fields
        uint32_t element = 0;
    };
    std::vector<Place> axes, buttons, hats;  // in report order; buttons 1..32, hats 1..4 only
    std::vector<hid::DescriptorField> fields;
};

// One Input report read in feel's units. position[axis_index(a)] for each of the layout's
// axes: the logical value normalized onto ±10000, the middle of the logical range being 0
// (feel's own −10000..10000 reads as is; a 0..1023 wheel's 511.5 is 0). buttons: bit n−1
// for Button n; hats: bit h−1 when hat h is pushed (a value inside its logical range; the
// null state, outside it, is centred).
struct JoystickReading {
    float position[kMaxAxes] = {};
    uint32_t buttons = 0;
    uint32_t hats = 0;
};

class PidLayout {
public:
    // Maps a parsed descriptor. Returns std::nullopt with `error` naming what is missing
    // when it is not a PID device this host can drive (no PID usage page, or one of Set
    // Effect, Effect Operation, Block Free, Create New Effect, Block Load missing).
    [[nodiscard]] static std::optional<PidLayout> map(const hid::ParsedDescriptor& descriptor, std::string& error);
    // Parses and maps descriptor bytes (the parser's error, else map()'s).
    [[nodiscard]] static std::optional<PidLayout> from_bytes(std::span<const uint8_t> descriptor, std::string& error);

    [[nodiscard]] const ReportLayout& report(PidReport r) const noexcept { return reports_[static_cast<int>(r)]; }
    [[nodiscard]] bool uses_report_ids() const noexcept { return uses_report_ids_; }
    // The Effect Type usages of Set Effect, in the descriptor's order.
    [[nodiscard]] const std::vector<EffectTypeEntry>& effect_types() const noexcept { return types_; }
    // effect_type_bit() of every usable type: what emulation may rely on the device for.
    [[nodiscard]] uint64_t supported_types() const noexcept { return supported_; }
    [[nodiscard]] bool supports(EffectType t) const noexcept { return (supported_ & effect_type_bit(t)) != 0; }
    // The largest Effect Block Index of Set Effect (the most effects the descriptor can
    // name); the PID Pool report's Simultaneous Effects Max says what the device holds.
    [[nodiscard]] int64_t max_block_index() const noexcept { return max_block_; }
    // The axes Set Effect's Axes Enable names (Generic Desktop X..Rz), in order.
    [[nodiscard]] const std::vector<Axis>& axes() const noexcept { return axes_; }
    // The joystick's Input report (present false when the descriptor declares no axis input).
    [[nodiscard]] const JoystickInputLayout& joystick_input() const noexcept { return joystick_; }
    // The axes that report a position, in report order.
    [[nodiscard]] std::vector<Axis> input_axes() const;
    // The axes of one custom force sample (Download Force Sample's Generic Desktop X..Rz),
    // in report order: a sample in Custom Force Data is one value for each.
    [[nodiscard]] std::vector<Axis> sample_axes() const;
    // Whether the descriptor has what a custom force needs (Set Custom Force with Sample
    // Count and Sample Period, Custom Force Data with its Offset, a sample format); else
    // false with the reason.
    [[nodiscard]] bool custom_force_ready(std::string& why_not) const;

    // The place of `usage` in report r: a Var field's element whose usage it is, or the
    // Array field that lists it. `within`: only fields inside a collection of that usage
    // (Direction's Ordinals, not Type Specific Block Offset's). Empty when none.
    [[nodiscard]] FieldPlace find(PidReport r, uint32_t usage, uint32_t within = 0) const noexcept;

private:
    ReportLayout reports_[kPidReportCount];
    bool uses_report_ids_ = false;
    std::vector<EffectTypeEntry> types_;
    uint64_t supported_ = 0;
    int64_t max_block_ = 0;
    std::vector<Axis> axes_;
    JoystickInputLayout joystick_;
};

// How a value is read in feel's units before it is scaled into a field.
enum class Scale : uint8_t {
    level,      // normalized, full scale 10000 -> the logical maximum (negative: minimum)
    raw,        // written as is (block index, loop count, byte count, axis index)
    time,       // µs -> the field's time unit (Unit Exponent of seconds; ms if none)
    angle,      // hundredths of a degree 0..36000 -> the logical range (max = 360°)
};

// Fills one report of a layout. Fields the host does not set stay 0 (as hid-pidff leaves
// them). Each setter returns false and sets error() on a value the field cannot hold or a
// field the report lacks when it is required.
class PidReportWriter {
public:
    PidReportWriter(const PidLayout& layout, PidReport report);

    // Sets `usage` (inside collection `within` if given). A missing field is an error
    // when `required`, else ignored.
    bool set(uint32_t usage, int64_t value, Scale scale, bool required = true, uint32_t within = 0);
    // Sets element `element` of the field of `usage` (counted from the usage's first
    // element): a buffer such as Custom Force Data. A missing field is an error.
    bool set_element(uint32_t usage, uint32_t element, int64_t value, Scale scale);
    // Selects `choice` in the named array `array` (Effect Type, Effect Operation, ...).
    bool select(uint32_t array, uint32_t choice);
    // A time that may be infinite (kInfiniteUs): the field's null (all ones, out of its
    // logical range), as PID says.
    bool set_time_or_infinite(uint32_t usage, int64_t us, bool required = true);

    [[nodiscard]] bool ok() const noexcept { return error_.empty(); }
    [[nodiscard]] const std::string& error() const noexcept { return error_; }
    // The bytes, with the report ID first (0 when the device numbers no reports).
    [[nodiscard]] const std::vector<uint8_t>& bytes() const noexcept { return bytes_; }

private:
    bool fail(std::string message);
    bool write(const FieldPlace& place, int64_t logical, uint32_t usage);
    bool scaled_write(const FieldPlace& place, int64_t value, Scale scale, uint32_t usage);
    const PidLayout& layout_;
    PidReport report_;
    std::vector<uint8_t> bytes_;
    std::string error_;
};

// Reads one field of a report the device sent (Block Load, PID Pool, PID State): the
// logical value, sign-extended when the logical minimum is negative. For a named array,
// the selected usage. std::nullopt when the report lacks the field or is too short.
[[nodiscard]] std::optional<int64_t> read_field(const PidLayout& layout, PidReport report,
                                                std::span<const uint8_t> bytes, uint32_t usage);
// Reads the joystick's Input report (bytes with the ID byte first). False when the bytes are
// not that report (another ID, or too short).
[[nodiscard]] bool read_joystick(const PidLayout& layout, std::span<const uint8_t> bytes, JoystickReading& out) noexcept;
[[nodiscard]] std::optional<uint32_t> read_selection(const PidLayout& layout, PidReport report,
                                                     std::span<const uint8_t> bytes, uint32_t array);

// A level's logical value: v in -10000..10000 onto the field's range (hid-pidff's and the
// PID specification's reading: 10000 is the logical maximum; on a signed field -10000 the
// minimum; on an unsigned one 0 the minimum). std::nullopt when v is negative and the field
// unsigned. Exposed for the tests, which check it against the specification's examples.
[[nodiscard]] std::optional<int64_t> level_to_logical(const hid::DescriptorField& f, int64_t v) noexcept;
// A time in µs in the field's unit: counts of 10^exponent s when its Unit is time (the
// time nibble 1, every other dimension 0, any system: 0x1001, 0x1003, ...), else ms.
[[nodiscard]] int64_t time_to_logical(const hid::DescriptorField& f, int64_t us) noexcept;
// Hundredths of a degree onto the logical range, the maximum being a full turn.
[[nodiscard]] int64_t angle_to_logical(const hid::DescriptorField& f, int64_t centidegrees) noexcept;

}  // namespace feel::protocol::pid
