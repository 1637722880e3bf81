// feel devices: the devices a host can open, as the host API enumerates them — one
// in-process simulated device per profile, then the `feel device` processes that answer on
// the Unix sockets of the socket directory (feel/host/device.hpp, enumerate_devices).
#include <algorithm>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "feel/host/device.hpp"

namespace feel::cli {
namespace {

void cell(std::ostream& out, const std::string& text, std::size_t width) {
    out << text;
    for (std::size_t i = text.size(); i < width + 2; ++i) out << ' ';
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
}

}  // namespace feel::cli
