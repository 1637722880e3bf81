// enumerate_pid_devices: the hidraw nodes whose descriptor (read from sysfs, no permission
// needed) uses the PID page, and what this host can do with each.
#include <cstdio>

#include "descriptor_check.hpp"
#include "feel/host/pid_device.hpp"
#include "feel/protocol/descriptor_parser.hpp"

namespace feel::host {
namespace {

constexpr uint32_t kBusUsb = 0x03;

bool uses_pid_page(const protocol::hid::ParsedDescriptor& d) {
    for (const protocol::hid::DescriptorReport& r : d.reports) {
        for (const protocol::hid::DescriptorField& f : r.fields) {
            for (uint32_t c : f.collections)
                if ((c >> 16) == 0x0F) return true;
            for (uint32_t u : f.usages)
                if ((u >> 16) == 0x0F) return true;
        }
    }
    return false;
}

}  // namespace

std::vector<PidDeviceInfo> enumerate_pid_devices(const transport::HidrawRoots& roots) {
    std::vector<PidDeviceInfo> out;
    for (const transport::HidrawNode& node : transport::list_hidraw_nodes(roots)) {
        const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(node.report_descriptor);
        if (!parse.ok() || !uses_pid_page(parse.descriptor)) continue;
        PidDeviceInfo info;
        info.address = "hidraw:" + node.node;
        if (node.bus == kBusUsb) {
            char ids[16];
            std::snprintf(ids, sizeof ids, "%04x:%04x", node.vendor_id, node.product_id);
            info.usb_address = "usb:" + std::string(ids) + (node.serial.empty() ? "" : ":" + node.serial);
        }
        info.name = node.name;
        info.vendor_id = node.vendor_id;
        info.product_id = node.product_id;
        info.feel_device = check_report_descriptor(node.report_descriptor).empty();
        std::string error;
        if (const std::optional<protocol::pid::PidLayout> layout = protocol::pid::PidLayout::map(parse.descriptor, error)) {
            info.supported_types = layout->supported_types();
        } else {
            info.problem = error;
        }
        out.push_back(std::move(info));
    }
    return out;
}

}  // namespace feel::host
