// feel descriptor: the HID report descriptor a feel device with a profile's inputs answers
// GET_DESCRIPTOR with, for people who build a device (firmware, a USB gadget): as hex
// bytes, as a C array with each item decoded in a comment, or as the decoded items alone,
// indented by collection.
//
// The bytes come from protocol::report_descriptor(layout), the same call a device session
// makes; the decoding here is a plain HID short-item reader (HID 1.11 §6.2.2) that names
// the items and the usage pages feel uses, for reading, not for parsing (the protocol's
// descriptor parser is the parser).
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "flag_checks.hpp"
#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli {
namespace {

std::string hex(uint32_t v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*X", digits, v);
    return buf;
}

// One short item: its bytes and what it says.
struct Item {
    std::size_t offset = 0;
    std::size_t size = 0;  // bytes, prefix included
    uint8_t prefix = 0;
    uint32_t data = 0;
};

std::vector<Item> items_of(std::span<const uint8_t> d) {
    std::vector<Item> items;
    for (std::size_t at = 0; at < d.size();) {
        Item it;
        it.offset = at;
        it.prefix = d[at];
        const std::size_t n = (it.prefix & 3u) == 3u ? 4 : (it.prefix & 3u);
        for (std::size_t k = 0; k < n && at + 1 + k < d.size(); ++k) {
            it.data |= static_cast<uint32_t>(d[at + 1 + k]) << (8 * k);
        }
        it.size = 1 + n;
        items.push_back(it);
        at += it.size;
    }
    return items;
}

int64_t signed_data(const Item& it) {
    switch (it.size - 1) {
        case 1: return static_cast<int8_t>(it.data);
        case 2: return static_cast<int16_t>(it.data);
        case 4: return static_cast<int32_t>(it.data);
        default: return 0;
    }
}

std::string page_name(uint32_t page) {
    switch (page) {
        case 0x01: return "Generic Desktop";
        case 0x09: return "Button";
        case 0x0A: return "Ordinal";
        case 0x0F: return "Physical Interface Device";
        case 0xFF00: return "Vendor 0xFF00 (feel)";
        default: return hex(page, 2);
    }
}

std::string main_flags(uint32_t data) {
    std::string s = (data & 0x01) ? "Cnst" : "Data";
    s += (data & 0x02) ? ",Var" : ",Arr";
    s += (data & 0x04) ? ",Rel" : ",Abs";
    if (data & 0x40) s += ",Null";
    return s;
}

std::string collection_name(uint32_t type) {
    switch (type) {
        case 0x00: return "Physical";
        case 0x01: return "Application";
        case 0x02: return "Logical";
        default: return hex(type, 2);
    }
}

// What an item says: "Usage Page (Physical Interface Device)", "Logical Maximum (10000)".
std::string describe(const Item& it) {
    const uint8_t tag = it.prefix & 0xFCu;
    const uint32_t v = it.data;
    switch (tag) {
        case 0x80: return "Input (" + main_flags(v) + ")";
        case 0x90: return "Output (" + main_flags(v) + ")";
        case 0xB0: return "Feature (" + main_flags(v) + ")";
        case 0xA0: return "Collection (" + collection_name(v) + ")";
        case 0xC0: return "End Collection";
        case 0x04: return "Usage Page (" + page_name(v) + ")";
        case 0x14: return "Logical Minimum (" + std::to_string(signed_data(it)) + ")";
        case 0x24: return "Logical Maximum (" + std::to_string(signed_data(it)) + ")";
        case 0x34: return "Physical Minimum (" + std::to_string(signed_data(it)) + ")";
        case 0x44: return "Physical Maximum (" + std::to_string(signed_data(it)) + ")";
        case 0x54: return "Unit Exponent (" + std::to_string(v >= 8 ? static_cast<int>(v) - 16 : static_cast<int>(v)) + ")";
        case 0x64: return "Unit (" + hex(v, 4) + ")";
        case 0x74: return "Report Size (" + std::to_string(v) + ")";
        case 0x84: return "Report ID (" + hex(v, 2) + ")";
        case 0x94: return "Report Count (" + std::to_string(v) + ")";
        case 0x08:
            return it.size == 5 ? "Usage (" + page_name(v >> 16) + ": " + hex(v & 0xFFFFu, 2) + ")"
                                : "Usage (" + hex(v, 2) + ")";
        case 0x18: return "Usage Minimum (" + hex(v, 2) + ")";
        case 0x28: return "Usage Maximum (" + hex(v, 2) + ")";
        default: return "item " + hex(it.prefix, 2);
    }
}

std::string item_bytes(std::span<const uint8_t> d, const Item& it) {
    std::string s;
    for (std::size_t k = 0; k < it.size && it.offset + k < d.size(); ++k) {
        s += hex(d[it.offset + k], 2) + ", ";
    }
    return s;
}

void print_hex(std::span<const uint8_t> d, std::ostream& out) {
    for (std::size_t i = 0; i < d.size(); ++i) {
        char byte[4];
        std::snprintf(byte, sizeof byte, "%02x", d[i]);
        out << byte << ((i + 1) % 16 == 0 || i + 1 == d.size() ? "\n" : " ");
    }
}

void print_items(std::span<const uint8_t> d, std::ostream& out, bool as_c, const std::string& profile) {
    if (as_c) {
        out << "// The HID report descriptor of a feel device with the \"" << profile
            << "\" profile's inputs (feel descriptor --format c).\n"
            << "static const unsigned char feel_report_descriptor[" << d.size() << "] = {\n";
    }
    int depth = 0;
    for (const Item& it : items_of(d)) {
        if ((it.prefix & 0xFCu) == 0xC0) --depth;
        const std::string indent(static_cast<std::size_t>(2 * (depth < 0 ? 0 : depth)), ' ');
        if (as_c) {
            std::string bytes = "    " + item_bytes(d, it);
            if (bytes.size() < 32) bytes.resize(32, ' ');
            out << bytes << "// " << indent << describe(it) << '\n';
        } else {
            out << indent << describe(it) << '\n';
        }
        if ((it.prefix & 0xFCu) == 0xA0) ++depth;
    }
    if (as_c) out << "};\n";
}

}  // namespace

void run_descriptor(const DescriptorArgs& args, std::ostream& out) {
    const sim::DeviceProfile& profile = checked_profile(args.profile);
    if (args.format != "hex" && args.format != "c" && args.format != "decoded") {
        throw UsageError("--format \"" + args.format + "\" is not a format (allowed: hex, c, decoded)");
    }
    const runtime::Capabilities caps = runtime::capabilities_for(profile);
    const std::vector<uint8_t> d = protocol::report_descriptor(peripheral::joystick_layout(caps));
    if (args.format == "hex") {
        print_hex(d, out);
    } else {
        print_items(d, out, args.format == "c", std::string(profile.name));
    }
}

}  // namespace feel::cli
