// feel caps: what a device tells the host about itself (GetCapabilities and EnumEffects,
// §6.2, §7.4), read over the protocol through the host API: the in-process simulated
// device, or a `feel device` process at unix:PATH or tcp:HOST:PORT.
//
// The text is the runtime's print_capabilities, so a device read over a socket prints
// exactly what the same profile prints in process; the lines only a host knows (where the
// device is, its state report rate) follow it.
#include <ostream>
#include <string>

#include "cli.hpp"
#include "feel/host/device.hpp"
#include "feel/runtime/capabilities.hpp"
#include "host_device.hpp"

namespace feel::cli {
namespace {

// The host's view of the capabilities as the runtime's record, for print_capabilities.
// The string views point into `caps`, which must outlive the result.
runtime::Capabilities as_runtime_capabilities(const host::DeviceCaps& caps) {
    runtime::Capabilities r;
    r.device = caps.device;
    r.description = caps.description;
    r.device_class = caps.device_class;
    r.class_name = caps.class_name;
    r.axis_count = caps.axis_count;
    for (int32_t i = 0; i < caps.axis_count && i < kMaxAxes; ++i) {
        const host::AxisCaps& a = caps.axes[i];
        runtime::AxisCapability& out = r.axes[i];
        out.axis = a.axis;
        out.kind = a.rotary ? sim::AxisKind::rotary : sim::AxisKind::linear;
        out.half_travel = a.half_travel;
        out.max_force = a.max_force;
        out.sensor_counts = a.sensor_counts;
        out.resolution = a.sensor_counts > 0 ? 2.0 * a.half_travel / a.sensor_counts : 0.0;
    }
    r.button_count = caps.button_count;
    r.hat_count = caps.hat_count;
    r.dead_man_switch = caps.dead_man_switch;
    r.max_force_normalized = caps.max_force;
    r.supported_types = caps.supported_types;
    r.effect_slots = caps.effect_slots;
    r.pool_bytes = caps.pool_bytes;
    r.sample_memory = caps.sample_memory;
    r.local_reflexes = caps.local_reflexes;
    r.interim_reports = caps.interim_reports;
    r.loop_rate_hz = caps.loop_rate_hz;
    r.max_loop_rate_hz = caps.max_loop_rate_hz;
    r.interim_report_hz = static_cast<float>(caps.interim_report_hz);
    r.firmware_version = caps.firmware_version;
    r.protocol_version = caps.protocol_version;
    return r;
}

}  // namespace

void run_caps(const CapsArgs& args, std::ostream& out) {
    host::Device device = open_device(args.device);
    const host::DeviceCaps& caps = device.capabilities();
    runtime::print_capabilities(out, as_runtime_capabilities(caps));
    out << "state reports:     " << caps.report_rate_hz << " Hz\n"
        << "address:           " << device.address() << '\n';
    device.close();
}

}  // namespace feel::cli
