// feel device --sim --usb: the simulated device as a real USB HID PID device on the Linux
// gadget stack (docs/usb-device.md).
//
//   feel device --sim --usb [--profile NAME] [--udc NAME | --ffs DIR] [--vid ID] [--pid ID]
//               [--manufacturer TEXT] [--product TEXT] [--serial TEXT] [--log FILE]
//
// Without --ffs (run as root, configfs mounted, libcomposite and usb_f_fs loaded): creates
// the gadget under /sys/kernel/config/usb_gadget/feel, mounts its FunctionFS instance,
// serves it and binds it to the first UDC (or --udc NAME). With --ffs DIR it serves a
// FunctionFS instance someone else mounted and binds. Prints
//   feel device: iforce2 (I-FORCE 2.0) on USB 1209:0001 via dummy_udc.0, loop 1000 Hz
// and runs until SIGINT/SIGTERM; then unbinds, removes the gadget and prints its figures.
#pragma once

#include <atomic>
#include <iosfwd>
#include <string>

#include "device_command.hpp"

namespace feel::cli {

struct UsbDeviceArgs {
    bool usb = false;            // --usb
    std::string udc;             // --udc NAME (empty: the first UDC)
    std::string ffs;             // --ffs DIR: a FunctionFS instance set up by someone else
    std::string vid = "0x1209";  // --vid: vendor ID, 0x0000..0xFFFF (default: pid.codes, test only)
    std::string pid = "0x0001";  // --pid: product ID (default: pid.codes' test product)
    std::string manufacturer = "feel";
    std::string product = "feel force-feedback joystick";
    std::string serial = "0001";
    std::string log;             // --log FILE: one line per host report and refusal
};

// Runs until `stop`. Throws UsageError (exit 2) for a wrong flag (--udc with --ffs, an ID
// out of range, --listen with --usb), std::runtime_error (exit 1) when the gadget cannot be
// set up (naming what is missing).
int run_usb_device(const DeviceArgs& device, const UsbDeviceArgs& usb, std::ostream& out, std::ostream& err,
                   std::atomic<bool>& stop);

// "0x1209", "4617" -> 0x1209; throws UsageError naming the flag and the range 0x0000..0xFFFF.
[[nodiscard]] uint16_t parse_usb_id(const char* flag, const std::string& text);

}  // namespace feel::cli
