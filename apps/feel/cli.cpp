// The command-line grammar (CLI11) and the one place that turns errors into exit codes.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <exception>
#include <iostream>
#include <optional>
#include <ostream>
#include <vector>

#include "bridge_command.hpp"
#include "cli.hpp"
#include "device_command.hpp"
#include "import_command.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/version.h"
#include "export_command.hpp"
#include "studio_command.hpp"
#include "usb_device_command.hpp"
#include "interrupt.hpp"

namespace feel::cli {
namespace {

constexpr const char* kVersion = "feel " FEEL_VERSION_STRING;
constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 failure (bad file, refused effect, unwritable output), 2 usage "
    "error. Full reference: docs/cli.md\n";

// A command's help footer: the exit codes it can return, its failures (exit 1) named.
// `failures` empty: the command cannot fail once its command line is right.
std::string exit_codes(const char* failures) {
    std::string text = "Exit codes: 0 success";
    if (failures != nullptr && *failures != '\0') text += std::string(", 1 failure (") + failures + ")";
    return text + ", 2 usage error. Full reference: docs/cli.md\n";
}

constexpr const char* kDeviceFailures = "a device that cannot be reached or refuses a command";

void add_render(CLI::App& app, RenderArgs& a, double& duration_s, CLI::Option*& duration) {
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a sensation on a simulated device in closed loop; write the trace as "
                  "CSV (and optionally a plot) and print a summary");
    cmd->add_option("FILE", a.file, "Sensation file (feel/1 JSON)")->required();
    cmd->add_option("--sensation", a.sensation,
                    "Name of the sensation to render (default: the file's only sensation)");
    cmd->add_option("--device", a.device,
                    "Simulated device: sim:PROFILE or PROFILE, PROFILE joystick, wheel, 3axis, "
                    "iforce1 or iforce2 (feel devices)")
        ->capture_default_str();
    cmd->add_option("--motion", a.motion,
                    "Target motion of the hand: hold:X[,Y[,Z]], ramp:AXIS:FROM:TO, "
                    "sine:AXIS:AMPLITUDE:HZ, circle:RADIUS:HZ or csv:PATH")
        ->capture_default_str();
    cmd->add_option("--hand", a.hand, "How the hand holds the handle: none, loose, firm, stiff "
                                      "or kinematic")
        ->capture_default_str();
    duration = cmd->add_option("--duration", duration_s, "Seconds to render, 0 < s <= 600 (default: the "
                                             "sensation's length plus a short tail, or 2 s if "
                                             "it never ends)");
    cmd->add_option("--rate", a.rate_hz, "Loop rate in whole Hz, 100..10000")->capture_default_str();
    cmd->add_option("-o,--output", a.output,
                    "CSV output file, or - for standard output (required unless --plot or --plot-xy is given)");
    cmd->add_option("--plot", a.plot,
                    "Draw force and position against time, with the hand's target, the reported "
                    "position and the walls and barriers, to OUT.svg or OUT.png");
    cmd->add_option("--plot-xy", a.plot_xy,
                    "Draw the x-y plane (2-axis devices): the handle's path, the hand's target, "
                    "walls and barriers, force arrows, to OUT.svg or OUT.png");
    cmd->add_option("--press", a.press,
                    "Buttons and hats to hold down, comma-separated CONTROL@PRESS:RELEASE (seconds): "
                    "BUTTON 1..32 or hatN:DIR, e.g. 1@0.2:0.9,hat2:up@1.5:1.8; effects with a "
                    "trigger start on its presses and repeat while it is held");
    cmd->footer(exit_codes("an unreadable or invalid file, a sensation the engine refuses, an unwritable output"));
}

void add_check(CLI::App& app, CheckArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "check", "Validate a sensation file and list its sensations");
    cmd->add_option("FILE", a.file, "Sensation file (feel/1 JSON)")->required();
    cmd->add_option("--device", a.device,
                    "Also check that each sensation plays on this device (its types, axes, buttons, hats, "
                    "slots and memory): sim:PROFILE, PROFILE, unix:PATH or tcp:HOST:PORT");
    cmd->footer(exit_codes("an unreadable or invalid file; with --device, a sensation that does not play there or a device that cannot be reached"));
}

void add_schema(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "schema", "Print the JSON Schema of the sensation format feel/1 (docs/feel-1.schema.json), for "
                  "editors to complete and check fields");
    cmd->footer(exit_codes(""));
}

constexpr const char* kDeviceHelp =
    "The device: sim:PROFILE (in process; PROFILE joystick, wheel, 3axis, iforce1 or iforce2), "
    "unix:PATH or tcp:HOST:PORT (a `feel device` process), hidraw:/dev/hidrawN or usb:VID:PID[:SERIAL] "
    "(a feel device on USB); a bare PROFILE means sim:PROFILE";

void add_devices(CLI::App& app, DevicesArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "devices", "List the devices a host can open: the in-process simulated devices, the "
                   "`feel device` processes listening on Unix sockets, and every USB HID force-feedback "
                   "(PID) device present, through hidraw");
    cmd->add_option("--socket-dir", a.socket_dirs,
                    "Directory whose Unix sockets are probed (repeatable; default: "
                    "$XDG_RUNTIME_DIR/feel, else /tmp/feel-UID)");
    cmd->footer(exit_codes(""));
}

void add_caps(CLI::App& app, CapsArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "caps", "Print a device's capabilities: axes, buttons, forces, effect types, memory, "
                "loop rate, firmware and protocol versions");
    cmd->add_option("--device", a.device, kDeviceHelp)->capture_default_str();
    cmd->footer(exit_codes(kDeviceFailures));
}

void add_descriptor(CLI::App& app, DescriptorArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "descriptor", "Print the HID report descriptor of a feel device with a profile's axes, buttons "
                      "and hats, for device builders (docs/protocol.md)");
    cmd->add_option("--profile", a.profile, "Device profile whose inputs the descriptor declares")
        ->capture_default_str();
    cmd->add_option("--format", a.format, "hex (bytes), c (a C array, items decoded in comments) or decoded")
        ->capture_default_str();
    cmd->footer(exit_codes(""));
}

void add_play(CLI::App& app, PlayArgs& a, double& seconds, CLI::Option*& seconds_option) {
    CLI::App* cmd = app.add_subcommand(
        "play", "Load a sensation file onto a device and play one sensation, showing the elapsed "
                "time, the force on each axis and the effects' states live, then the peaks");
    cmd->add_option("FILE", a.file, "Sensation file (feel/1 JSON)")->required();
    cmd->add_option("--sensation", a.sensation, "Name of the sensation to play (default: the file's only sensation)");
    cmd->add_option("--device", a.device, kDeviceHelp)->capture_default_str();
    seconds_option = cmd->add_option("--seconds", seconds,
                                     "Stop after this many seconds, 0 < s <= 3600 (default: when the "
                                     "sensation ends, not before the last --press release; one that "
                                     "never ends 10 s after the start or the last release)");
    cmd->add_option("--iterations", a.iterations,
                    "Play each effect this many times: a whole number 1..255 or infinite (default: "
                    "each effect's own count)");
    cmd->add_option("--press", a.press,
                    "Simulated devices only: buttons and hats the hand holds down, as for feel render "
                    "(CONTROL@PRESS:RELEASE, seconds after play), e.g. 1@0.2:0.9,hat2:up@1.5:1.8");
    cmd->footer(exit_codes("an unreadable or invalid file, a sensation the device refuses, a device that cannot be reached"));
}

void add_stream(CLI::App& app, StreamArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "stream", "Force streaming demo (§2.4): the host sends a force waveform on x sample by "
                  "sample; shows the samples next to the force the device applied and how "
                  "faithfully it reconstructed them");
    cmd->add_option("--device", a.device, kDeviceHelp)->capture_default_str();
    cmd->add_option("--rate", a.rate_hz, "Samples per second, a whole number of Hz 1..1000")
        ->capture_default_str();
    cmd->add_option("--seconds", a.seconds, "Seconds to stream, 0 < s <= 600")->capture_default_str();
    cmd->add_option("--shape", a.shape, "Waveform: sine, square, or step (0, then the amplitude "
                                        "from half-way)")
        ->capture_default_str();
    cmd->add_option("--amplitude", a.amplitude, "Amplitude, normalized force 0..10000")->capture_default_str();
    cmd->add_option("--frequency", a.frequency_hz, "Frequency of sine and square, 0 < Hz <= rate / 2")
        ->capture_default_str();
    cmd->footer(exit_codes(kDeviceFailures));
}

void add_monitor(CLI::App& app, MonitorArgs& a, double& seconds, CLI::Option*& seconds_option) {
    CLI::App* cmd = app.add_subcommand(
        "monitor", "Watch a device live: its effects, the force on each axis, the loop rate it "
                   "measures, overruns and the safety state, refreshed 5 times a second");
    cmd->add_option("--device", a.device, kDeviceHelp)->capture_default_str();
    seconds_option = cmd->add_option("--seconds", seconds,
                                     "Stop after this many seconds, 0 < s <= 86400 (default: run until "
                                     "Ctrl-C)");
    cmd->add_option("--sensation", a.sensation,
                    "FILE:NAME: load the sensation file and play this sensation while watching");
    cmd->footer(exit_codes("an unreadable or invalid --sensation file, a device that cannot be reached or refuses a command"));
}

void add_device(CLI::App& app, DeviceArgs& a, UsbDeviceArgs& u) {
    CLI::App* cmd = app.add_subcommand(
        "device", "Run the simulated device and its runtime as a process of its own, like a "
                  "peripheral on a cable: it listens for one host at a time until Ctrl-C or SIGTERM");
    cmd->add_flag("--sim", a.sim, "Run the simulated device (required)");
    cmd->add_option("--profile", a.profile, "Device profile: joystick, wheel, 3axis, iforce1 or iforce2")
        ->capture_default_str();
    cmd->add_option("--listen", a.listen,
                    "Where hosts connect: unix:PATH or tcp:HOST:PORT (port 0: any free port) "
                    "(default: unix:<socket dir>/<profile>.sock, the socket dir as for feel devices)");
    cmd->add_option("--hand", a.hand, "How the simulated hand holds the handle: none, loose, firm, stiff or "
                                      "kinematic")
        ->capture_default_str();
    cmd->add_option("--motion", a.motion, "The hand's target motion, as for feel render")->capture_default_str();
    cmd->add_option("--rate", a.rate_hz, "Loop rate, a whole number of Hz 100..the profile's maximum "
                                         "(default: the profile's rate)");
    cmd->add_flag("--pid-effects-only", a.pid_effects_only,
                  "Play only HID PID 1.0's effect types, like a standard PID device: a feel host renders the "
                  "others itself (host emulation, docs/real-devices.md)");
    cmd->add_flag("--standard-pid-only", a.standard_pid_only,
                  "Be a plain USB HID PID device: a report descriptor with only PID's reports and the joystick's "
                  "Input report, PID's eleven effect types, no vendor report sent (docs/usb-device.md)");
    cmd->add_flag("--allow-remote", a.allow_remote,
                  "Allow a tcp: address that is not loopback (hosts on other machines); needs a token");
    cmd->add_option("--token-file", a.token_file,
                    "A file holding the shared secret every host must present (tcp:HOST:PORT?token=... or "
                    "$FEEL_DEVICE_TOKEN on the host); default: $FEEL_DEVICE_TOKEN, else none");
    cmd->add_option("--group", a.group,
                    "unix: give the socket file to this group, mode 0660 (default: mode 0600, you alone)");
    cmd->add_flag("--usb", u.usb, "Be a USB HID PID device on the Linux gadget stack (configfs + FunctionFS; "
                                  "root; docs/usb-device.md)");
    cmd->add_option("--udc", u.udc, "With --usb: the USB device controller to bind to (default: the first in "
                                    "/sys/class/udc)");
    cmd->add_option("--ffs", u.ffs, "With --usb: serve this mounted FunctionFS instance, set up and bound by "
                                    "someone else");
    cmd->add_option("--vid", u.vid, "With --usb: vendor ID (default 0x1209, pid.codes: test only)")
        ->capture_default_str();
    cmd->add_option("--pid", u.pid, "With --usb: product ID (default 0x0001, pid.codes' test product: test only)")
        ->capture_default_str();
    cmd->add_option("--manufacturer", u.manufacturer, "With --usb: the manufacturer string")->capture_default_str();
    cmd->add_option("--product", u.product, "With --usb: the product string")->capture_default_str();
    cmd->add_option("--serial", u.serial, "With --usb: the serial number string")->capture_default_str();
    cmd->add_option("--log", u.log, "With --usb: write one line per host report and refusal to FILE");
    cmd->footer(exit_codes("the device cannot listen, bind its USB gadget, or read its token file"));
}

void add_bench(CLI::App& app, BenchLoopArgs& a) {
    CLI::App* bench = app.add_subcommand("bench", "Measure the device runtime's performance");
    bench->require_subcommand(1);
    bench->footer(exit_codes("the benchmark cannot run"));
    CLI::App* loop = bench->add_subcommand(
        "loop", "Run the real-time loop with a busy mix of effects on the simulated joystick and "
                "report its period jitter; the last line is p50=..us p99=..us p99.9=..us "
                "overruns=N ticks=N");
    loop->add_option("--rate", a.rate_hz, "Loop rate in whole Hz, 100..20000")->capture_default_str();
    loop->add_option("--seconds", a.seconds, "Seconds to run, 1..3600")->capture_default_str();
    loop->add_option("--cpu", a.cpu, "Pin the loop thread to this CPU, 0..(CPUs - 1); -1: any CPU")->capture_default_str();
    loop->add_flag("--floor", a.floor,
                   "Run the same loop with an empty tick instead of the device's work: the machine's own "
                   "timing floor, to compare the device's figures with");
    loop->footer(exit_codes("the loop cannot run"));
}

constexpr const char* kCommands = "render, check, schema, import, export, devices, caps, descriptor, play, stream, monitor, device, bench, studio, bridge";

void add_bridge(CLI::App& app, BridgeArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "bridge", "Make a feel device a Linux force-feedback joystick through uinput, for games "
                  "(docs/real-devices.md); runs until Ctrl-C");
    cmd->add_option("--device", a.device, kDeviceHelp)->capture_default_str();
    cmd->add_option("--name", a.name, "The input device's name, 0..79 bytes (default: \"feel PROFILE (bridge)\")");
    cmd->add_option("--log", a.log, "Write one line per report the device receives, feature reply and refusal to FILE");
    cmd->add_option("--uinput", a.uinput, "The uinput device node")->capture_default_str();
    cmd->add_flag("--verbose", a.verbose, "Print one line per request of the game: each effect it uploads (in "
                                          "evdev's terms), erase, play, stop, gain and autocenter");
    cmd->footer(exit_codes("uinput missing or not permitted, a device that cannot be reached"));
}

void add_export(CLI::App& app, ExportArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "export", "Write the code that recreates sensations of a file: a C++ program on the §8 wrappers "
                  "and the host API, a C program on feel.h, or the two SensationLibrary calls (docs/cli.md)");
    cmd->add_option("FILE", a.file, "Sensation file (feel/1 JSON)")->required();
    cmd->add_option("--lang", a.lang, "cpp, c or library")->required();
    cmd->add_option("--sensation", a.sensations, "A sensation to export, repeatable (default: all; library: "
                                                 "the file's only one)");
    cmd->add_option("-o,--output", a.output, "Write the code to this file (default: standard output)");
    cmd->footer(exit_codes("an unreadable or invalid file, an unwritable output"));
}

void add_studio(CLI::App& app, StudioArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "studio", "Design sensations in the browser and feel them live: serves the Studio and prints "
                  "the URL to open (docs/studio.md)");
    cmd->add_option("--workspace", a.workspace, "Folder whose *.feel.json files the Studio reads and writes")
        ->capture_default_str();
    cmd->add_option("--device", a.device, kDeviceHelp)->capture_default_str();
    cmd->add_option("--port", a.port, "TCP port, 0..65535 (0: any free port)")->capture_default_str();
    cmd->add_option("--listen", a.listen, "IP address to listen on; anything but loopback is "
                                          "reachable by others (a warning is printed)")
        ->capture_default_str();
    cmd->add_option("--hand", a.hand, "The simulated hand at the start: loose, firm or stiff")
        ->capture_default_str();
    cmd->footer(exit_codes("the Studio cannot listen or read its workspace, a device that cannot be reached"));
}

// The chain of subcommands the command line selected, outermost first.
std::vector<const CLI::App*> chosen(const CLI::App& app) {
    std::vector<const CLI::App*> chain;
    const CLI::App* scope = &app;
    for (;;) {
        const auto subs = scope->get_subcommands();
        if (subs.empty()) return chain;
        scope = subs.front();
        chain.push_back(scope);
    }
}

// "feel render" or "feel bench loop" when the error came from a subcommand, else "feel".
std::string who(const CLI::App& app) {
    std::string name = "feel";
    for (const CLI::App* sub : chosen(app)) name += " " + sub->get_name();
    return name;
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : " ") + s;
    return out;
}

// CLI11 reports a missing required option before an unknown one, and lists leftovers in
// an odd order; a typo in a flag name is the likelier mistake, so name it first.
std::string parse_error_message(const CLI::App& app, std::span<const std::string> args,
                                const CLI::ParseError& e) {
    std::vector<std::string> unknown_flags;
    std::vector<std::string> leftovers;
    std::vector<const CLI::App*> scopes = chosen(app);
    scopes.insert(scopes.begin(), &app);
    for (const CLI::App* a : scopes) {
        for (const std::string& s : a->remaining()) {
            (s.size() > 1 && s[0] == '-' ? unknown_flags : leftovers).push_back(s);
        }
    }
    if (!unknown_flags.empty()) {
        return (unknown_flags.size() == 1 ? "unknown option " : "unknown options ") +
               join(unknown_flags);
    }
    if (app.get_subcommands().empty()) {
        if (args.size() <= 1) return std::string("no command given (available: ") + kCommands + ")";
        if (!args[1].empty() && args[1][0] != '-') {
            return "unknown command \"" + args[1] + "\" (available: " + kCommands + ")";
        }
    }
    if (scopes.back()->get_name() == "bench") {  // "feel bench" without a benchmark
        if (leftovers.empty()) return "no benchmark given (available: loop)";
        return "unknown benchmark \"" + leftovers.front() + "\" (available: loop)";
    }
    return e.what();
}

// Whether the command runs until its work ends or it is asked to stop (signals matter).
bool long_running(const CLI::App& app) {
    for (const char* name : {"device", "play", "stream", "monitor", "studio", "bridge"}) {
        if (app.got_subcommand(name)) return true;
    }
    return false;
}

// Set by run_main: SIGINT and SIGTERM stop the long-running commands cleanly.
bool g_handle_stop_signals = false;

}  // namespace

int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    CLI::App app{"feel renders force-feedback sensations (I-FORCE 2.0 / DirectX 5 effects) on a "
                 "simulated device and plays them on devices through the host API.",
                 "feel"};
    app.set_version_flag("--version", kVersion);
    app.require_subcommand(1);
    app.footer("Run 'feel COMMAND --help' for the options of a command.\n" + std::string(kExitCodes));

    RenderArgs render_args;
    CheckArgs check_args;
    BenchLoopArgs bench_loop_args;
    DevicesArgs devices_args;
    CapsArgs caps_args;
    DescriptorArgs descriptor_args;
    PlayArgs play_args;
    StreamArgs stream_args;
    MonitorArgs monitor_args;
    DeviceArgs device_args;
    UsbDeviceArgs usb_args;
    double duration_s = 0;
    CLI::Option* duration = nullptr;
    double play_seconds = 0;
    CLI::Option* play_seconds_option = nullptr;
    double monitor_seconds = 0;
    CLI::Option* monitor_seconds_option = nullptr;
    add_render(app, render_args, duration_s, duration);
    add_check(app, check_args);
    add_schema(app);
    ImportArgs import_args;
    add_import(app, import_args);
    add_devices(app, devices_args);
    add_caps(app, caps_args);
    add_descriptor(app, descriptor_args);
    add_play(app, play_args, play_seconds, play_seconds_option);
    add_stream(app, stream_args);
    add_monitor(app, monitor_args, monitor_seconds, monitor_seconds_option);
    add_device(app, device_args, usb_args);
    StudioArgs studio_args;
    add_studio(app, studio_args);
    add_bench(app, bench_loop_args);
    BridgeArgs bridge_args;
    add_bridge(app, bridge_args);
    ExportArgs export_args;
    add_export(app, export_args);

    // Progress is redrawn in place only on a terminal (live_output.hpp).
    const bool terminal = &out == &std::cout && ::isatty(STDOUT_FILENO) == 1;
    play_args.terminal = stream_args.terminal = monitor_args.terminal = terminal;

    try {
        std::vector<const char*> argv;
        argv.reserve(args.size());
        for (const std::string& s : args) argv.push_back(s.c_str());
        try {
            app.parse(static_cast<int>(argv.size()), argv.data());
        } catch (const CLI::Success& e) {  // --help, --version
            return app.exit(e, out, err);
        } catch (const CLI::ParseError& e) {
            err << who(app) << ": error: " << parse_error_message(app, args, e) << "\n"
                << "Run '" << who(app) << " --help' for usage.\n";
            return kExitUsage;
        }

        stop_requested().store(false);
        std::optional<ScopedStopSignals> signals;
        if (g_handle_stop_signals && long_running(app)) signals.emplace();

        if (app.got_subcommand("render")) {
            if (duration->count() > 0) render_args.duration_s = duration_s;
            run_render(render_args, out, err);
        } else if (app.got_subcommand("check")) {
            run_check(check_args, out, err);
        } else if (app.got_subcommand("import")) {
            run_import(import_args, out, err);
        } else if (app.got_subcommand("export")) {
            run_export(export_args, out);
        } else if (app.got_subcommand("schema")) {
            out << format::json_schema();
        } else if (app.got_subcommand("devices")) {
            run_devices(devices_args, out);
        } else if (app.got_subcommand("caps")) {
            run_caps(caps_args, out);
        } else if (app.got_subcommand("descriptor")) {
            run_descriptor(descriptor_args, out);
        } else if (app.got_subcommand("play")) {
            if (play_seconds_option->count() > 0) play_args.seconds = play_seconds;
            run_play(play_args, out, err);
        } else if (app.got_subcommand("stream")) {
            run_stream(stream_args, out, err);
        } else if (app.got_subcommand("monitor")) {
            if (monitor_seconds_option->count() > 0) monitor_args.seconds = monitor_seconds;
            run_monitor(monitor_args, out, err);
        } else if (app.got_subcommand("studio")) {
            return run_studio(studio_args, out, err, stop_requested());
        } else if (app.got_subcommand("device")) {
            if (usb_args.usb) return run_usb_device(device_args, usb_args, out, err, stop_requested());
            return run_device(device_args, out, err, stop_requested());
        } else if (app.got_subcommand("bridge")) {
            return run_bridge_command(bridge_args, out, err, stop_requested());
        } else if (app.got_subcommand("bench")) {
            run_bench_loop(bench_loop_args, out, err);  // "loop" is bench's only subcommand
        }
        return kExitOk;
    } catch (const UsageError& e) {
        err << who(app) << ": error: " << e.what() << '\n';
        return kExitUsage;
    } catch (const std::invalid_argument& e) {  // the libraries' option checks name a flag
        err << who(app) << ": error: " << e.what() << '\n';
        return kExitUsage;
    } catch (const std::exception& e) {
        err << who(app) << ": error: " << e.what() << '\n';
        return kExitFailure;
    } catch (...) {
        err << who(app) << ": error: unexpected failure\n";
        return kExitFailure;
    }
}

int run_main(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    g_handle_stop_signals = true;
    return run(args, out, err);
}

}  // namespace feel::cli
