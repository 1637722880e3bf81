// feel device: the simulated device and its runtime as a process hosts connect to
// (device_command.hpp, docs/peripheral.md).
#include "device_command.hpp"

#include <grp.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
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

// The shared secret: the file's content (without a final newline), else the environment's.
// A token file others may read is refused: the secret would not be one.
std::string device_token(const DeviceArgs& args) {
    std::string token;
    if (!args.token_file.empty()) {
        struct stat info {};
        if (::stat(args.token_file.c_str(), &info) != 0)
            throw UsageError("--token-file " + args.token_file + " cannot be read");
        if ((info.st_mode & 0077) != 0) {
            throw UsageError("--token-file " + args.token_file +
                             " may be read by others (allowed a mode without group or other access, e.g. 0600)");
        }
        std::ifstream in(args.token_file, std::ios::binary);
        std::ostringstream content;
        content << in.rdbuf();
        if (!in) throw UsageError("--token-file " + args.token_file + " cannot be read");
        token = content.str();
        while (!token.empty() && (token.back() == '\n' || token.back() == '\r')) token.pop_back();
        if (const std::string problem = transport::check_token(token); !problem.empty())
            throw UsageError("--token-file " + args.token_file + ": the token " + problem);
        return token;
    }
    if (const char* from_environment = std::getenv(transport::kTokenEnvironmentVariable)) {
        token = from_environment;
        if (const std::string problem = transport::check_token(token); !problem.empty())
            throw UsageError(std::string("$") + transport::kTokenEnvironmentVariable + ": the token " + problem);
    }
    return token;
}

std::optional<unsigned> group_id(const DeviceArgs& args, const transport::Address& address) {
    if (args.group.empty()) return std::nullopt;
    if (address.kind != transport::Address::Kind::unix_socket)
        throw UsageError("--group is for a unix: socket, not " + address.to_string());
    const struct group* g = ::getgrnam(args.group.c_str());
    if (g == nullptr) throw UsageError("--group \"" + args.group + "\" is not a group on this machine");
    return static_cast<unsigned>(g->gr_gid);
}

transport::Address listen_address(const DeviceArgs& args, std::ostream& err) {
    std::string text = args.listen.empty() ? default_device_address(args.profile) : args.listen;
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
        // The default directory is per user and must be private: else a fresh private one.
        const std::filesystem::path file = std::filesystem::path(address.path).filename();
        const transport::PrivateDir dir =
            transport::private_socket_dir(std::filesystem::path(address.path).parent_path().string());
        if (!dir.warning.empty()) err << "feel device: warning: " << dir.warning << std::endl;
        address.path = (std::filesystem::path(dir.path) / file).string();
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
    options.pid_effects_only = args.pid_effects_only;
    options.standard_pid_only = args.standard_pid_only;
    return options;
}

std::string default_device_address(const std::string& profile) {
    return "unix:" + (std::filesystem::path(transport::default_socket_dir()) / (profile + ".sock")).string();
}

int run_device(const DeviceArgs& args, std::ostream& out, std::ostream& err, std::atomic<bool>& stop) {
    if (!args.sim) {
        throw UsageError("only simulated devices exist yet: run `feel device --sim` (a backend for real "
                         "hardware would run without --sim)");
    }
    const peripheral::PeripheralOptions options = peripheral_options(args);
    const transport::Address wanted = listen_address(args, err);
    transport::ListenOptions access;
    access.allow_remote = args.allow_remote;
    access.token = device_token(args);
    access.group_id = group_id(args, wanted);
    const bool remote = wanted.kind == transport::Address::Kind::tcp && !transport::is_loopback_host(wanted.host);
    if (remote && !args.allow_remote) {
        throw UsageError("--listen " + wanted.to_string() +
                         " is not a loopback address: hosts on other machines could command the device (allowed "
                         "with --allow-remote and a token: --token-file FILE or $" +
                         std::string(transport::kTokenEnvironmentVariable) + ")");
    }
    if (remote && access.token.empty()) {
        throw UsageError("--allow-remote needs a token every host must present (--token-file FILE or $" +
                         std::string(transport::kTokenEnvironmentVariable) + ")");
    }

    const auto started = std::chrono::steady_clock::now();
    peripheral::Peripheral device(options);
    device.serve(transport::listen(wanted, access));
    if (remote) {
        err << "feel device: warning: listening on " << wanted.to_string()
            << ", beyond loopback: any machine that reaches it and knows the token can command the device"
            << std::endl;
    }
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
        << s.reports_refused << " refused), " << s.frames_sent << " frames sent (" << s.reports_dropped
        << " state reports dropped for slow hosts), " << s.hosts_silent << " silent and " << s.hosts_dropped
        << " misbehaving hosts detached; loop " << s.runtime.pipeline.ticks
        << " ticks, " << s.runtime.loop.overruns << " overruns" << std::endl;
    return kExitOk;
}

}  // namespace feel::cli
