// feel::transport — HID devices through Linux's hidraw (hidraw:/dev/hidrawN, usb:VID:PID).
//
// hidraw is the kernel's raw view of a HID device: write() sends an output report, read()
// returns the next input report, HIDIOCSFEATURE / HIDIOCGFEATURE set and get a feature
// report (SET_REPORT / GET_REPORT on the control pipe), HIDIOCGRDESC returns the report
// descriptor the device gave at enumeration. A Connection over it carries feel's frames:
//   output_report  -> write()
//   set_feature    -> HIDIOCSFEATURE
//   get_feature    -> HIDIOCGFEATURE, whose reply is the next frame receive() returns
//   get_descriptor -> HIDIOCGRDESC, the same
//   input_report   <- read()
// A device that numbers no reports gets and gives the ID byte 0 in frames, as hidraw wants.
// send() throws TransportError(disconnected) when the device is gone, std::runtime_error
// when it refused one request (a stall), naming the request.
//
// Where the devices are: /sys/class/hidraw/hidrawN/device/ has the HID device's uevent
// (HID_ID bus:vendor:product, HID_NAME, HID_UNIQ — the serial number) and its
// report_descriptor, readable without opening the node. Listing needs no permission;
// opening /dev/hidrawN does (docs/real-devices.md, "hidraw permissions").
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "feel/transport/transport.hpp"

namespace feel::transport {

struct HidrawNode {
    std::string node;        // "/dev/hidraw3"
    std::string name;        // HID_NAME, e.g. "Logitech G29 Driving Force Racing Wheel"
    uint32_t bus = 0;        // BUS_USB 3, BUS_BLUETOOTH 5, ...
    uint16_t vendor_id = 0;
    uint16_t product_id = 0;
    std::string serial;      // HID_UNIQ (empty when the device has none)
    std::vector<uint8_t> report_descriptor;  // from sysfs (empty if unreadable)
};

// Where list_hidraw_nodes looks: the roots of sysfs and of the device nodes (tests point
// them at a fake tree).
struct HidrawRoots {
    std::string sysfs = "/sys";
    std::string dev = "/dev";
};

// Every hidraw node the kernel has, in node-number order. Never throws for a missing or
// unreadable entry: it is listed with what could be read, or skipped when nothing could.
[[nodiscard]] std::vector<HidrawNode> list_hidraw_nodes(const HidrawRoots& roots = {});

// The node of a usb: address: the first USB hidraw node (in node order) with its vendor
// and product IDs and, when the address has one, its serial. Throws TransportError
// (refused) naming the IDs and what is there when none matches.
[[nodiscard]] std::string find_usb_node(const Address& address, const HidrawRoots& roots = {});

// Opens a hidraw: or usb: address. Throws TransportError(refused) when the node does not
// exist, is not a hidraw node, or this user may not open it (then the message says which
// udev rule to add); std::invalid_argument for another kind of address.
[[nodiscard]] std::unique_ptr<Connection> open_hidraw(const Address& address, const HidrawRoots& roots = {});

// The udev rule that gives the logged-in user access to a device's hidraw nodes (one line,
// for /etc/udev/rules.d/70-feel-hidraw.rules).
[[nodiscard]] std::string hidraw_udev_rule(uint16_t vendor_id, uint16_t product_id);

}  // namespace feel::transport
