// Opening --device and getting it ready (host_device.hpp).
#include "host_device.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "feel/axis.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/transport/transport.hpp"

namespace feel::cli {
namespace {

std::string profile_names() {
    std::string names;
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        names += names.empty() ? "" : ", ";
        names += p.name;
    }
    return names;
}

transport::Address parsed_address(const std::string& address) {
    transport::Address parsed;
    try {
        parsed = transport::Address::parse(address);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--device: ") + e.what());
    }
    if (parsed.kind == transport::Address::Kind::sim && sim::find_device_profile(parsed.profile) == nullptr) {
        throw UsageError("--device \"" + address + "\" is not a known device (available: sim:PROFILE with PROFILE " +
                         "one of " + profile_names() + ", unix:PATH or tcp:HOST:PORT)");
    }
    return parsed;
}

host::Device opened_or_thrown(host::Result<host::Device> device, const transport::Address& parsed) {
    if (!device) {
        const host::Status status = device.status();
        const std::string message = "cannot open device " + parsed.to_string() + ": " + status.message;
        if (status.kind == host::ErrorKind::invalid_parameter) throw UsageError("--device: " + message);
        throw std::runtime_error(message);
    }
    return std::move(device).value();
}

}  // namespace

HandledDevice open_handled_device(const std::string& address, const char* flag) {
    const transport::Address parsed = parsed_address(address);
    if (parsed.kind != transport::Address::Kind::sim) {
        throw UsageError(std::string(flag) + " needs a simulated device (--device sim:PROFILE or PROFILE), not \"" +
                         address + "\": a device on a cable has a hand of its own");
    }
    peripheral::PeripheralOptions options;
    options.profile = parsed.profile;
    auto sim = std::make_unique<peripheral::Peripheral>(options);
    transport::ConnectionPair pair = transport::in_process_pair(parsed.to_string());
    sim->attach(std::move(pair.device));
    host::Device device = opened_or_thrown(host::Device::attach(std::move(pair.host), parsed.to_string()), parsed);
    return HandledDevice{sim::find_device_profile(parsed.profile), std::move(sim), std::move(device)};
}

host::Device open_device(const std::string& address, const host::OpenOptions& options) {
    const transport::Address parsed = parsed_address(address);
    return opened_or_thrown(host::Device::open(parsed.to_string(), options), parsed);
}

void check(const host::Status& status, const std::string& what) {
    if (!status.ok()) throw std::runtime_error(what + ": " + status.message);
}

int32_t use_fastest_reports(host::Device& device) {
    const host::DeviceCaps& caps = device.capabilities();
    const int32_t fastest = std::min(1000, caps.loop_rate_hz);
    if (fastest < 100 || fastest == caps.report_rate_hz) return caps.report_rate_hz;
    check(device.set_report_rate(fastest), "set the state report rate to " + std::to_string(fastest) + " Hz");
    return fastest;
}

bool wait_for_full_strength(host::Device& device, std::chrono::milliseconds limit) {
    using clock = std::chrono::steady_clock;
    const clock::time_point deadline = clock::now() + limit;
    for (;;) {
        const host::InputState state = device.input();
        if (state.reports_received > 0 && state.fade_level >= 1.0f) return true;
        const clock::time_point now = clock::now();
        if (now >= deadline) return false;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now);
        const host::Result<host::InputState> next = device.wait_input(std::max(left, std::chrono::milliseconds(1)));
        if (!next && next.status().kind != host::ErrorKind::timeout) check(next.status(), "read the device's state");
    }
}

std::string axis_label(int32_t axis_index) {
    return std::string(axis_name(static_cast<Axis>(axis_index)));
}

std::string format_forces(const float* force, int32_t axis_count) {
    std::string s;
    for (int32_t a = 0; a < axis_count; ++a) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "%s%s %+8.1f", a == 0 ? "" : "  ", axis_label(a).c_str(),
                      static_cast<double>(force[a]));
        s += buf;
    }
    return s;
}

std::string format_elapsed(double seconds) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3f s", seconds);
    return buf;
}

}  // namespace feel::cli
