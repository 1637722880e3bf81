// `feel bridge` in the Linux VM (tests/linux/run.sh): reads what the VM left and decides.
//
//   feel_check_bridge_log --console FILE --wire-log FILE --fftest SPY_LOG --testhaptic SPY_LOG
//                         --events HEX_DUMP --invalid PROBE_LOG
//
// In the VM, `feel bridge --device sim:iforce2 --log FILE` made a uinput joystick; fftest and
// SDL2's testhaptic played their effects on its event node with ff_spy.so preloaded.
// Truth comes from outside the bridge:
//   - the spy logs (tests/linux/ff_spy.c): every effect the programs uploaded, played,
//     stopped and erased, and the gains they set, from their own system calls;
//   - the documented mapping from evdev's units to feel's (docs/real-devices.md, "evdev
//     units and feel units"), which is hid-pidff's arithmetic, written out independently in
//     log_checks.hpp from the kernel's source; FF_RUMBLE's documented pair of sines;
//   - the kernel, which answered each program's EVIOCSFF with the bridge's reply.
//   - the kernel's input events read from the bridge's node while fftest played (one struct
//     input_event a line, in hex): the axes the banner declares, each within -10000..10000,
//     in SYN_REPORT batches.
//   - ff_probe's EVIOCSFF results for ff_effects feel cannot play (errno EINVAL each, from the
//     bridge through the kernel) and a valid one after them (accepted: the bridge carried on),
//     with the bridge's log line naming the ff_effect field on the console.
// The wire log says what the feel device received over its cable: each uploaded effect is
// found by the Create New Effect(s) between the program's EVIOCSFF and its return (the
// bridge answers the kernel only after the device answered), and every field is compared.
//
// Prints one line per check and "N passed, M failed"; exits 1 when a check failed.
#include <cstdio>
#include <initializer_list>

#include "log_checks.hpp"

using namespace feel_linux_checks;

namespace {

constexpr int64_t kOpStart = 0x79;  // PID Op Effect Start
constexpr int64_t kOpStop = 0x7B;   // PID Op Effect Stop
constexpr int64_t kRumbleStrongPeriodMs = 50;  // docs/real-devices.md, "FF_RUMBLE"
constexpr int64_t kRumbleWeakPeriodMs = 10;

const Line* last_line(const std::vector<Line>& log, const std::string& report, int64_t block, double from, double to,
                      std::optional<int64_t> axis = std::nullopt) {
    const Line* found = nullptr;
    for (const Line& l : log) {
        if (l.t < from || l.t > to || l.report != report || l.verb == "refused") continue;
        auto b = l.fields.find("block");
        if (b == l.fields.end() || b->second != block) continue;
        if (axis) {
            auto a = l.fields.find("parameter_block_offset");
            if (a == l.fields.end()) a = l.fields.find("axis_index");
            if (a == l.fields.end() || a->second != *axis) continue;
        }
        found = &l;
    }
    return found;
}

int64_t angle(int64_t evdev) { return rescale(evdev, 0xffff, 0, kAngle) % kAngle; }

struct Upload {
    Line asked, done;
    std::vector<int64_t> blocks;  // the device's blocks for it (two for a rumble)
};

void check_upload(Upload& u, const std::vector<Line>& log, Checks& c) {
    const Line& a = u.asked;
    const int64_t type = a.fields.at("type");
    char name[64];
    std::snprintf(name, sizeof name, "effect id %lld (evdev type 0x%llx) ", static_cast<long long>(u.done.fields.at("id")),
                  static_cast<long long>(type));
    const std::string at = name;
    c.equal(u.done.fields.at("result"), 0, at + "upload accepted (EVIOCSFF returned)");
    // The device's blocks: each Create New Effect in the upload's window and the Block Load after it.
    for (std::size_t i = 0; i < log.size(); ++i) {
        const Line& l = log[i];
        if (l.t < a.t || l.t > u.done.t || l.report != "create_new_effect") continue;
        for (std::size_t j = i + 1; j < log.size(); ++j) {
            if (log[j].report == "block_load" && log[j].verb == "feature_reply") {
                u.blocks.push_back(log[j].fields.count("block") ? log[j].fields.at("block") : -1);
                break;
            }
        }
    }
    const std::size_t want = type == 0x50 ? 2 : 1;
    c.equal(static_cast<int64_t>(u.blocks.size()), static_cast<int64_t>(want),
            at + "feel effects created on the device (FF_RUMBLE: two sines)");
    if (u.blocks.size() != want) return;
    const double from = a.t, to = u.done.t;
    const bool wave = type == 0x51 || type == 0x52 || type == 0x57;
    const bool negative = type == 0x51 && a.fields.at("magnitude") < 0;
    int64_t waveform = a.fields.count("waveform") ? a.fields.at("waveform") : 0;
    if (negative && waveform == 0x5b) waveform = 0x5c;  // a saw up upside down is the saw down
    else if (negative && waveform == 0x5c) waveform = 0x5b;
    const auto envelope_of = [&](int64_t block, const std::string& where) {
        const bool any = a.fields.at("attack_length") != 0 || a.fields.at("attack_level") != 0 ||
                         a.fields.at("fade_length") != 0 || a.fields.at("fade_level") != 0;
        const Line* env = last_line(log, "set_envelope", block, from, to);
        if (!any) {
            c.expect(env == nullptr, where + "no envelope sent (the ff_effect has none)");
            return;
        }
        c.expect(env != nullptr, where + "Set Envelope received");
        if (env != nullptr) check_envelope_fields(a, *env, c, where);
    };
    for (std::size_t k = 0; k < u.blocks.size(); ++k) {
        const int64_t block = u.blocks[k];
        const std::string where = at + "block " + std::to_string(block) + ": ";
        const Line* effect = last_line(log, "set_effect", block, from, to);
        c.expect(effect != nullptr, where + "Set Effect received");
        if (effect == nullptr) continue;
        c.equal(field(*effect, {"type_usage"}, c, where), pid_effect_usage(type == 0x50 ? 0x51 : type, type == 0x50 ? 0x5a : waveform),
                where + "effect type usage");
        const int64_t length = a.fields.at("length");
        c.equal(field(*effect, {"duration_ms"}, c, where), length == 0 ? 0xFFFF : length, where + "duration ms (0: infinite, 0xFFFF)");
        c.equal(field(*effect, {"start_delay_ms"}, c, where), a.fields.at("delay"), where + "start delay ms");
        c.equal(field(*effect, {"gain"}, c, where), kLevel, where + "effect gain (evdev has none: full)");
        c.equal(field(*effect, {"trigger_index", "trigger_button"}, c, where), type == 0x50 ? 0 : a.fields.at("trigger_button"),
                where + "trigger button (none; FF_RUMBLE has no trigger)");
        if (wave) {
            c.equal(field(*effect, {"direction_enable"}, c, where), 1, where + "direction given");
            c.equal(field(*effect, {"direction_angle[0]", "direction[0]"}, c, where), angle(a.fields.at("direction")),
                    where + "direction (evdev 0..0xFFFF -> 0..35999)");
        } else {
            c.equal(field(*effect, {"direction_enable"}, c, where), 0, where + "no direction (conditions act per axis; rumble on one axis)");
        }
        switch (type) {
            case 0x52: {
                const Line* r = last_line(log, "set_constant_force", block, from, to);
                c.expect(r != nullptr, where + "Set Constant Force received");
                if (r) c.equal(field(*r, {"magnitude"}, c, where), set_signed(a.fields.at("level"), -kLevel, kLevel), where + "level");
                envelope_of(block, where);
                break;
            }
            case 0x57: {
                const Line* r = last_line(log, "set_ramp_force", block, from, to);
                c.expect(r != nullptr, where + "Set Ramp Force received");
                if (r) {
                    c.equal(field(*r, {"ramp_start", "start"}, c, where), set_signed(a.fields.at("start_level"), -kLevel, kLevel), where + "ramp start");
                    c.equal(field(*r, {"ramp_end", "end"}, c, where), set_signed(a.fields.at("end_level"), -kLevel, kLevel), where + "ramp end");
                }
                envelope_of(block, where);
                break;
            }
            case 0x51: {
                const Line* r = last_line(log, "set_periodic", block, from, to);
                c.expect(r != nullptr, where + "Set Periodic received");
                if (r) {
                    const int64_t m = set_signed(a.fields.at("magnitude"), -kLevel, kLevel);
                    c.equal(field(*r, {"magnitude"}, c, where), m < 0 ? -m : m, where + "magnitude (|level|: upside down is the phase or the other saw)");
                    c.equal(field(*r, {"offset"}, c, where), set_signed(a.fields.at("offset"), -kLevel, kLevel), where + "offset");
                    c.equal(field(*r, {"period_ms"}, c, where), a.fields.at("period"), where + "period ms");
                    const bool by_phase = negative && waveform != 0x5b && waveform != 0x5c;
                    c.equal(field(*r, {"phase"}, c, where), (angle(a.fields.at("phase")) + (by_phase ? 18000 : 0)) % kAngle,
                            where + "phase (+180 degrees when upside down)");
                }
                envelope_of(block, where);
                break;
            }
            case 0x50: {
                const Line* r = last_line(log, "set_periodic", block, from, to);
                c.expect(r != nullptr, where + "Set Periodic received");
                if (r) {
                    const bool strong = k == 0;
                    c.equal(field(*r, {"magnitude"}, c, where),
                            set_unsigned(a.fields.at(strong ? "strong_magnitude" : "weak_magnitude"), 0, kLevel),
                            where + (strong ? "strong motor magnitude" : "weak motor magnitude"));
                    c.equal(field(*r, {"period_ms"}, c, where), strong ? kRumbleStrongPeriodMs : kRumbleWeakPeriodMs, where + "period ms");
                    c.equal(field(*r, {"offset"}, c, where), 0, where + "offset");
                }
                break;
            }
            default: {  // conditions: one Set Condition per axis
                for (int axis = 0; axis < 2; ++axis) {
                    const Line* r = last_line(log, "set_condition", block, from, to, axis);
                    c.expect(r != nullptr, where + "Set Condition axis " + std::to_string(axis) + " received");
                    if (r != nullptr) check_condition_fields(a, *r, axis, c, where);
                }
                break;
            }
        }
    }
}

// struct input_event on x86-64 (linux/input.h): struct timeval (16 bytes), __u16 type,
// __u16 code, __s32 value, little-endian.
void check_events(const std::vector<std::string>& hex, Checks& c) {
    constexpr int kEvSyn = 0, kEvAbs = 3, kAbsX = 0, kAbsY = 1;
    auto byte = [](const std::string& h, std::size_t i) { return static_cast<uint32_t>(std::stoul(h.substr(2 * i, 2), nullptr, 16)); };
    int abs_x = 0, abs_y = 0, syn = 0, outside = 0, other = 0;
    for (const std::string& h : hex) {
        if (h.size() != 48) continue;
        const uint32_t type = byte(h, 16) | byte(h, 17) << 8;
        const uint32_t code = byte(h, 18) | byte(h, 19) << 8;
        const auto value = static_cast<int32_t>(byte(h, 20) | byte(h, 21) << 8 | byte(h, 22) << 16 | byte(h, 23) << 24);
        if (type == kEvSyn) {
            ++syn;
        } else if (type == kEvAbs && (code == kAbsX || code == kAbsY)) {
            (code == kAbsX ? abs_x : abs_y)++;
            if (value < -10000 || value > 10000) ++outside;
        } else if (type != 1 && type != 0x15) {  // EV_KEY may come too, and evdev echoes the
            ++other;                              // EV_FF plays and gains a program writes
        }
    }
    std::printf("measure [bridge] input events while fftest played: %d ABS_X, %d ABS_Y, %d SYN_REPORT\n", abs_x, abs_y, syn);
    c.expect(abs_x + abs_y > 0, "the handle's positions came out as EV_ABS events (ABS_X/ABS_Y)");
    c.expect(syn > 0, "the events came in SYN_REPORT batches");
    c.equal(outside, 0, "EV_ABS values outside -10000..10000");
    c.equal(other, 0, "events other than EV_ABS, EV_KEY, EV_SYN (and fftest's own EV_FF)");
}

}  // namespace

int main(int argc, char** argv) {
    std::map<std::string, std::string> args;
    for (int i = 1; i + 1 < argc; i += 2) args[argv[i]] = argv[i + 1];
    Checks c;
    c.prefix = "[bridge] ";
    const std::vector<std::string> console = read_lines(args["--console"]);
    auto has = [&](const std::string& s) {
        return std::any_of(console.begin(), console.end(), [&](const std::string& l) { return l.find(s) != std::string::npos; });
    };
    c.expect(has("==== bridge event device /dev/input/event"), "feel bridge made an input device with an event node");
    // The banner: "feel bridge: ... force feedback: constant ramp ...[; not offered ...]".
    std::vector<std::string> offered;
    for (const std::string& l : console) {
        const std::size_t at = l.find("force feedback:");
        if (l.find("feel bridge: ") == std::string::npos || at == std::string::npos) continue;
        std::istringstream words(l.substr(at + 15, l.find(';', at) == std::string::npos ? std::string::npos : l.find(';', at) - at - 15));
        for (std::string w; words >> w;) offered.push_back(w);
        break;
    }
    // The I-FORCE 2.0 profile plays every effect evdev has.
    for (const char* ff : {"constant", "periodic", "ramp", "spring", "damper", "inertia", "friction", "rumble", "gain",
                           "autocenter", "square", "triangle", "sine", "saw_up", "saw_down"}) {
        c.expect(std::find(offered.begin(), offered.end(), ff) != offered.end(), std::string("the bridge offers FF ") + ff);
    }
    c.expect(!has("not offered (the device lacks them)"), "the bridge offers everything evdev has on I-FORCE 2.0");
    c.expect(has("feel bridge exit status 0"), "feel bridge exited 0 on SIGTERM");

    std::vector<Line> log;
    for (const std::string& t : read_lines(args["--wire-log"])) {
        if (auto l = parse(t, true)) log.push_back(*l);
    }
    c.expect(!log.empty(), "the wire log has lines");
    for (const Line& l : log) {
        if (l.verb == "refused") c.expect(false, "the device refused nothing: " + l.text);
    }

    for (const char* judge : {"--fftest", "--testhaptic"}) {
        const std::string who = std::string(judge + 2);
        std::vector<Line> spy;
        for (const std::string& t : read_lines(args[judge])) {
            if (auto l = parse(t, false)) spy.push_back(*l);
        }
        c.expect(!spy.empty(), who + " ran and its calls were recorded");
        std::vector<Upload> uploads;
        std::map<int64_t, std::vector<int64_t>> blocks_of;  // evdev id -> device blocks
        for (std::size_t i = 0; i + 1 < spy.size(); ++i) {
            if (spy[i].verb == "upload" && spy[i].fields["id"] == -1 && spy[i + 1].verb == "uploaded") {
                uploads.push_back(Upload{spy[i], spy[i + 1], {}});
            }
        }
        c.expect(!uploads.empty(), who + " uploaded effects");
        for (Upload& u : uploads) {
            c.prefix = "[bridge " + who + "] ";
            check_upload(u, log, c);
            blocks_of[u.done.fields.at("id")] = u.blocks;
        }
        check_gains(spy, log, c, who);
        // Plays and stops: an Effect Operation start (count given) or stop for each of the
        // effect's blocks, before the judge's next call about it (answer_window_end).
        int plays = 0, seen = 0;
        for (std::size_t i = 0; i < spy.size(); ++i) {
            const Line& p = spy[i];
            if (p.verb != "play") continue;
            ++plays;
            const double until = answer_window_end(spy, i);
            const std::vector<int64_t>& blocks = blocks_of[p.fields.at("id")];
            std::size_t reached = 0;
            for (int64_t block : blocks) {
                for (const Line& l : log) {
                    if (l.t < p.t || l.t > until || l.report != "effect_operation") continue;
                    if (!l.fields.count("block") || l.fields.at("block") != block) continue;
                    const int64_t op = l.fields.count("operation_usage") ? l.fields.at("operation_usage") : -1;
                    if ((p.fields.at("value") > 0 && op == kOpStart) || (p.fields.at("value") == 0 && op == kOpStop)) {
                        ++reached;
                        break;
                    }
                }
            }
            if (!blocks.empty() && reached == blocks.size()) ++seen;
        }
        c.equal(seen, plays, "plays and stops that reached the device as Effect Operations on every block of the effect");
        // Erases: each of the effect's blocks freed.
        for (std::size_t i = 0; i < spy.size(); ++i) {
            const Line& e = spy[i];
            if (e.verb != "erase") continue;
            const double until = answer_window_end(spy, i);
            const std::vector<int64_t>& blocks = blocks_of[e.fields.at("id")];
            std::size_t freed = 0;
            for (int64_t block : blocks) {
                for (const Line& l : log) {
                    if (l.t >= e.t && l.t <= until && l.report == "block_free" && l.fields.count("block") &&
                        l.fields.at("block") == block) {
                        ++freed;
                        break;
                    }
                }
            }
            c.expect(!blocks.empty() && freed == blocks.size(),
                     "erase of effect " + std::to_string(e.fields.at("id")) + " freed its blocks on the device");
        }
        c.prefix = "[bridge] ";
    }
    check_events(read_lines(args["--events"]), c);
    // Refusals: the kernel hands the bridge's errno to the program (EINVAL = 22).
    const std::map<std::string, std::string> refused = {
        {"periodic_period_0", "u.periodic.period = 0 is out of range"},
        {"endless_ramp", "replay.length = 0 (endless) leaves a ramp no end"},
        {"envelope_level_0x8000", "envelope.attack_level = 32768 is out of range (allowed 0..32767)"},
        {"trigger_not_a_button", "trigger.button = 0x6269 is not a joystick button"}};
    std::map<std::string, Line> results;
    for (const std::string& t : read_lines(args["--invalid"])) {
        if (auto l = parse("0 " + t, false); l && l->verb == "invalid") {
            const std::size_t at = t.find("case=");
            results[t.substr(at + 5, t.find(' ', at) - at - 5)] = *l;
        }
    }
    for (const auto& [name, why] : refused) {
        auto it = results.find(name);
        c.expect(it != results.end(), "invalid ff_effect " + name + " was tried");
        if (it == results.end()) continue;
        c.equal(it->second.fields.at("errno"), 22, "invalid ff_effect " + name + ": EVIOCSFF failed with EINVAL");
        c.expect(has(why), "invalid ff_effect " + name + ": the bridge logged \"" + why + "\"");
    }
    auto valid = results.find("valid_constant");
    c.expect(valid != results.end() && valid->second.fields.at("result") == 0,
             "a valid ff_effect after the refusals was accepted (the bridge carried on)");
    std::cout << c.prefix << c.passed << " passed, " << c.failed << " failed\n";
    return c.failed == 0 ? 0 : 1;
}
