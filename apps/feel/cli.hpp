// The feel command line: subcommands as plain functions, so tests can call them directly.
//
// Exit codes (docs/cli.md):
//   0  success
//   1  the work failed: an unreadable or invalid file, a sensation the engine or the device
//      refuses, an output that cannot be written, a device that cannot be reached
//   2  the command line is wrong: an unknown flag, a missing or out-of-range option, an
//      unknown device, hand or sensation name, a --device that is not an address
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace feel::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// The device every host command uses without --device: the in-process simulated I-FORCE
// 2.0-class joystick, so that the commands work on a fresh machine.
inline constexpr const char* kDefaultDeviceAddress = "sim:iforce2";

// A mistake on the command line (exit code 2). Anything else thrown is a failure (1),
// except std::invalid_argument from the libraries, which also names a flag (2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RenderArgs {
    std::string file;
    std::string sensation;
    std::string device = "joystick";
    std::string motion = "hold:0";
    std::string hand = "firm";
    std::optional<double> duration_s;  // unset: the sensation's own length
    double rate_hz = 1000;
    std::string output;                // CSV path, "-" for stdout
    std::string plot;                  // empty: no plot
    std::string plot_xy;               // --plot-xy: the x-y plane; empty: none
    std::string press;                 // --press list (render::parse_presses); empty: none
};

struct CheckArgs {
    std::string file;
    std::string device;  // empty: the format only; else also whether each sensation plays there
};

struct DevicesArgs {
    // Directories whose Unix sockets are probed for `feel device` processes; empty: the
    // default socket directory (transport::default_socket_dir()).
    std::vector<std::string> socket_dirs;
};

struct CapsArgs {
    std::string device = kDefaultDeviceAddress;  // sim:PROFILE, unix:PATH, tcp:HOST:PORT or PROFILE
};

struct DescriptorArgs {
    std::string profile = "iforce2";  // a built-in device profile: its inputs shape the descriptor
    std::string format = "hex";       // hex, c or decoded
};
struct BenchLoopArgs {
    double rate_hz = 1000;  // whole Hz, runtime::kMinLoopRateHz..kMaxLoopRateHz
    double seconds = 60;    // 1..3600
    double cpu = -1;        // the loop thread's CPU, 0..CPUs−1, or −1: any (a double: checked whole)
    bool floor = false;     // an empty tick: the machine's timing floor under the same loop
};

// The commands that run for a while redraw one status line (or block) in place when
// standard output is a terminal, and print plain lines otherwise (pipes, files, tests).
struct PlayArgs {
    std::string file;
    std::string sensation;
    std::string device = kDefaultDeviceAddress;
    std::optional<double> seconds;     // unset: until the sensation ends (play_command.cpp's play_limit)
    std::string iterations;            // empty: each effect's own count; "infinite" or a whole 1..254
    std::string press;                 // --press list (render::parse_presses), sim: devices only
    bool terminal = false;             // redraw the progress line in place
};
// How long `feel play` lets a sensation run without --seconds: one that never ends (an
// infinite duration or iteration count) is stopped this many seconds after the start, or
// after the last release of --press; one that ends is given this long beyond its end.
inline constexpr double kPlayDefaultCapS = 10;

struct StreamArgs {
    std::string device = kDefaultDeviceAddress;
    double rate_hz = 60;        // samples per second, whole Hz 1..1000
    double seconds = 3;         // 0 < s <= 600
    std::string shape = "sine"; // sine, square or step
    double amplitude = 5000;    // 0..10000 (normalized force)
    double frequency_hz = 1;    // sine and square: 0 < F <= rate / 2
    bool terminal = false;
};

struct MonitorArgs {
    std::string device = kDefaultDeviceAddress;
    std::optional<double> seconds;  // unset: until interrupted (Ctrl-C)
    std::string sensation;          // "FILE:NAME" to play while watching; empty: none
    bool terminal = false;
};

// Each writes its results to `out` and its diagnostics to `err`, and throws on error.
void run_render(const RenderArgs& args, std::ostream& out, std::ostream& err);
void run_check(const CheckArgs& args, std::ostream& out, std::ostream& err);
// feel devices: the devices a host can open (in-process simulated ones and `feel device`
// processes listening on Unix sockets).
void run_devices(const DevicesArgs& args, std::ostream& out);
// feel caps: a device's capabilities, read through the host API (docs/cli.md).
void run_caps(const CapsArgs& args, std::ostream& out);
// feel descriptor: the HID report descriptor of a device with the profile's inputs.
void run_descriptor(const DescriptorArgs& args, std::ostream& out);
// feel bench loop: the real-time loop's period jitter under a busy mix (docs/runtime.md).
void run_bench_loop(const BenchLoopArgs& args, std::ostream& out, std::ostream& err);
// feel play: load a sensation file onto a device, play one sensation, show its force live.
void run_play(const PlayArgs& args, std::ostream& out, std::ostream& err);
// feel stream: the host closes the loop, streaming a force waveform (§2.4).
void run_stream(const StreamArgs& args, std::ostream& out, std::ostream& err);
// feel monitor: the device's effects, forces, loop rate and safety state, live.
void run_monitor(const MonitorArgs& args, std::ostream& out, std::ostream& err);

// The whole command line: args[0] is the program name. Never throws; returns the exit code.
[[nodiscard]] int run(std::span<const std::string> args, std::ostream& out, std::ostream& err);

// What main() calls: run(), with SIGINT and SIGTERM handled while a long-running command
// (device, play, stream, monitor) runs, so that it stops cleanly and still prints its
// summary. A second signal of the same kind ends the process the default way.
[[nodiscard]] int run_main(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace feel::cli
