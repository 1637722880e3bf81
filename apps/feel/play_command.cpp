// feel play: the two calls of §9.5 — load a sensation file onto a device, play one of its
// sensations — with the force shown live while it plays.
//
// Everything that can be checked without a device is checked first: the flags, the file
// (the reader names the field and the range of anything wrong), the sensation's name.
// Then the device is opened, asked for state reports at up to 1 kHz, and given the half
// second its safety fade-in takes after power-on, so that the forces shown are the full
// ones. Only the sensation to play is downloaded (SensationLibrary::load with a name), so
// that one sensation of a large file plays on a small device (an I-FORCE 1.x holds 16
// effects); a game would load its whole file once and play from it.
//
// While it plays, each state report (one per device tick at 1 kHz) updates the peaks, and
// ten times a second a progress line shows the elapsed time, the force on each axis and
// the state of each effect of the sensation. The sensation has ended when a state report
// shows no effect playing and every effect's status, asked over the protocol, says
// stopped (a compound's delayed effect plays nothing yet but is not stopped).
//
// How long it plays without --seconds (play_limit()): a sensation that ends by itself
// plays until it has, and with --press not before the last release; in case an effect's
// end is never seen, it is stopped at its length (after the last release, when there is
// one: a reflex starts at the latest then) plus kEndSlackS (10 s). A sensation that never ends
// is stopped kPlayDefaultCapS after the start, or after the last release with --press.
// With --press, effects with a trigger wait for their presses as in `feel render`: play
// starts only the others (without it, every effect starts once, as SensationLibrary::play
// does, so that a reflex's effect can be felt without a hand).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "feel/effect.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/host/device.hpp"
#include "feel/host/sensation_library.hpp"
#include "feel/render/render.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/sim/input_schedule.hpp"
#include "flag_checks.hpp"
#include "host_device.hpp"
#include "interrupt.hpp"
#include "live_output.hpp"
#include "sensation_choice.hpp"

namespace feel::cli {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kMaxSeconds = 3600;
constexpr auto kProgressPeriod = std::chrono::milliseconds(100);
constexpr auto kStatusCheckPeriod = std::chrono::milliseconds(10);
constexpr auto kFadeInLimit = std::chrono::milliseconds(2000);

double seconds_since(Clock::time_point t0, Clock::time_point t) {
    return std::chrono::duration<double>(t - t0).count();
}

int32_t parse_iterations(const std::string& text) {
    if (text.empty()) return runtime::kEffectIterations;
    if (text == "infinite") return kInfiniteIterations;
    double value = 0;
    std::size_t used = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size()) {
        throw UsageError("--iterations = " + text + " is not a number (allowed a whole number 1..255, or infinite)");
    }
    return checked_whole("--iterations", value, 1, 255);
}

// The largest |force| each axis showed, with its sign and when.
struct AxisPeak {
    float force = 0;
    double at_s = -1;  // seconds after play; < 0: never above 0
};

// Whether every effect's status says stopped; `states` gets each one's state name.
bool all_stopped(std::span<host::Effect> effects, std::string& states) {
    bool stopped = true;
    states.clear();
    for (host::Effect& e : effects) {
        host::Result<host::EffectStatusInfo> status = e.status();
        check(status.status(), "ask the status of effect block " + std::to_string(e.block()));
        states += (states.empty() ? "" : " ");
        states += runtime::reported_effect_state_name(status->state);
        if (status->emulated) states += "(emulated)";
        if (status->state != runtime::ReportedEffectState::stopped) stopped = false;
    }
    return stopped;
}

std::string progress_line(double elapsed_s, const host::InputState& s, const std::string& states) {
    return format_elapsed(elapsed_s) + "   " + format_forces(s.force, s.axis_count) + "   " + states;
}

// How long the sensation plays with this --iterations: render's sensation length for the
// effects' own counts; with N, the latest start delay + N × duration. nullopt: it never
// ends by itself.
std::optional<int64_t> play_length_us(const format::Sensation& sensation, int32_t iterations) {
    if (iterations == runtime::kEffectIterations) return render::sensation_length_us(sensation);
    if (iterations == kInfiniteIterations) return std::nullopt;
    int64_t longest = 0;
    for (const format::EffectSpec& e : sensation.effects) {
        if (e.params.duration_us == kInfiniteUs) return std::nullopt;
        longest = std::max(longest, e.params.start_delay_us + e.params.duration_us * iterations);
    }
    return longest;
}

std::string effect_count(std::size_t n) { return std::to_string(n) + (n == 1 ? " effect" : " effects"); }

// Beyond a sensation's own end, the time its end may take to show in the reports before
// play gives up waiting: the presses and the reports go through the host's clock and
// queues, which a loaded machine can hold up for a long time, so it is the same generous
// grace as for a sensation that never ends.
constexpr double kEndSlackS = kPlayDefaultCapS;

// When play stops a sensation without --seconds, and what it says about that.
struct PlayLimit {
    double seconds = 0;
    std::string rule;  // one line for the header, and the reason when the limit is hit
};

PlayLimit play_limit(std::optional<int64_t> length_us, int64_t last_release_us) {
    const double release_s = static_cast<double>(last_release_us) * 1e-6;
    const std::string slack = " + " + number(kEndSlackS) + " s";
    if (!length_us) {
        if (last_release_us == 0) return {kPlayDefaultCapS, "the sensation never ends by itself"};
        return {release_s + kPlayDefaultCapS,
                "the sensation never ends by itself; " + number(kPlayDefaultCapS) + " s after the last release"};
    }
    const double length_s = static_cast<double>(*length_us) * 1e-6;
    if (last_release_us == 0) return {length_s + kEndSlackS, "its length " + format_elapsed(length_s) + slack};
    return {release_s + length_s + kEndSlackS,
            "the last release + its length " + format_elapsed(length_s) + slack + ", if its end is not seen before"};
}

}  // namespace

void run_play(const PlayArgs& args, std::ostream& out, std::ostream& err) {
    std::optional<double> limit_s;
    if (args.seconds) limit_s = checked_range("--seconds", *args.seconds, 0, kMaxSeconds, "s", false);
    const int32_t iterations = parse_iterations(args.iterations);
    const format::SensationFile file = format::load_sensation_file(args.file);
    const format::Sensation& sensation = choose_sensation(file, args.sensation, args.file);
    const std::optional<int64_t> length_us = play_length_us(sensation, iterations);
    const bool endless = !length_us;

    std::vector<render::Press> presses;
    try {
        presses = render::parse_presses(args.press);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    int64_t last_release_us = 0;
    for (const render::Press& p : presses) last_release_us = std::max(last_release_us, p.release_us);

    // With --press the command drives the simulated hand, so it opens the device itself.
    std::optional<HandledDevice> handled;
    std::optional<host::Device> plain;
    if (presses.empty()) {
        plain.emplace(open_device(args.device));
    } else {
        handled.emplace(open_handled_device(args.device, "--press"));
    }
    host::Device& device = handled ? handled->device : *plain;
    std::optional<sim::InputSchedule> hand;
    if (handled) hand.emplace(render::input_schedule(presses, *handled->profile));  // names a control it lacks
    uint32_t buttons_down = 0;
    uint32_t hats_pushed = 0;
    // Presses the schedule says are due by `t_s` seconds after play.
    const auto move_hand = [&](double t_s) {
        if (!hand) return;
        const auto t_us = static_cast<int64_t>(t_s * 1e6);
        if (const uint32_t b = hand->buttons_at(t_us); b != buttons_down) {
            buttons_down = b;
            (void)handled->peripheral->set_buttons(b);
        }
        if (const uint32_t h = hand->hats_at(t_us); h != hats_pushed) {
            hats_pushed = h;
            (void)handled->peripheral->set_hats(h);
        }
    };
    const host::DeviceCaps& caps = device.capabilities();
    const int32_t report_hz = use_fastest_reports(device);
    const std::string only[] = {sensation.name};
    host::Result<host::SensationLibrary> loaded = host::SensationLibrary::load(args.file, device, only);
    if (!loaded) throw std::runtime_error("load " + args.file + " onto " + device.address() + ": " + loaded.status().message);
    host::SensationLibrary& library = loaded.value();
    std::span<host::Effect> effects = library.effects(sensation.name);
    if (!wait_for_full_strength(device, kFadeInLimit)) {
        err << "feel play: note: the device's forces are faded to " << number(device.input().fade_level)
            << " of full strength (is the handle held?)\n";
    }

    const PlayLimit rule = play_limit(length_us, last_release_us);
    const double cap_s = limit_s ? *limit_s : rule.seconds;
    out << "playing    " << sensation.name << " (" << effect_count(effects.size()) << ", "
        << (endless ? std::string("endless") : format_elapsed(static_cast<double>(*length_us) * 1e-6)) << ") from "
        << args.file << '\n'
        << "on         " << device.address() << " (" << caps.device << ", " << caps.class_name
        << "), state reports at " << report_hz << " Hz\n";
    if (!limit_s && (endless || !presses.empty())) {
        if (!presses.empty() && !endless) {
            out << "until      every effect has stopped after the last release at "
                << format_elapsed(static_cast<double>(last_release_us) * 1e-6) << "\n";
        }
        out << "limit      " << format_elapsed(cap_s) << ": " << rule.rule << " (--seconds S to change)\n";
    }
    out << std::flush;

    const Clock::time_point t0 = Clock::now();
    if (presses.empty()) {
        check(library.play(sensation.name, iterations), "play " + sensation.name);
    } else {  // the reflexes wait for the hand's presses, as in feel render
        for (std::size_t i = 0; i < effects.size(); ++i) {
            if (sensation.effects[i].params.trigger.kind != TriggerKind::none) continue;
            check(effects[i].start(iterations), "play " + sensation.name + ": start effect block " +
                                                    std::to_string(effects[i].block()));
        }
    }

    LiveLine live(out, args.terminal);
    AxisPeak peaks[kMaxAxes] = {};
    const int32_t axes = caps.axis_count;
    // Every report the live line shows counts in the peaks, the first one too (it may be
    // the only report of the sensation's first force, as wait_input() returns newer ones).
    const auto note_peaks = [&](const host::InputState& s, double t) {
        for (int32_t a = 0; a < axes; ++a) {
            if (std::fabs(s.force[a]) > std::fabs(peaks[a].force)) peaks[a] = {s.force[a], t};
        }
    };
    host::InputState last = device.input();
    const double first_s = seconds_since(t0, Clock::now());
    note_peaks(last, first_s);
    std::string states;
    (void)all_stopped(effects, states);
    live.show(progress_line(first_s, last, states));  // the states at the start
    uint64_t reports = 0;
    Clock::time_point next_line = t0 + kProgressPeriod;
    Clock::time_point next_status_check = t0;
    // The first report of the current run with nothing playing, s; < 0 while effects play.
    // (Plain doubles, not std::optional: g++ 12 warns spuriously on an optional here.)
    double quiet_since_s = -1;
    double ended_s = -1;  // when every effect was seen stopped, s; < 0 until then
    enum class Why { ended, limit, interrupted } why = Why::limit;
    for (;;) {
        if (stop_requested().load()) {
            why = Why::interrupted;
            break;
        }
        const Clock::time_point now = Clock::now();
        if (seconds_since(t0, now) >= cap_s) break;
        move_hand(seconds_since(t0, now));
        const host::Result<host::InputState> next = device.wait_input(std::chrono::milliseconds(20));
        if (!next) {
            if (next.status().kind == host::ErrorKind::timeout) continue;
            check(next.status(), "read the device's state");
        }
        const Clock::time_point arrived = Clock::now();
        const double t = seconds_since(t0, arrived);
        last = next.value();
        ++reports;
        note_peaks(last, t);
        if (last.playing_effects > 0) {
            quiet_since_s = -1;
        } else {
            if (quiet_since_s < 0) quiet_since_s = t;
            // Triggered effects wait for their presses: nothing has ended before the last.
            if (arrived >= next_status_check && t * 1e6 >= static_cast<double>(last_release_us)) {
                next_status_check = arrived + kStatusCheckPeriod;
                if (all_stopped(effects, states)) {
                    ended_s = quiet_since_s;
                    why = Why::ended;
                    break;
                }
            }
        }
        if (arrived >= next_line) {
            while (next_line <= arrived) next_line += kProgressPeriod;
            (void)all_stopped(effects, states);
            live.show(progress_line(t, last, states));
        }
    }
    const double elapsed_s = ended_s >= 0 ? ended_s : seconds_since(t0, Clock::now());
    if (why != Why::ended) {
        check(library.stop(sensation.name), "stop " + sensation.name);
        (void)all_stopped(effects, states);
    }
    live.show(progress_line(elapsed_s, last, states));
    live.finish();

    switch (why) {
        case Why::ended:
            out << "ended      after " << format_elapsed(elapsed_s) << ": every effect stopped\n";
            break;
        case Why::limit:
            out << "stopped    after " << format_elapsed(elapsed_s)
                << (limit_s ? " (--seconds)" : " (the limit: " + rule.rule + ")") << '\n';
            break;
        case Why::interrupted:
            out << "stopped    after " << format_elapsed(elapsed_s) << " (interrupted)\n";
            break;
    }
    out << "axis   peak force     at time\n";
    for (int32_t a = 0; a < axes; ++a) {
        char row[96];
        if (peaks[a].at_s < 0) {
            std::snprintf(row, sizeof row, "%-5s %11.1f     -\n", axis_label(a).c_str(), 0.0);
        } else {
            std::snprintf(row, sizeof row, "%-5s %+11.1f     %s\n", axis_label(a).c_str(),
                          static_cast<double>(peaks[a].force), format_elapsed(peaks[a].at_s).c_str());
        }
        out << row;
    }
    out << "(force is normalized, ±10000 = the motor limit; peaks over the " << reports
        << " state reports received)\n";
    library.stop_all();
    device.close();
}

}  // namespace feel::cli
