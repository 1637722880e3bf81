// DeviceInfoReport -> DeviceCaps / DeviceInfo.
#include "device_info.hpp"

#include <cstring>
#include <string>

#include "feel/runtime/capabilities.hpp"

namespace feel::host {
namespace {

template <std::size_t N>
std::string text(const char (&field)[N]) {
    return std::string(field, strnlen(field, N));
}

sim::DeviceClass device_class_of(uint8_t value) {
    // decode() has checked the range (1..2): the wire's numbers are DeviceClass's.
    return static_cast<sim::DeviceClass>(value);
}

}  // namespace

DeviceCaps caps_from_info(const protocol::DeviceInfoReport& info) {
    DeviceCaps c;
    c.device = text(info.device);
    c.description = text(info.description);
    c.device_class = device_class_of(info.device_class);
    c.class_name = std::string(sim::device_class_name(c.device_class));
    c.firmware_version = text(info.firmware_version);
    // The protocol runtime::kProtocolVersion names, at the vendor revision the device speaks.
    c.protocol_version = "HID PID 1.0 + feel vendor " + std::to_string(info.vendor_revision);
    c.axis_count = info.axis_count;
    for (int i = 0; i < kMaxAxes && i < info.axis_count; ++i) {
        const protocol::AxisInfo& a = info.axes[i];
        c.axes[i].axis = a.axis;
        c.axes[i].rotary = a.rotary != 0;
        c.axes[i].half_travel = static_cast<double>(a.half_travel_micro) / 1e6;
        c.axes[i].max_force = static_cast<double>(a.max_force_milli) / 1e3;
        c.axes[i].sensor_counts = static_cast<int32_t>(a.sensor_counts);
    }
    c.button_count = info.button_count;
    c.hat_count = info.hat_count;
    c.dead_man_switch = info.dead_man_switch;
    c.max_force = info.max_force;
    c.supported_types = info.supported_types;
    c.effect_slots = info.effect_slots;
    c.pool_bytes = static_cast<int32_t>(info.pool_bytes);
    c.sample_memory = static_cast<int32_t>(info.sample_memory);
    c.local_reflexes = info.local_reflexes;
    c.interim_reports = info.interim_reports;
    c.loop_rate_hz = info.loop_rate_hz;
    c.max_loop_rate_hz = info.max_loop_rate_hz;
    c.interim_report_hz = static_cast<double>(info.interim_report_centihz) / 100.0;
    c.report_rate_hz = info.report_rate_hz;
    return c;
}

DeviceInfo device_info_from(const protocol::DeviceInfoReport& info, std::string address) {
    const DeviceCaps caps = caps_from_info(info);
    DeviceInfo d;
    d.address = std::move(address);
    d.device = caps.device;
    d.description = caps.description;
    d.class_name = caps.class_name;
    d.in_process = false;
    return d;
}

}  // namespace feel::host
