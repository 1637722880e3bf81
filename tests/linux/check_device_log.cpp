// The host side of the Linux VM test (tests/linux/run.sh): reads what the VM left and
// decides.
//
//   feel_check_device_log --speed high|full --console FILE --device-log FILE
//                         --fftest SPY_LOG --testhaptic SPY_LOG
//
// Truth comes from outside feel:
//   - the kernel's console: hid-pidff's force-feedback banner, the device's speed, feel's
//     exit and the gadget removed;
//   - the spy logs (tests/linux/ff_spy.c): every effect the judges uploaded, played,
//     stopped and erased, and the gains they set, read from their own system calls;
//   - hid-pidff's documented conversions from evdev's units to the descriptor's logical
//     ranges (drivers/hid/usbhid/hid-pidff.c, Linux 6.1), written out below, and feel's
//     unit conventions for those ranges (docs/protocol.md): levels ±10000, gains 0..10000,
//     angles 0..36000 hundredths of a degree, times in milliseconds.
// The device log (`feel device --usb --log`) says what feel received; each uploaded effect
// is found there by the block its Block Load reply gave, and every field is compared.
//
// Prints one line per check and "N passed, M failed"; exits 1 when a check failed.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "log_checks.hpp"

using namespace feel_linux_checks;

namespace {

// How long `feel device --usb` may take from SIGTERM to its exit, in the VM (TCG, on a
// loaded 2-core machine): its I/O thread comes back to its loop every 100 ms at most, then
// the runtime stops and the gadget is removed from configfs.
constexpr double kStopBoundS = 3.0;

struct Upload {
    Line asked;       // the spy's upload line
    Line done;        // its uploaded line
    bool created = false;
};

const Line* find_field_line(const std::vector<Line>& log, const std::string& report, int64_t block, double from,
                            double to, std::optional<int64_t> axis = std::nullopt) {
    const Line* found = nullptr;
    for (const Line& l : log) {
        if (l.t < from || l.t > to || l.report != report) continue;
        auto b = l.fields.find("block");
        if (b == l.fields.end() || b->second != block) continue;
        if (axis) {
            auto a = l.fields.find("axis_index");
            if (a == l.fields.end()) a = l.fields.find("parameter_block_offset");
            if (a == l.fields.end() || a->second != *axis) continue;
        }
        found = &l;  // the last one in the window: what the effect ended up with
    }
    return found;
}

void check_effect(const Upload& u, const std::vector<Line>& log, double until, Checks& c) {
    const Line& a = u.asked;
    const int64_t type = a.fields.at("type");
    const std::string name = "effect id " + std::to_string(u.done.fields.at("id")) + " (evdev type 0x" +
                             [&] { char b[8]; std::snprintf(b, sizeof b, "%llx", static_cast<long long>(type)); return std::string(b); }() + ")";
    // The block: the Block Load reply after the Create New Effect this upload caused.
    double created_at = -1;
    for (const Line& l : log) {
        if (l.t >= a.t && l.t <= u.done.t && l.verb == "set_feature" && l.report == "create_new_effect") {
            created_at = l.t;
            break;
        }
    }
    c.expect(created_at >= 0, name + ": a Create New Effect reached the device");
    if (created_at < 0) return;
    int64_t block = -1;
    for (const Line& l : log) {
        if (l.t >= created_at && l.verb == "feature_reply" && l.report == "block_load") {
            block = l.fields.count("block") ? l.fields.at("block") : -1;
            break;
        }
    }
    c.expect(block > 0, name + ": Block Load gave block " + std::to_string(block));
    if (block <= 0) return;
    // The block is this effect's until a later Create New Effect is given the same block:
    // output reports may come after the program's next upload began (they are queued).
    until = 1e18;
    bool past_own = false;
    for (const Line& l : log) {
        if (l.t < created_at || l.verb != "feature_reply" || l.report != "block_load") continue;
        if (!l.fields.count("block") || l.fields.at("block") != block) continue;
        if (past_own) {
            until = l.t;
            break;
        }
        past_own = true;
    }
    const std::string at = name + " block " + std::to_string(block) + ": ";

    const bool garbage_trigger = a.fields.at("trigger_button") > 32;
    if (garbage_trigger) {
        // fftest's rumble leaves trigger and direction uninitialised: the device must refuse
        // the Set Effect cleanly (an error status naming the field), nothing else.
        bool refused = false;
        for (const Line& l : log) {
            if (l.t >= a.t && l.t <= until && l.verb == "refused" && l.text.find("set_effect") != std::string::npos) {
                refused = true;
            }
        }
        c.expect(refused, at + "trigger button " + std::to_string(a.fields.at("trigger_button")) +
                              " (uninitialised by the program) refused with an error status");
        return;
    }
    const Line* effect = find_field_line(log, "set_effect", block, a.t, until);
    c.expect(effect != nullptr, at + "Set Effect received");
    if (effect == nullptr) return;
    c.equal(field(*effect, {"type_usage"}, c, at), pid_effect_usage(type, a.fields.count("waveform") ? a.fields.at("waveform") : 0),
            at + "effect type usage");
    c.equal(field(*effect, {"duration_ms"}, c, at), a.fields.at("length"), at + "duration ms");
    c.equal(field(*effect, {"start_delay_ms"}, c, at), a.fields.at("delay"), at + "start delay ms");
    c.equal(field(*effect, {"trigger_index", "trigger_button"}, c, at), a.fields.at("trigger_button"), at + "trigger button");
    c.equal(field(*effect, {"gain"}, c, at), kLevel, at + "effect gain (hid-pidff: the field's maximum)");
    c.equal(field(*effect, {"direction_angle[0]", "direction[0]"}, c, at),
            rescale(a.fields.at("direction"), 0xffff, 0, kAngle), at + "direction (evdev 0..0xFFFF -> 0..36000)");

    auto check_envelope = [&](const Line* env) {
        c.expect(env != nullptr, at + "Set Envelope received");
        if (env != nullptr) check_envelope_fields(a, *env, c, at);
    };
    switch (type) {
        case 0x52: {  // constant
            const Line* r = find_field_line(log, "set_constant_force", block, a.t, until);
            c.expect(r != nullptr, at + "Set Constant Force received");
            if (r) c.equal(field(*r, {"magnitude", "level"}, c, at), set_signed(a.fields.at("level"), -kLevel, kLevel), at + "level");
            check_envelope(find_field_line(log, "set_envelope", block, a.t, until));
            break;
        }
        case 0x51: {  // periodic
            const Line* r = find_field_line(log, "set_periodic", block, a.t, until);
            c.expect(r != nullptr, at + "Set Periodic received");
            if (r) {
                c.equal(field(*r, {"magnitude"}, c, at), set_signed(a.fields.at("magnitude"), -kLevel, kLevel), at + "magnitude");
                c.equal(field(*r, {"offset"}, c, at), set_signed(a.fields.at("offset"), -kLevel, kLevel), at + "offset");
                c.equal(field(*r, {"period_ms"}, c, at), a.fields.at("period"), at + "period ms");
            }
            check_envelope(find_field_line(log, "set_envelope", block, a.t, until));
            break;
        }
        case 0x50: {  // rumble: ff-core's compat_effect() makes it a 50 ms sine of magnitude
                      // strong/3 + weak/6, no offset, no envelope (drivers/input/ff-core.c)
            const Line* r = find_field_line(log, "set_periodic", block, a.t, until);
            c.expect(r != nullptr, at + "Set Periodic received (rumble as a sine)");
            if (r) {
                const int64_t magnitude = a.fields.at("strong_magnitude") / 3 + a.fields.at("weak_magnitude") / 6;
                c.equal(field(*r, {"magnitude"}, c, at), set_signed(magnitude, -kLevel, kLevel), at + "rumble magnitude");
                c.equal(field(*r, {"period_ms"}, c, at), 50, at + "rumble period ms");
                c.equal(field(*r, {"offset"}, c, at), 0, at + "rumble offset");
            }
            break;
        }
        case 0x57: {  // ramp
            const Line* r = find_field_line(log, "set_ramp_force", block, a.t, until);
            c.expect(r != nullptr, at + "Set Ramp Force received");
            if (r) {
                c.equal(field(*r, {"start", "ramp_start"}, c, at), set_signed(a.fields.at("start_level"), -kLevel, kLevel), at + "ramp start");
                c.equal(field(*r, {"end", "ramp_end"}, c, at), set_signed(a.fields.at("end_level"), -kLevel, kLevel), at + "ramp end");
            }
            check_envelope(find_field_line(log, "set_envelope", block, a.t, until));
            break;
        }
        case 0x53: case 0x54: case 0x55: case 0x56: {  // conditions: one Set Condition per axis
            for (int axis = 0; axis < 2; ++axis) {
                const Line* r = find_field_line(log, "set_condition", block, a.t, until, axis);
                c.expect(r != nullptr, at + "Set Condition axis " + std::to_string(axis) + " received");
                if (r != nullptr) check_condition_fields(a, *r, axis, c, at);
            }
            break;
        }
        default: break;
    }
    // A saw with a negative magnitude (the wave upside down) is the other saw, which no phase
    // gives: the device refuses its Set Periodic naming the magnitude (docs/protocol.md,
    // "Standard hosts"); the effect then never exists, so what follows about the block
    // (Set Effect's commit, start, stop) is refused as a consequence.
    const bool inverted_saw = type == 0x51 && a.fields.count("waveform") &&
                              (a.fields.at("waveform") == 0x5c || a.fields.at("waveform") == 0x5d) &&
                              a.fields.at("magnitude") < 0;
    // Nothing the device refused about this block (other than the garbage case above).
    bool refused = false;
    bool magnitude_refused = false;
    for (const Line& l : log) {
        if (l.t >= a.t && l.t <= until && l.verb == "refused" && l.fields.count("block") && l.fields.at("block") == block) {
            if (inverted_saw && l.text.find("set_periodic.magnitude") != std::string::npos) {
                magnitude_refused = true;
                continue;
            }
            refused = true;
            std::cout << "       refused: " << l.text << "\n";
        }
    }
    if (inverted_saw) {
        c.expect(magnitude_refused, at + "negative saw magnitude refused naming set_periodic.magnitude");
        return;
    }
    c.expect(!refused, at + "no report about the block refused");
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5);
    return v[std::min(i, v.size() - 1)];
}

// The kernel's printk time of the first console line holding `what`, or -1.
double kernel_time(const std::vector<std::string>& console, const std::string& what) {
    for (const std::string& l : console) {
        if (l.find(what) == std::string::npos) continue;
        const std::size_t open = l.find('[');
        if (open != std::string::npos) return std::atof(l.c_str() + open + 1);
    }
    return -1;
}

// §4's figures, printed (never asserted: under TCG they are indicative only).
void measure(const std::vector<std::string>& console, const std::vector<Line>& log, const std::string& probe_path,
             Checks& c) {
    const double t_new = kernel_time(console, "USB device number");
    const double t_hid = kernel_time(console, "USB HID v1.11 Joystick");
    if (t_new >= 0 && t_hid >= 0) {
        std::printf("measure %senumeration: %.0f ms from the kernel's \"new USB device\" to hid-generic/hid-pidff "
                    "bound (kernel clock, TCG)\n", c.prefix.c_str(), (t_hid - t_new) * 1e3);
    }
    // Device time -> CLOCK_MONOTONIC: the least delayed status report gives the offset.
    double offset = 1e18;
    for (const Line& l : log) {
        if ((l.verb == "motor" || l.verb == "loop") && l.fields.count("t_us")) {
            offset = std::min(offset, l.t - static_cast<double>(l.fields.at("t_us")) * 1e-6);
        }
    }
    std::vector<double> seen_ms, tick_ms;
    std::vector<Line> probe;
    for (const std::string& t : read_lines(probe_path)) {
        std::istringstream in(t);
        std::string verb;
        in >> verb;
        if (auto l = parse("0 " + t, false)) probe.push_back(*l);
    }
    for (const Line& p : probe) {
        if (p.verb != "latency") continue;
        // start= was parsed as an integer prefix; read the real number from the text.
        const std::size_t at = p.text.find("start=");
        const double start = std::atof(p.text.c_str() + at + 6);
        for (const Line& l : log) {
            if (l.verb != "motor" || l.t < start) continue;
            bool pushing = false;
            for (const auto& [k, v] : l.fields) pushing = pushing || (k.rfind("force", 0) == 0 && v != 0);
            if (!pushing) continue;
            seen_ms.push_back((l.t - start) * 1e3);
            tick_ms.push_back((static_cast<double>(l.fields.at("t_us")) * 1e-6 + offset - start) * 1e3);
            break;
        }
    }
    const auto trials = std::count_if(probe.begin(), probe.end(), [](const Line& p) { return p.verb == "latency"; });
    if (trials > 0) {
        c.expect(static_cast<std::size_t>(trials) == seen_ms.size(),
                 "each latency trial's force reached the motors (" + std::to_string(seen_ms.size()) + " of " +
                     std::to_string(trials) + ")");
    }
    if (!seen_ms.empty()) {
        std::printf("measure %sEVIOCSFF + play -> first motor tick with the force: p50 %.1f ms, p99 %.1f ms "
                    "(%zu trials; tick time from the status report's device time; the report reaching the USB "
                    "side: p50 %.1f ms, p99 %.1f ms; TCG: indicative only)\n",
                    c.prefix.c_str(), percentile(tick_ms, 0.5), percentile(tick_ms, 0.99), tick_ms.size(),
                    percentile(seen_ms, 0.5), percentile(seen_ms, 0.99));
    }
    for (const Line& p : probe) {
        if (p.verb != "flood") continue;
        const double start = std::atof(p.text.c_str() + p.text.find("start=") + 6);
        const double end = std::atof(p.text.c_str() + p.text.find("end=") + 4);
        double before = 0, worst = 1e18;
        int64_t overruns_before = -1, overruns_after = -1;
        for (const Line& l : log) {
            if (l.verb != "loop") continue;
            const double rate = static_cast<double>(l.fields.at("measured_millihz")) * 1e-3;
            if (l.t < start) {
                before = rate;
                overruns_before = l.fields.at("overruns");
            } else if (l.t <= end + 1.0) {
                worst = std::min(worst, rate);
                overruns_after = l.fields.at("overruns");
            }
        }
        c.expect(worst < 1e18, "the loop reported its rate during the host's flood");
        if (worst < 1e18) {
            std::printf("measure %sloop under a host's flood of %s output reports: measured rate %.0f Hz "
                        "before, at least %.0f Hz during; overruns %lld -> %lld\n",
                        c.prefix.c_str(), p.text.substr(p.text.find("updates=") + 8).c_str(), before, worst,
                        static_cast<long long>(overruns_before), static_cast<long long>(overruns_after));
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::map<std::string, std::string> args;
    for (int i = 1; i + 1 < argc; i += 2) args[argv[i]] = argv[i + 1];
    const std::string speed = args["--speed"];
    Checks c;
    c.prefix = "[" + speed + " speed] ";

    const std::vector<std::string> console = read_lines(args["--console"]);
    auto has = [&](const std::string& s) {
        return std::any_of(console.begin(), console.end(), [&](const std::string& l) { return l.find(s) != std::string::npos; });
    };
    c.expect(has("==== modules loaded"), "the gadget and HID modules loaded");
    // The speed: the kernel's "new ...-speed USB device" line, or (when hid-pidff's debug
    // trace pushed it out of the kernel's log) the packet size of the endpoint descriptors
    // FunctionFS enabled, which the device log states.
    const std::string packet = speed == "full" ? "(max packet 64 bytes)" : "(max packet 1024 bytes)";
    bool packet_seen = false;
    for (const std::string& l : read_lines(args["--device-log"])) packet_seen = packet_seen || l.find(packet) != std::string::npos;
    c.expect(has(speed == "full" ? "new full-speed USB device" : "new high-speed USB device") || packet_seen,
             "the kernel enumerated feel's gadget at " + speed + " speed");
    c.expect(has("Force feedback for USB HID PID devices by Anssi Hannula"), "hid-pidff initialised on feel's device");
    c.expect(has("==== event device /dev/input/event"), "an event device with EV_FF appeared");
    c.expect(has("feel device exit status 0"), "feel device exited 0 on SIGTERM");
    {
        // From SIGTERM to its exit (init.sh's stop_program, in steps of 0.1 s): its USB I/O
        // thread never waits for the host (docs/usb-device.md, "Stopping"); the 5 s after
        // which init.sh kills it are what the exit status above fails on.
        double seconds = -1;
        for (const std::string& l : console) {
            if (std::sscanf(l.c_str(), "feel device stopped in %lf s", &seconds) == 1) break;
        }
        char figure[32];
        std::snprintf(figure, sizeof figure, "%.2f", seconds);
        c.expect(seconds >= 0 && seconds <= kStopBoundS, "feel device stopped " + std::string(figure) +
                                                             " s after SIGTERM (bound " +
                                                             std::to_string(static_cast<int>(kStopBoundS)) + " s)");
    }
    // tests/linux/init.sh names on the console each program that outlived its time limit.
    {
        std::string hung;
        for (const std::string& l : console) {
            const std::size_t at = l.find("FAIL: ");
            if (at == std::string::npos || l.find(" did not ", at) == std::string::npos) continue;
            std::string what = l.substr(at + 6);
            if (!what.empty() && what.back() == '\r') what.pop_back();
            hung += (hung.empty() ? "" : "; ") + what;
        }
        c.expect(hung.empty(), "every program in the VM ended within its time limit" +
                                   (hung.empty() ? std::string() : ": " + hung));
    }
    c.expect(!has("gadget left: "), "the gadget was removed from configfs on exit");

    // feel's protocol through hidraw (tests/linux/hidraw_probe.cpp): every USB path.
    c.expect(has("hidraw get device_info bytes=") && !has("hidraw get device_info bytes=-") &&
                 has("decoded=1 device=iforce2"),
             "GET_REPORT(Feature) on ep0: Device Info came back whole and decodes");
    c.expect(has("hidraw set create_new_effect result="), "SET_REPORT(Feature) on ep0: Create New Effect sent");
    c.expect(has("hidraw get block_load") && has(" block=1 status=1"),
             "Block Load on ep0: block 1, status success");
    c.expect(has("hidraw status command=17 block=1 code=0"),
             "interrupt IN: Create New Effect answered ok (CommandStatus)");
    c.expect(has("hidraw status command=5 block=1 code=0"), "interrupt OUT -> IN: Set Constant Force answered ok");
    c.expect(has("hidraw status command=1 block=1 code=0"), "interrupt OUT -> IN: Set Effect answered ok");
    c.expect(has("hidraw status command=10 block=1 code=0"), "interrupt OUT -> IN: Effect Operation start answered ok");
    {
        // ... and the motors pushed: a "motor" line with a force after the probe's start.
        bool pushed = false;
        for (const std::string& t : read_lines(args["--device-log"])) {
            if (t.find(" motor ") != std::string::npos && t.find("force[0]=0 ") == std::string::npos) pushed = true;
        }
        c.expect(pushed, "the constant force played: the device log shows the motors pushing");
    }

    std::vector<Line> log;
    for (const std::string& t : read_lines(args["--device-log"])) {
        if (auto l = parse(t, true)) log.push_back(*l);
    }
    c.expect(!log.empty(), "the device log has lines");

    for (const char* judge : {"--fftest", "--testhaptic"}) {
        std::vector<Line> spy;
        for (const std::string& t : read_lines(args[judge])) {
            if (auto l = parse(t, false)) spy.push_back(*l);
        }
        const std::string who = std::string(judge + 2);
        c.expect(!spy.empty(), who + " ran and its calls were recorded");
        std::vector<Upload> uploads;
        for (std::size_t i = 0; i + 1 < spy.size(); ++i) {
            if (spy[i].verb == "upload" && spy[i].fields["id"] == -1 && spy[i + 1].verb == "uploaded") {
                uploads.push_back(Upload{spy[i], spy[i + 1], spy[i + 1].fields["result"] == 0});
            }
        }
        c.expect(!uploads.empty(), who + " uploaded effects");
        for (std::size_t k = 0; k < uploads.size(); ++k) {
            const double until = k + 1 < uploads.size() ? uploads[k + 1].asked.t : uploads[k].done.t + 2.0;
            check_effect(uploads[k], log, until, c);
        }
        check_gains(spy, log, c, who);
        // Plays and stops: an Effect Operation for the effect's block with Op Effect Start
        // (0x79) or Op Effect Stop (0x7B).
        int plays = 0, seen = 0;
        for (const Line& p : spy) {
            if (p.verb != "play") continue;
            ++plays;
            for (const Line& l : log) {
                if (l.t >= p.t && l.t <= p.t + 2.0 && l.report == "effect_operation") {
                    const int64_t op = l.fields.count("operation_usage") ? l.fields.at("operation_usage") : -1;
                    if ((p.fields.at("value") > 0 && op == 0x79) || (p.fields.at("value") == 0 && op == 0x7B)) {
                        ++seen;
                        break;
                    }
                }
            }
        }
        c.equal(seen, plays, who + " plays and stops that reached the device as Effect Operations");
    }
    measure(console, log, args["--probe"], c);
    std::cout << c.prefix << c.passed << " passed, " << c.failed << " failed\n";
    return c.failed == 0 ? 0 : 1;
}
