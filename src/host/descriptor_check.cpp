// Checking a device's report descriptor against the codec, with the protocol's HID
// descriptor parser (feel/protocol/descriptor_parser.hpp: an independent reader that
// refuses malformed descriptors with the offset and the reason).
#include "descriptor_check.hpp"

#include <cstdio>
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

}  // namespace

std::string check_report_descriptor(std::span<const uint8_t> descriptor) {
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(descriptor);
    if (!parse.ok()) return "the report descriptor does not parse: " + parse.error;
    const protocol::hid::ParsedDescriptor& d = parse.descriptor;
    if (!d.uses_report_ids) return "the report descriptor declares no report ids";
    for (const protocol::hid::DescriptorReport& r : d.reports) {
        const auto kind = protocol::report_kind(r.id);
        if (!kind) return "the report descriptor declares " + report_label(r.id) + ", which this host does not know";
        if (*kind != kind_of(r.kind)) {
            return report_label(r.id) + " is declared as " + std::string(kind_name(kind_of(r.kind))) +
                   ", this host expects " + std::string(kind_name(*kind));
        }
        const std::size_t bytes = 1 + static_cast<std::size_t>((r.bit_length + 7) / 8);
        const std::size_t expected = protocol::report_size(r.id);
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
