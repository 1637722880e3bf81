// What the Linux VM's checkers share (tests/linux: check_device_log.cpp for feel's USB device,
// check_bridge_log.cpp for `feel bridge`): reading the logs' "<t> <verb> [<report>] k=v ..."
// lines, counting checks, and the independent truth both compare against: hid-pidff's
// conversions from evdev's units to a field's logical range (drivers/hid/usbhid/hid-pidff.c,
// Linux 6.1), written out here from the kernel's source, and feel's documented ranges.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace feel_linux_checks {

struct Line {
    double t = 0;
    std::string verb;                       // spy: upload, uploaded, play, gain, ...; device: frame kind
    std::string report;                     // device log: the report key
    std::map<std::string, int64_t> fields;  // name=value pairs
    std::string text;
};

// How far after the judge's call at spy[i] (a play or a stop of effect `id`, or its erase)
// the device's answer to it is looked for: until the judge makes the same call about the
// same effect again (its next play with the same value), or, once the effect is erased, until
// the next upload (which may be given the freed block), at most kAnswerWindowS. The answers
// keep the calls' order but may come after the judge's next calls: on a loaded machine the
// VM's programs answer late (a fixed 2 s failed there once).
inline constexpr double kAnswerWindowS = 15.0;
inline double answer_window_end(const std::vector<Line>& spy, std::size_t i) {
    const Line& call = spy[i];
    const auto field = [](const Line& l, const char* name) {
        const auto it = l.fields.find(name);
        return it == l.fields.end() ? int64_t{-1} : it->second;
    };
    bool erased = call.verb == "erase";
    for (std::size_t k = i + 1; k < spy.size() && spy[k].t < call.t + kAnswerWindowS; ++k) {
        const Line& next = spy[k];
        const bool same_effect = field(next, "id") == field(call, "id");
        if (erased && next.verb == "upload") return next.t;
        if (same_effect && next.verb == "erase") erased = true;
        if (same_effect && call.verb == "play" && next.verb == "play" &&
            (field(next, "value") > 0) == (field(call, "value") > 0)) {
            return next.t;
        }
    }
    return call.t + kAnswerWindowS;
}

inline std::vector<std::string> read_lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

// "<t> <verb> [<report>] k=v k=v ..." (values decimal or 0x hex).
inline std::optional<Line> parse(const std::string& text, bool has_report) {
    std::istringstream in(text);
    Line l;
    l.text = text;
    if (!(in >> l.t >> l.verb)) return std::nullopt;
    std::string word;
    bool first = true;
    while (in >> word) {
        const std::size_t eq = word.find('=');
        if (eq == std::string::npos) {
            if (first && has_report) l.report = word;
            first = false;
            continue;
        }
        first = false;
        const std::string value = word.substr(eq + 1);
        char* end = nullptr;
        const long long v = std::strtoll(value.c_str(), &end, 0);
        if (end != value.c_str()) l.fields[word.substr(0, eq)] = v;
    }
    return l;
}

struct Checks {
    int passed = 0, failed = 0;
    std::string prefix;
    void expect(bool ok, const std::string& what) {
        (ok ? passed : failed)++;
        std::cout << (ok ? "ok     " : "FAIL   ") << prefix << what << "\n";
    }
    void equal(int64_t got, int64_t want, const std::string& what, int64_t tolerance = 0) {
        expect(std::llabs(got - want) <= tolerance,
               what + " = " + std::to_string(got) + " (expected " + std::to_string(want) + ")");
    }
};

// hid-pidff's conversions (Linux 6.1, drivers/hid/usbhid/hid-pidff.c), for a field with
// logical range [min, max]:
//   pidff_rescale(i, m):  i * (max - min) / m + min
//   pidff_set(u16 v):     pidff_rescale(v, 0xffff)                 gains, saturations, deadband, phase
//   pidff_set_signed(v):  min < 0: v > 0 ? v * max / 0x7fff : v * min / -0x8000
//                         min >= 0: v >= 0 ? rescale(v, 0x7fff) : rescale(-v, 0x8000)
//   envelope levels:      pidff_rescale(min(v, 0x7fff), 0x7fff)
//   times:                the value unchanged (milliseconds)
//   direction:            pidff_rescale(direction, 0xffff)
inline int64_t rescale(int64_t i, int64_t m, int64_t min, int64_t max) { return i * (max - min) / m + min; }
inline int64_t set_unsigned(int64_t v, int64_t min, int64_t max) { return rescale(v, 0xffff, min, max); }
inline int64_t set_signed(int64_t v, int64_t min, int64_t max) {
    if (min < 0) return v == 0 ? 0 : v > 0 ? v * max / 0x7fff : v * min / -0x8000;
    return v >= 0 ? rescale(v, 0x7fff, min, max) : rescale(-v, 0x8000, min, max);
}
inline int64_t envelope_level(int64_t v, int64_t min, int64_t max) { return rescale(std::min<int64_t>(v, 0x7fff), 0x7fff, min, max); }

// feel's logical ranges (docs/protocol.md).
constexpr int64_t kLevel = 10000;     // levels and magnitudes: 0..10000 or -10000..10000
constexpr int64_t kAngle = 36000;     // direction: 0..36000 hundredths of a degree

// PID 1.0's effect type usages (HID PID 1.0 §5.2, page 0x0F) for evdev's types.
inline int pid_effect_usage(int64_t type, int64_t waveform) {
    switch (type) {
        case 0x52: return 0x26;  // FF_CONSTANT -> ET Constant Force
        case 0x57: return 0x27;  // FF_RAMP -> ET Ramp
        case 0x53: return 0x40;  // FF_SPRING -> ET Spring
        case 0x54: return 0x43;  // FF_FRICTION -> ET Friction
        case 0x55: return 0x41;  // FF_DAMPER -> ET Damper
        case 0x56: return 0x42;  // FF_INERTIA -> ET Inertia
        case 0x51:               // FF_PERIODIC
        case 0x50:               // FF_RUMBLE: ff-core makes it a 50 ms sine
            switch (type == 0x50 ? 0x5a : waveform) {
                case 0x58: return 0x30;  // FF_SQUARE -> ET Square
                case 0x59: return 0x32;  // FF_TRIANGLE -> ET Triangle
                case 0x5a: return 0x31;  // FF_SINE -> ET Sine
                case 0x5b: return 0x33;  // FF_SAW_UP -> ET Sawtooth Up
                case 0x5c: return 0x34;  // FF_SAW_DOWN -> ET Sawtooth Down
                default: return 0;
            }
        default: return 0;
    }
}

// The value of the first of `names` the line has (the report table's name, then older ones);
// a failed check when it has none.
inline int64_t field(const Line& l, std::initializer_list<const char*> names, Checks& c, const std::string& what) {
    for (const char* n : names) {
        if (auto it = l.fields.find(n); it != l.fields.end()) return it->second;
    }
    c.expect(false, what + ": the device log's report has no field " + *names.begin() + ": " + l.text);
    return INT64_MIN;
}

// A Set Envelope against the envelope of the ff_effect `asked` (the spy's upload line).
inline void check_envelope_fields(const Line& asked, const Line& env, Checks& c, const std::string& at) {
    c.equal(field(env, {"attack_level", "impulse_level"}, c, at), envelope_level(asked.fields.at("attack_level"), 0, kLevel),
            at + "attack level");
    c.equal(field(env, {"attack_time_ms", "settle_time_ms"}, c, at), asked.fields.at("attack_length"), at + "attack time ms");
    c.equal(field(env, {"fade_level"}, c, at), envelope_level(asked.fields.at("fade_level"), 0, kLevel), at + "fade level");
    c.equal(field(env, {"fade_time_ms"}, c, at), asked.fields.at("fade_length"), at + "fade time ms");
}

// A Set Condition against evdev's condition[axis] of the ff_effect `asked`.
inline void check_condition_fields(const Line& asked, const Line& r, int axis, Checks& c, const std::string& at) {
    const std::string s = std::to_string(axis);
    c.equal(field(r, {"center_offset"}, c, at), set_signed(asked.fields.at("center" + s), -kLevel, kLevel), at + "axis " + s + " center");
    c.equal(field(r, {"pos_coefficient"}, c, at), set_signed(asked.fields.at("right_coeff" + s), -kLevel, kLevel),
            at + "axis " + s + " positive coefficient");
    c.equal(field(r, {"neg_coefficient"}, c, at), set_signed(asked.fields.at("left_coeff" + s), -kLevel, kLevel),
            at + "axis " + s + " negative coefficient");
    c.equal(field(r, {"pos_saturation"}, c, at), set_unsigned(asked.fields.at("right_saturation" + s), 0, kLevel),
            at + "axis " + s + " positive saturation");
    c.equal(field(r, {"neg_saturation"}, c, at), set_unsigned(asked.fields.at("left_saturation" + s), 0, kLevel),
            at + "axis " + s + " negative saturation");
    c.equal(field(r, {"deadband"}, c, at), set_unsigned(asked.fields.at("deadband" + s), 0, kLevel), at + "axis " + s + " deadband");
}

// Each FF_GAIN a program wrote (the spy's "gain" lines) reached the device as a Device Gain
// report on 0..10000 (hid-pidff's pidff_set).
inline void check_gains(const std::vector<Line>& spy, const std::vector<Line>& log, Checks& c, const std::string& who) {
    for (const Line& g : spy) {
        if (g.verb != "gain") continue;
        const Line* r = nullptr;
        for (const Line& l : log) {
            if (l.t >= g.t && l.report == "device_gain") {
                r = &l;
                break;
            }
        }
        c.expect(r != nullptr, who + " gain " + std::to_string(g.fields.at("value")) + " reached the device");
        if (r) c.equal(field(*r, {"gain"}, c, who), set_unsigned(g.fields.at("value"), 0, kLevel), who + " device gain");
    }
}

}  // namespace feel_linux_checks
