// The --press list of `feel render` (and its tests): which buttons and hats a render holds
// down, and when. Each token is CONTROL@PRESS:RELEASE in seconds; the hat's direction is
// spelled out for the reader, though a reflex triggers on any direction off center.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/render/render.hpp"

namespace feel::render {
namespace {

constexpr const char* kForms =
    "allowed BUTTON@PRESS:RELEASE or hatN:DIR@PRESS:RELEASE, BUTTON 1..32, N 1..4, DIR up, down, "
    "left, right, up-left, up-right, down-left or down-right, times in seconds with "
    "0 <= PRESS < RELEASE <= 600; e.g. 1@0.2:0.9,hat2:up@1.5:1.8";

[[noreturn]] void bad(const std::string& token, const std::string& why) {
    throw std::invalid_argument("--press \"" + token + "\": " + why + " (" + kForms + ")");
}

// A whole number in min..max, or nullopt-like -1 when `text` is not one.
int32_t whole(const std::string& text, int32_t min, int32_t max) {
    if (text.empty() || text.size() > 3) return -1;
    for (char c : text) {
        if (c < '0' || c > '9') return -1;
    }
    const int32_t v = std::stoi(text);
    return v >= min && v <= max ? v : -1;
}

double seconds(const std::string& token, const std::string& text, const char* what) {
    double v = 0;
    std::size_t used = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size() || !std::isfinite(v)) {
        bad(token, std::string("the ") + what + " time \"" + text + "\" is not a number of seconds");
    }
    if (v < 0 || v > kMaxDurationS) {
        bad(token, std::string("the ") + what + " time " + text + " s is out of range");
    }
    return v;
}

Press parse_token(const std::string& token) {
    const std::size_t at = token.find('@');
    if (at == std::string::npos) bad(token, "no @ between the control and its times");
    const std::string control = token.substr(0, at);
    const std::string times = token.substr(at + 1);
    Press p;
    if (control.rfind("hat", 0) == 0) {
        const std::size_t colon = control.find(':');
        if (colon == std::string::npos) bad(token, "a hat needs a direction, as hat2:up");
        const int32_t hat = whole(control.substr(3, colon - 3), 1, 4);
        if (hat < 0) bad(token, "\"" + control.substr(0, colon) + "\" is not a hat 1..4");
        const std::string dir = control.substr(colon + 1);
        static const char* const kDirections[] = {"up",      "down",     "left",      "right",
                                                  "up-left", "up-right", "down-left", "down-right"};
        bool known = false;
        for (const char* d : kDirections) known = known || dir == d;
        if (!known) bad(token, "\"" + dir + "\" is not a hat direction");
        p.control = Trigger{TriggerKind::hat, hat};
    } else {
        const int32_t button = whole(control, 1, 32);
        if (button < 0) bad(token, "\"" + control + "\" is not a button 1..32 nor a hat");
        p.control = Trigger{TriggerKind::button, button};
    }
    const std::size_t colon = times.find(':');
    if (colon == std::string::npos) bad(token, "no : between the press and release times");
    const double press_s = seconds(token, times.substr(0, colon), "press");
    const double release_s = seconds(token, times.substr(colon + 1), "release");
    if (!(release_s > press_s)) bad(token, "the release must come after the press");
    p.press_us = std::llround(press_s * 1e6);
    p.release_us = std::llround(release_s * 1e6);
    return p;
}

}  // namespace

std::vector<Press> parse_presses(const std::string& spec) {
    std::vector<Press> presses;
    if (spec.empty()) return presses;
    std::size_t begin = 0;
    while (begin <= spec.size()) {
        std::size_t end = spec.find(',', begin);
        if (end == std::string::npos) end = spec.size();
        const std::string token = spec.substr(begin, end - begin);
        if (token.empty()) bad(spec, "an empty entry in the list");
        presses.push_back(parse_token(token));
        begin = end + 1;
    }
    return presses;
}

}  // namespace feel::render
