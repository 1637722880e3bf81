// feel device: the simulated device and its runtime as a process hosts connect to
// (device_command.hpp, docs/peripheral.md).
#include "device_command.hpp"

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include "cli.hpp"
#include "flag_checks.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/runtime/realtime_loop.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/transport/transport.hpp"

namespace feel::cli {
namespace {

using namespace std::chrono_literals;

constexpr auto kStopPoll = 20ms;

void check_hand(const std::string& name) {
    if (sim::grip_from_name(name)) return;
    std::string names;
    for (sim::Grip g : {sim::Grip::none, sim::Grip::loose, sim::Grip::firm, sim::Grip::stiff, sim::Grip::kinematic}) {
        names += names.empty() ? "" : ", ";
        names += sim::grip_name(g);
    }
    throw UsageError("--hand \"" + name + "\" is not a hand (allowed: " + names + ")");
}

int32_t checked_rate(double rate_hz, const sim::DeviceProfile& profile) {
    const int32_t max = std::min(profile.max_loop_rate_hz, runtime::kMaxLoopRateHz);
    const bool whole = std::isfinite(rate_hz) && std::floor(rate_hz) == rate_hz;
    if (whole && rate_hz == 0) return 0;
    if (!whole || rate_hz < runtime::kMinLoopRateHz || rate_hz > max) {
        throw UsageError("--rate = " + number(rate_hz) + " Hz is out of range (allowed a whole number of Hz, " +
                         std::to_string(runtime::kMinLoopRateHz) + ".." + std::to_string(max) + " on the " +
                         std::string(profile.name) + ", or 0 for its default " +
                         std::to_string(profile.default_loop_rate_hz) + " Hz)");
    }
    return static_cast<int32_t>(rate_hz);
}

void check_motion(const std::string& spec, const sim::DeviceProfile& profile) {
    try {
        (void)sim::TargetMotion::parse(spec, 60, profile.axis_count);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--motion: ") + e.what());
    }
}

transport::Address listen_address(const DeviceArgs& args) {
    const std::string text = args.listen.empty() ? default_device_address(args.profile) : args.listen;
    transport::Address address;
    try {
        address = transport::Address::parse_listen(text);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--listen: ") + e.what());
    }
    if (address.kind == transport::Address::Kind::sim) {
        throw UsageError("--listen \"" + text +
                         "\" is not a place to listen (allowed unix:PATH or tcp:HOST:PORT; sim: devices run "
                         "inside their host)");
    }
    if (args.listen.empty()) {
        // The default directory is per user: made private, as a runtime directory is.
        const std::filesystem::path dir = std::filesystem::path(address.path).parent_path();
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (ec) throw std::runtime_error("cannot create the socket directory " + dir.string() + ": " + ec.message());
        if (::chmod(dir.c_str(), 0700) != 0) {
            throw std::runtime_error("cannot make the socket directory " + dir.string() + " private (mode 0700)");
        }
    }
    return address;
}

}  // namespace

peripheral::PeripheralOptions peripheral_options(const DeviceArgs& args) {
    const sim::DeviceProfile& profile = checked_profile(args.profile);
    check_hand(args.hand);
    check_motion(args.motion, profile);
    peripheral::PeripheralOptions options;
    options.profile = args.profile;
    options.hand = args.hand;
    options.motion = args.motion;
    options.loop_rate_hz = checked_rate(args.rate_hz, profile);
    return options;
}

std::string default_device_address(const std::string& profile) {
    return "unix:" + (std::filesystem::path(transport::default_socket_dir()) / (profile + ".sock")).string();
}

int run_device(const DeviceArgs& args, std::ostream& out, std::ostream& /*err*/, std::atomic<bool>& stop) {
    if (!args.sim) {
        throw UsageError("only simulated devices exist yet: run `feel device --sim` (a backend for real "
                         "hardware would run without --sim)");
    }
    const peripheral::PeripheralOptions options = peripheral_options(args);
    const transport::Address wanted = listen_address(args);

    const auto started = std::chrono::steady_clock::now();
    peripheral::Peripheral device(options);
    device.serve(transport::listen(wanted));
    const transport::Address address = device.address();
    const runtime::Capabilities& caps = device.capabilities();
    out << "feel device: " << caps.device << " (" << caps.class_name << ") listening on " << address.to_string()
        << ", loop " << device.runtime().config().loop_rate_hz << " Hz" << std::endl;

    while (!stop.load(std::memory_order_relaxed)) std::this_thread::sleep_for(kStopPoll);

    device.stop();  // closes the listener (its socket file goes) and detaches the host
    if (address.kind == transport::Address::Kind::unix_socket) {
        std::error_code ec;
        std::filesystem::remove(address.path, ec);  // in case the listener left it
    }
    const peripheral::PeripheralStats s = device.stats();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    char uptime[32];
    std::snprintf(uptime, sizeof uptime, "%.1f", seconds);
    out << "feel device: stopped after " << uptime << " s: " << s.hosts_served << " host"
        << (s.hosts_served == 1 ? "" : "s") << " served, " << s.reports_received << " reports received ("
        << s.reports_refused << " refused), " << s.frames_sent << " frames sent; loop " << s.runtime.pipeline.ticks
        << " ticks, " << s.runtime.loop.overruns << " overruns" << std::endl;
    return kExitOk;
}

}  // namespace feel::cli
