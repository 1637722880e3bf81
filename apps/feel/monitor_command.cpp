// feel monitor: a live view of a device — its loop, the force on each axis, the safety
// state and the effects — refreshed five times a second.
//
// Everything shown comes from the device's state reports (Device::input(), no round trip):
// the loop rate the device measured over its last second next to its nominal rate, its
// overruns (ticks that started after the next one was due), the input reports (state
// rounds, pages, PID states, dynamics' reports) that arrived per second here, the forces its motors got, the dead-man switch, the safety
// fade, the hands-off and host-lost flags, pause, actuators and gain. A device serves one
// host at a time, so the effects on it are this host's: with --sensation FILE:NAME the
// monitor loads the file, plays that sensation and lists its effects (block, type, state,
// asked over the protocol); without, it shows the device's counts only.
#include <chrono>
#include <cstdio>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli.hpp"
#include "feel/effect_type.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/host/device.hpp"
#include "feel/host/sensation_library.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "flag_checks.hpp"
#include "host_device.hpp"
#include "interrupt.hpp"
#include "live_output.hpp"

namespace feel::cli {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kMaxSeconds = 86400;
constexpr auto kRefreshPeriod = std::chrono::milliseconds(200);
constexpr auto kPollPeriod = std::chrono::milliseconds(10);  // for the stop flag between refreshes

struct SensationChoice {
    std::string file;
    std::string name;
};

SensationChoice parse_sensation(const std::string& text) {
    const std::size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
        throw UsageError("--sensation \"" + text + "\" is not FILE:NAME (a sensation file and the name of one of its "
                         "sensations, e.g. examples/primer.feel.json:railing_impact)");
    }
    SensationChoice c{text.substr(0, colon), text.substr(colon + 1)};
    const format::SensationFile file = format::load_sensation_file(c.file);
    if (file.find(c.name) == nullptr) {
        std::string names;
        for (const format::Sensation& s : file.sensations) names += (names.empty() ? "" : ", ") + s.name;
        if (names.empty()) names = "none: the file holds no sensations";
        throw UsageError("--sensation: \"" + c.name + "\" is not in " + c.file + " (available: " + names + ")");
    }
    return c;
}

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string safety_line(const host::InputState& s, const host::DeviceCaps& caps) {
    std::string line = "safety   ";
    if (caps.dead_man_switch) line += s.handle_held ? "handle held, " : "handle NOT held (no force), ";
    line += "fade " + fixed(s.fade_level, 2) + ", actuators " + (s.actuators_enabled ? "on" : "OFF") + ", gain " +
            std::to_string(s.gain);
    if (s.paused) line += ", PAUSED";
    if (s.hands_off) line += ", HANDS OFF (forces faded out)";
    if (s.host_lost) line += ", HOST LOST (watchdog)";
    return line;
}

void effect_lines(std::span<host::Effect> effects, std::vector<std::string>& lines) {
    if (effects.empty()) return;
    lines.emplace_back("  block  type              state");
    for (host::Effect& e : effects) {
        host::Result<host::EffectStatusInfo> status = e.status();
        check(status.status(), "ask the status of effect block " + std::to_string(e.block()));
        std::string state = runtime::reported_effect_state_name(status->state);
        if (status->emulated) state += " (emulated by the host)";
        if (status->iterations != 1 && status->iterations != 0) {
            state += ", iteration " + std::to_string(status->completed_iterations + 1) + " of " +
                     (status->iterations == kInfiniteIterations ? std::string("infinite")
                                                                : std::to_string(status->iterations));
        }
        char row[160];
        std::snprintf(row, sizeof row, "  %5d  %-16s  %s", static_cast<int>(e.block()),
                      std::string(effect_type_name(e.type())).c_str(), state.c_str());
        lines.emplace_back(row);
    }
}

}  // namespace

void run_monitor(const MonitorArgs& args, std::ostream& out, std::ostream& /*err*/) {
    std::optional<double> seconds;
    if (args.seconds) seconds = checked_range("--seconds", *args.seconds, 0, kMaxSeconds, "s", false);
    std::optional<SensationChoice> choice;
    if (!args.sensation.empty()) choice = parse_sensation(args.sensation);

    host::Device device = open_device(args.device);
    const host::DeviceCaps& caps = device.capabilities();
    std::optional<host::SensationLibrary> library;
    std::span<host::Effect> effects;
    if (choice) {
        const std::string only[] = {choice->name};
        host::Result<host::SensationLibrary> loaded = host::SensationLibrary::load(choice->file, device, only);
        if (!loaded) {
            throw std::runtime_error("load " + choice->file + " onto " + device.address() + ": " +
                                     loaded.status().message);
        }
        library.emplace(std::move(loaded).value());
        effects = library->effects(choice->name);
        check(library->play(choice->name), "play " + choice->name);
    }

    LiveBlock block(out, args.terminal);
    const Clock::time_point t0 = Clock::now();
    Clock::time_point last_refresh = t0;
    uint64_t last_reports = device.input().reports_received;
    for (Clock::time_point next = t0 + kRefreshPeriod;; next += kRefreshPeriod) {
        bool last_frame = false;
        while (Clock::now() < next) {
            if (stop_requested().load() || (seconds && std::chrono::duration<double>(Clock::now() - t0).count() >= *seconds)) {
                last_frame = true;
                break;
            }
            std::this_thread::sleep_for(std::min<Clock::duration>(kPollPeriod, next - Clock::now()));
        }
        if (!device.connected()) throw std::runtime_error("the device at " + device.address() + " disconnected");
        const Clock::time_point now = Clock::now();
        const host::InputState s = device.input();
        const double dt = std::chrono::duration<double>(now - last_refresh).count();
        const double report_rate = dt > 0 ? static_cast<double>(s.reports_received - last_reports) / dt : 0;
        last_refresh = now;
        last_reports = s.reports_received;

        std::vector<std::string> lines;
        lines.push_back("device   " + device.address() + " (" + caps.device + ", " + caps.class_name + "), " +
                        format_elapsed(std::chrono::duration<double>(now - t0).count()) +
                        (choice ? ", playing " + choice->name : std::string()));
        // The device measures its tick rate over windows of about a second: 0 before the first.
        const std::string measured =
            s.measured_loop_hz > 0 ? fixed(s.measured_loop_hz, 1) + " Hz measured" : std::string("not measured yet");
        lines.push_back("loop     " + measured + " (nominal " + std::to_string(s.loop_rate_hz) + " Hz), overruns " +
                        std::to_string(s.overruns) + ", input reports " + fixed(report_rate, 0) + "/s, dropped " +
                        std::to_string(s.dropped_reports));
        lines.push_back("force    " + format_forces(s.force, s.axis_count));
        lines.push_back(safety_line(s, caps));
        lines.push_back("effects  " + std::to_string(s.resident_effects) + " resident, " +
                        std::to_string(s.playing_effects) + " playing");
        effect_lines(effects, lines);
        block.show(lines);
        if (last_frame) break;
    }
    if (library) library->stop_all();
    device.close();
}

}  // namespace feel::cli
