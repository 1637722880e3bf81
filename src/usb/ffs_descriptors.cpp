// FunctionFS descriptors and strings (ffs_descriptors.hpp). Every multi-byte field is
// little-endian, as USB and FunctionFS's headers both say.
#include "ffs_descriptors.hpp"

#include <linux/usb/ch9.h>
#include <linux/usb/functionfs.h>

#include <stdexcept>

namespace feel::usb::detail {
namespace {

void put16(std::vector<uint8_t>& out, uint16_t v) {
    out.push_back(static_cast<uint8_t>(v & 0xFF));
    out.push_back(static_cast<uint8_t>(v >> 8));
}
void put32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>((v >> (8 * i)) & 0xFF));
}
void patch32(std::vector<uint8_t>& out, std::size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) out[at + static_cast<std::size_t>(i)] = static_cast<uint8_t>((v >> (8 * i)) & 0xFF);
}

// One speed's set: interface, HID, endpoint IN, endpoint OUT (4 descriptors).
void put_speed_set(std::vector<uint8_t>& out, uint16_t report_bytes, uint16_t packet, uint8_t interval) {
    // Interface: number 0, alternate 0, two endpoints, HID class, no subclass or protocol,
    // string 1 (the interface's name).
    out.insert(out.end(), {USB_DT_INTERFACE_SIZE, USB_DT_INTERFACE, 0, 0, 2, USB_CLASS_HID, 0, 0, 1});
    const auto hid = hid_class_descriptor(report_bytes);
    out.insert(out.end(), hid.begin(), hid.end());
    for (const uint8_t address : {kEndpointInAddress, kEndpointOutAddress}) {
        out.insert(out.end(), {USB_DT_ENDPOINT_SIZE, USB_DT_ENDPOINT, address, USB_ENDPOINT_XFER_INT});
        put16(out, packet);
        out.push_back(interval);
    }
}

}  // namespace

std::array<uint8_t, 9> hid_class_descriptor(uint16_t report_descriptor_bytes) {
    return {9,
            0x21,  // HID
            static_cast<uint8_t>(kBcdHid & 0xFF),
            static_cast<uint8_t>(kBcdHid >> 8),
            0,     // country: not localized
            1,     // one class descriptor follows
            0x22,  // of type Report
            static_cast<uint8_t>(report_descriptor_bytes & 0xFF),
            static_cast<uint8_t>(report_descriptor_bytes >> 8)};
}

std::vector<uint8_t> function_descriptors(std::size_t report_descriptor_bytes) {
    if (report_descriptor_bytes > 0xFFFF) {
        throw std::invalid_argument("the report descriptor has " + std::to_string(report_descriptor_bytes) +
                                    " bytes; a HID descriptor can announce at most 65535");
    }
    const auto report_bytes = static_cast<uint16_t>(report_descriptor_bytes);
    std::vector<uint8_t> out;
    put32(out, FUNCTIONFS_DESCRIPTORS_MAGIC_V2);
    put32(out, 0);  // length, patched below
    put32(out, FUNCTIONFS_HAS_FS_DESC | FUNCTIONFS_HAS_HS_DESC);
    put32(out, 4);  // full-speed descriptors
    put32(out, 4);  // high-speed descriptors
    put_speed_set(out, report_bytes, kFullSpeedPacketBytes, kFullSpeedInterval);
    put_speed_set(out, report_bytes, kHighSpeedPacketBytes, kHighSpeedInterval);
    patch32(out, 4, static_cast<uint32_t>(out.size()));
    return out;
}

std::vector<uint8_t> function_strings(const std::string& interface_name) {
    std::vector<uint8_t> out;
    put32(out, FUNCTIONFS_STRINGS_MAGIC);
    put32(out, 0);  // length, patched below
    put32(out, 1);  // strings per language
    put32(out, 1);  // languages
    put16(out, 0x0409);
    out.insert(out.end(), interface_name.begin(), interface_name.end());
    out.push_back(0);
    patch32(out, 4, static_cast<uint32_t>(out.size()));
    return out;
}

}  // namespace feel::usb::detail
