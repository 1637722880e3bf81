// The command-line grammar (CLI11) and the one place that turns errors into exit codes.
#include <CLI/CLI.hpp>

#include <exception>
#include <ostream>
#include <vector>

#include "cli.hpp"

namespace feel::cli {
namespace {

constexpr const char* kVersion = "feel " FEEL_VERSION;
constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 failure (bad file, refused effect, unwritable output), 2 usage "
    "error. Full reference: docs/cli.md\n";

void add_render(CLI::App& app, RenderArgs& a, double& duration_s, CLI::Option*& duration) {
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a sensation on a simulated device in closed loop; write the trace as "
                  "CSV (and optionally a plot) and print a summary");
    cmd->add_option("FILE", a.file, "Sensation file (feel/1 JSON)")->required();
    cmd->add_option("--sensation", a.sensation, "Name of the sensation to render")->required();
    cmd->add_option("--device", a.device,
                    "Simulated device: joystick, wheel, 3axis, iforce1 or iforce2 (feel devices)")
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
    cmd->add_option("-o,--output", a.output, "CSV output file, or - for standard output")
        ->required();
    cmd->add_option("--plot", a.plot, "Also draw force and position to OUT.svg or OUT.png");
    cmd->footer(kExitCodes);
}

void add_check(CLI::App& app, CheckArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "check", "Validate a sensation file and list its sensations");
    cmd->add_option("FILE", a.file, "Sensation file (feel/1 JSON)")->required();
    cmd->footer(kExitCodes);
}

void add_devices(CLI::App& app) {
    app.add_subcommand("devices", "List the simulated device profiles")->footer(kExitCodes);
}

void add_caps(CLI::App& app, CapsArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "caps", "Print a device's capabilities: axes, buttons, forces, effect types, memory, "
                "loop rate, firmware and protocol versions");
    cmd->add_option("--device", a.device,
                    "Simulated device: joystick, wheel, 3axis, iforce1 or iforce2 (feel devices)")
        ->capture_default_str();
    cmd->footer(kExitCodes);
}

void add_bench(CLI::App& app, BenchLoopArgs& a) {
    CLI::App* bench = app.add_subcommand("bench", "Measure the device runtime's performance");
    bench->require_subcommand(1);
    bench->footer(kExitCodes);
    CLI::App* loop = bench->add_subcommand(
        "loop", "Run the real-time loop with a busy mix of effects on the simulated joystick and "
                "report its period jitter; the last line is p50=..us p99=..us p99.9=..us "
                "overruns=N ticks=N");
    loop->add_option("--rate", a.rate_hz, "Loop rate in whole Hz, 100..20000")->capture_default_str();
    loop->add_option("--seconds", a.seconds, "Seconds to run, 1..3600")->capture_default_str();
    loop->footer(kExitCodes);
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
        if (args.size() <= 1) return "no command given (available: render, check, devices, caps, bench)";
        if (!args[1].empty() && args[1][0] != '-') {
            return "unknown command \"" + args[1] + "\" (available: render, check, devices, caps, bench)";
        }
    }
    if (scopes.back()->get_name() == "bench") {  // "feel bench" without a benchmark
        if (leftovers.empty()) return "no benchmark given (available: loop)";
        return "unknown benchmark \"" + leftovers.front() + "\" (available: loop)";
    }
    return e.what();
}

}  // namespace

int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    CLI::App app{"feel renders force-feedback sensations (I-FORCE 2.0 / DirectX 5 effects) on a "
                 "simulated device.",
                 "feel"};
    app.set_version_flag("--version", kVersion);
    app.require_subcommand(1);
    app.footer("Run 'feel COMMAND --help' for the options of a command.\n" + std::string(kExitCodes));

    RenderArgs render_args;
    CheckArgs check_args;
    BenchLoopArgs bench_loop_args;
    CapsArgs caps_args;
    double duration_s = 0;
    CLI::Option* duration = nullptr;
    add_render(app, render_args, duration_s, duration);
    add_check(app, check_args);
    add_devices(app);
    add_caps(app, caps_args);
    add_bench(app, bench_loop_args);

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

        if (app.got_subcommand("render")) {
            if (duration->count() > 0) render_args.duration_s = duration_s;
            run_render(render_args, out, err);
        } else if (app.got_subcommand("check")) {
            run_check(check_args, out, err);
        } else if (app.got_subcommand("devices")) {
            run_devices(out);
        } else if (app.got_subcommand("caps")) {
            run_caps(caps_args, out);
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

}  // namespace feel::cli
