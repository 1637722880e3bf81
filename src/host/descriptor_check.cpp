// Checking a device's report descriptor against the codec, with the protocol's HID
// descriptor parser (feel/protocol/descriptor_parser.hpp: an independent reader that
// refuses malformed descriptors with the offset and the reason).
#include "descriptor_check.hpp"

#include <cstdio>
#include <optional>
#include <string_view>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"

namespace feel::host {
namespace {

std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%02X", v);
    return buf;
}

std::string_view kind_name(protocol::ReportKind k) {
    switch (k) {
        case protocol::ReportKind::input: return "an input report";
        case protocol::ReportKind::output: return "an output report";
        case protocol::ReportKind::feature: return "a feature report";
    }
    return "a report";
}

protocol::ReportKind kind_of(protocol::hid::MainItemKind k) {
    switch (k) {
        case protocol::hid::MainItemKind::input: return protocol::ReportKind::input;
        case protocol::hid::MainItemKind::output: return protocol::ReportKind::output;
        case protocol::hid::MainItemKind::feature: return protocol::ReportKind::feature;
    }
    return protocol::ReportKind::input;
}

protocol::hid::MainItemKind main_item_of(protocol::ReportKind k) {
    switch (k) {
        case protocol::ReportKind::input: return protocol::hid::MainItemKind::input;
        case protocol::ReportKind::output: return protocol::hid::MainItemKind::output;
        case protocol::ReportKind::feature: return protocol::hid::MainItemKind::feature;
    }
    return protocol::hid::MainItemKind::input;
}

std::string report_label(uint32_t id) {
    std::string out = "report " + hex(id);
    const std::string_view name = protocol::report_name(static_cast<protocol::ReportId>(id));
    if (!name.empty()) out += " (" + std::string(name) + ")";
    return out;
}

// The joystick inputs the descriptor declares in Joystick Input: Generic Desktop axes
// X..Rz in order, Button usages, Hat Switches. std::nullopt with `why` when it declares
// something else.
std::optional<protocol::JoystickLayout> layout_of(const protocol::hid::DescriptorReport& r, std::string& why) {
    protocol::JoystickLayout layout;
    layout.axis_count = 0;
    layout.button_count = 0;
    layout.hat_count = 0;
    for (const protocol::hid::DescriptorField& f : r.fields) {
        if (f.is_constant() || f.usages.empty()) continue;
        for (uint32_t k = 0; k < f.report_count; ++k) {
            const uint32_t u = f.usage_of(k);
            if (u >= 0x00010030u && u <= 0x00010035u && layout.axis_count < kMaxAxes) {
                layout.axes[layout.axis_count++] = static_cast<Axis>(u - 0x00010030u);
            } else if ((u >> 16) == 0x0009 && layout.button_count < 32) {
                ++layout.button_count;
            } else if (u == 0x00010039u && layout.hat_count < 4) {
                ++layout.hat_count;
            } else {
                why = "Joystick Input declares usage " + hex(u) + ", which is not an axis, a button or a hat this host reads";
                return std::nullopt;
            }
        }
    }
    if (const Error e = protocol::check_layout(layout)) {
        why = "Joystick Input's inputs are not a joystick this host reads: " + e.message();
        return std::nullopt;
    }
    return layout;
}

// A standard PID device's Effect Operation: Loop Count 8 bits (feel's is 16).
bool has_standard_loop_count(const protocol::hid::ParsedDescriptor& d) {
    const auto id = static_cast<uint8_t>(protocol::ReportId::effect_operation);
    const protocol::hid::DescriptorReport* r = d.find(protocol::hid::MainItemKind::output, id);
    if (r == nullptr) return false;
    for (const protocol::hid::DescriptorField& f : r->fields) {
        if (!f.usages.empty() && f.usages.front() == 0x000F007Cu) return f.report_size == 8;
    }
    return false;
}

}  // namespace

std::string check_report_descriptor(std::span<const uint8_t> descriptor, protocol::JoystickLayout* joystick) {
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(descriptor);
    if (!parse.ok()) return "the report descriptor does not parse: " + parse.error;
    const protocol::hid::ParsedDescriptor& d = parse.descriptor;
    if (!d.uses_report_ids) return "the report descriptor declares no report ids";
    if (has_standard_loop_count(d)) {
        return "Effect Operation's Loop Count is 8 bits, as on a standard PID device (where 255 means "
               "infinite and 255 iterations cannot be asked for): this host needs a feel device's 16-bit "
               "loop count, which plays 1..255 iterations and infinite";
    }
    for (const protocol::hid::DescriptorReport& r : d.reports) {
        const auto kind = protocol::report_kind(r.id);
        if (!kind) return "the report descriptor declares " + report_label(r.id) + ", which this host does not know";
        if (*kind != kind_of(r.kind)) {
            return report_label(r.id) + " is declared as " + std::string(kind_name(kind_of(r.kind))) +
                   ", this host expects " + std::string(kind_name(*kind));
        }
        const std::size_t bytes = 1 + static_cast<std::size_t>((r.bit_length + 7) / 8);
        std::size_t expected = protocol::report_size(r.id);
        if (r.id == static_cast<uint8_t>(protocol::ReportId::joystick_input)) {
            std::string why;
            const std::optional<protocol::JoystickLayout> layout = layout_of(r, why);
            if (!layout) return why;
            if (joystick != nullptr) *joystick = *layout;
            expected = protocol::joystick_input_size(*layout);
        }
        if (bytes != expected) {
            return report_label(r.id) + " is declared as " + std::to_string(bytes) + " bytes, this host sends and reads " +
                   std::to_string(expected);
        }
    }
    for (uint32_t id = 1; id < 256; ++id) {
        const auto kind = protocol::report_kind(static_cast<uint8_t>(id));
        if (kind && d.find(main_item_of(*kind), static_cast<uint8_t>(id)) == nullptr) {
            return "the report descriptor does not declare " + report_label(id);
        }
    }
    return {};
}

}  // namespace feel::host
