// feel devices: the devices a host can open, as the host API enumerates them — one
// in-process simulated device per profile, then the `feel device` processes that answer on
// the Unix sockets of the socket directory (feel/host/device.hpp, enumerate_devices) — and
// every USB HID force-feedback device present, through hidraw (feel/host/pid_device.hpp,
// enumerate_pid_devices).
#include <algorithm>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "feel/host/device.hpp"
#include "feel/host/pid_device.hpp"

namespace feel::cli {
namespace {

void cell(std::ostream& out, const std::string& text, std::size_t width) {
    out << text;
    for (std::size_t i = text.size(); i < width + 2; ++i) out << ' ';
}

std::string types_text(const host::PidDeviceInfo& d) {
    if (!d.problem.empty()) return "unusable: " + d.problem;
    int count = 0;
    for (int t = 0; t < kEffectTypeCount; ++t) count += (d.supported_types >> t) & 1u;
    return std::to_string(count) + " PID effect types";
}

// The HID PID devices present (hidraw nodes whose descriptor uses the PID page 0x0F).
void print_pid_devices(std::ostream& out) {
    const std::vector<host::PidDeviceInfo> devices = host::enumerate_pid_devices();
    out << '\n';
    if (devices.empty()) {
        out << "No USB HID force-feedback device: no hidraw node (/sys/class/hidraw) has a report descriptor "
               "with the PID usage page (0x0F).\n";
        return;
    }
    std::size_t address_width = std::string("hidraw address").size();
    std::size_t usb_width = std::string("usb address").size();
    std::size_t effects_width = std::string("effects").size();
    for (const host::PidDeviceInfo& d : devices) {
        address_width = std::max(address_width, d.address.size());
        usb_width = std::max(usb_width, d.usb_address.size());
        effects_width = std::max(effects_width, types_text(d).size());
    }
    out << "USB HID force-feedback devices (hidraw):\n";
    cell(out, "hidraw address", address_width);
    cell(out, "usb address", usb_width);
    cell(out, "protocol", 8);
    cell(out, "effects", effects_width);
    out << "name\n";
    for (const host::PidDeviceInfo& d : devices) {
        cell(out, d.address, address_width);
        cell(out, d.usb_address.empty() ? "-" : d.usb_address, usb_width);
        cell(out, d.feel_device ? "feel" : "PID", 8);
        cell(out, types_text(d), effects_width);
        out << d.name << '\n';
    }
}

}  // namespace

void run_devices(const DevicesArgs& args, std::ostream& out) {
    host::EnumerateOptions options;
    options.socket_dirs = args.socket_dirs;
    const std::vector<host::DeviceInfo> devices = host::enumerate_devices(options);

    std::size_t address_width = std::string("address").size();
    std::size_t device_width = std::string("device").size();
    std::size_t class_width = std::string("class").size();
    for (const host::DeviceInfo& d : devices) {
        address_width = std::max(address_width, d.address.size());
        device_width = std::max(device_width, d.device.size());
        class_width = std::max(class_width, d.class_name.size());
    }
    cell(out, "address", address_width);
    cell(out, "device", device_width);
    cell(out, "class", class_width);
    out << "description\n";
    for (const host::DeviceInfo& d : devices) {
        cell(out, d.address, address_width);
        cell(out, d.device, device_width);
        cell(out, d.class_name, class_width);
        out << d.description << '\n';
    }
    print_pid_devices(out);
}

}  // namespace feel::cli
