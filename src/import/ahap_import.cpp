// Apple AHAP (Apple Haptic and Audio Pattern, JSON) → a feel/1 sensation on one axis.
//
// An AHAP file is {"Version": 1.0, "Metadata": {...}, "Pattern": [...]}; each entry of
// "Pattern" holds one "Event", "Parameter" or "ParameterCurve". Core Haptics plays haptic
// events on a phone's actuator; feel plays waves on a device's axis. The mapping
// (docs/import.md, "AHAP") keeps what a hand feels of each event: when it starts, how
// strong it is, how it rises and falls, and a rate from its sharpness.
//
//   HapticTransient at Time t, HapticIntensity i, HapticSharpness s
//     → sine, start delay t, magnitude 10000·i, one period 1/f(s) long, faded to 0 over
//       that period (envelope fade_level 0, fade_time = the period): a short tap.
//   HapticContinuous at t for EventDuration d, with i, s, AttackTime a, DecayTime y,
//   ReleaseTime r, Sustained
//     → sine, start delay t, magnitude 10000·i, period 1/f(s), duration d; the envelope
//       rises from 0 over a (impulse_level 0, settle_time a) and falls to 0 over r
//       (fade_level 0, fade_time r). Not Sustained: the event ends after a + y, falling
//       to 0 over y.
//   f(s) = 30 Hz + 70 Hz · s, so sharpness 0..1 spans 30..100 Hz, the band a joystick's
//   motors render crisply (Core Haptics' own actuator band is higher; feel's devices are
//   hand-held mechanisms, not phones).
//   ParameterCurve HapticIntensityControl (control points (tₖ, vₖ), each a multiplier
//   0..1 of the intensity, linear between points) over a continuous event
//     → the event is cut at the points into consecutive sines whose envelopes follow the
//       straight segments exactly (impulse level → magnitude, or magnitude → fade level),
//       each with the phase that continues the previous one. The event's own attack and
//       release then give way to the curve (a note says so).
//
// Everything else is reported in ImportResult::notes and not mapped: audio events,
// HapticSharpnessControl and the other curves and parameters, sharpness changes within an
// event. An intensity outside 0..1, a negative time or a time beyond 65 s is an error.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "feel/import/import.hpp"
#include "import_support.hpp"

namespace feel::import {
namespace {

using detail::fail;
using Json = nlohmann::json;

constexpr double kMinHz = 30.0;
constexpr double kHzPerSharpness = 70.0;
constexpr double kMaxSeconds = 65.0;  // feel's longest time (§6.3)

struct CurvePoint {
    double time_s;
    double value;  // intensity multiplier 0..1
};

struct Curve {
    double start_s;
    std::vector<CurvePoint> points;  // absolute times, increasing
    [[nodiscard]] double end_s() const { return points.back().time_s; }
    // The multiplier at t (within the curve's span).
    [[nodiscard]] double at(double t) const {
        if (t <= points.front().time_s) return points.front().value;
        for (size_t i = 1; i < points.size(); ++i) {
            if (t <= points[i].time_s) {
                const CurvePoint& a = points[i - 1];
                const CurvePoint& b = points[i];
                const double span = b.time_s - a.time_s;
                return span <= 0 ? b.value : a.value + (b.value - a.value) * (t - a.time_s) / span;
            }
        }
        return points.back().value;
    }
};

double number(const Json& j, const std::string& where, const char* key) {
    const auto it = j.find(key);
    if (it == j.end()) fail(where + ": \"" + key + "\" is missing");
    if (!it->is_number()) fail(where + ": \"" + key + "\" must be a number");
    const double v = it->get<double>();
    if (!std::isfinite(v)) fail(where + ": \"" + key + "\" must be a finite number");
    return v;
}

double checked(double v, const std::string& where, const std::string& what, double lo, double hi) {
    if (v < lo || v > hi) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s = %g is out of range (allowed %g..%g)", what.c_str(), v, lo, hi);
        fail(where + ": " + buf);
    }
    return v;
}

int64_t to_us(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }
int32_t to_level(double unit) { return static_cast<int32_t>(std::lround(unit * kFullScale)); }

struct EventParams {
    double intensity = 1.0;  // Core Haptics' defaults
    double sharpness = 0.5;
    double attack_s = 0, decay_s = 0, release_s = 0;
    bool sustained = true;
};

EventParams read_event_params(const Json& event, const std::string& where, std::vector<std::string>& notes) {
    EventParams ep;
    const auto it = event.find("EventParameters");
    if (it == event.end()) return ep;
    if (!it->is_array()) fail(where + ": \"EventParameters\" must be an array");
    for (size_t k = 0; k < it->size(); ++k) {
        const Json& param = (*it)[k];
        const std::string pw = where + ".EventParameters[" + std::to_string(k) + "]";
        if (!param.is_object() || !param.contains("ParameterID") || !param["ParameterID"].is_string()) {
            fail(pw + ": needs a string \"ParameterID\"");
        }
        const std::string id = param["ParameterID"].get<std::string>();
        if (id == "Sustained") {
            const Json& v = param.contains("ParameterValue") ? param["ParameterValue"] : Json();
            if (v.is_boolean()) ep.sustained = v.get<bool>();
            else if (v.is_number()) ep.sustained = v.get<double>() != 0;
            else fail(pw + ": Sustained's \"ParameterValue\" must be true or false");
            continue;
        }
        const double v = number(param, pw, "ParameterValue");
        if (id == "HapticIntensity") ep.intensity = checked(v, pw, "HapticIntensity", 0, 1);
        else if (id == "HapticSharpness") ep.sharpness = checked(v, pw, "HapticSharpness", 0, 1);
        else if (id == "AttackTime") ep.attack_s = checked(v, pw, "AttackTime (s)", 0, kMaxSeconds);
        else if (id == "DecayTime") ep.decay_s = checked(v, pw, "DecayTime (s)", 0, kMaxSeconds);
        else if (id == "ReleaseTime") ep.release_s = checked(v, pw, "ReleaseTime (s)", 0, kMaxSeconds);
        else notes.push_back(pw + ": the event parameter \"" + id + "\" is not mapped");
    }
    return ep;
}

EffectParams sine_on(Axis axis, double start_s, double duration_s, double hz, double intensity,
                     const std::string& where) {
    EffectParams p;
    p.type = EffectType::sine;
    p.axis_count = 1;
    p.axes[0] = axis;
    p.start_delay_us = to_us(checked(start_s, where, "Time (s)", 0, kMaxSeconds));
    p.duration_us = std::max<int64_t>(1, to_us(checked(duration_s, where, "the event's length (s)", 0, kMaxSeconds)));
    p.periodic.magnitude = to_level(intensity);
    p.periodic.period_us = std::max<int64_t>(1, to_us(1.0 / hz));
    return p;
}

}  // namespace

ImportResult import_ahap(std::string_view text, const ImportOptions& options) {
    if (options.sample_period_us) fail("--sample-period applies to WAV files only");
    if (text.size() > kMaxImportBytes) {
        fail("the file has " + std::to_string(text.size()) + " bytes (allowed at most " +
             std::to_string(kMaxImportBytes) + ")");
    }
    const Axis axis = options.axis.value_or(Axis::x);
    Json doc;
    try {
        doc = Json::parse(text.begin(), text.end(), nullptr, true, false);
    } catch (const Json::exception& e) {  // a syntax error, or a number too large for a double
        fail(std::string("not valid JSON: ") + e.what());
    }
    if (!doc.is_object()) fail("an AHAP file is a JSON object with a \"Pattern\" array");
    const auto pattern = doc.find("Pattern");
    if (pattern == doc.end() || !pattern->is_array()) fail("\"Pattern\" is missing or not an array");
    if (doc.contains("Version") && doc["Version"].is_number() && doc["Version"].get<double>() != 1.0) {
        fail("\"Version\" = " + doc["Version"].dump() + ": feel reads AHAP version 1.0");
    }

    ImportResult result;
    std::vector<Curve> curves;
    struct Pending {
        std::string where;
        const Json* event;
    };
    std::vector<Pending> events;
    for (size_t i = 0; i < pattern->size(); ++i) {
        const Json& entry = (*pattern)[i];
        const std::string where = "Pattern[" + std::to_string(i) + "]";
        if (!entry.is_object()) fail(where + ": each entry is an object with an \"Event\", \"Parameter\" or \"ParameterCurve\"");
        if (entry.contains("Event")) {
            if (!entry["Event"].is_object()) fail(where + ".Event must be an object");
            events.push_back({where + ".Event", &entry["Event"]});
        } else if (entry.contains("ParameterCurve")) {
            const Json& c = entry["ParameterCurve"];
            const std::string cw = where + ".ParameterCurve";
            if (!c.is_object() || !c.contains("ParameterID") || !c["ParameterID"].is_string()) {
                fail(cw + ": needs a string \"ParameterID\"");
            }
            const std::string id = c["ParameterID"].get<std::string>();
            if (id != "HapticIntensityControl") {
                result.notes.push_back(cw + ": the curve \"" + id + "\" is not mapped (feel maps HapticIntensityControl)");
                continue;
            }
            Curve curve;
            curve.start_s = checked(number(c, cw, "Time"), cw, "Time (s)", 0, kMaxSeconds);
            const auto pts = c.find("ParameterCurveControlPoints");
            if (pts == c.end() || !pts->is_array() || pts->empty()) {
                fail(cw + ": \"ParameterCurveControlPoints\" must be a non-empty array");
            }
            if (pts->size() > 16384) fail(cw + ": " + std::to_string(pts->size()) + " control points (allowed at most 16384)");
            for (size_t k = 0; k < pts->size(); ++k) {
                const std::string pw = cw + ".ParameterCurveControlPoints[" + std::to_string(k) + "]";
                if (!(*pts)[k].is_object()) fail(pw + " must be an object");
                const double t = curve.start_s + checked(number((*pts)[k], pw, "Time"), pw, "Time (s)", 0, kMaxSeconds);
                const double v = checked(number((*pts)[k], pw, "ParameterValue"), pw, "HapticIntensityControl", 0, 1);
                if (!curve.points.empty() && t < curve.points.back().time_s) {
                    fail(pw + ": control point times must not decrease");
                }
                curve.points.push_back({t, v});
            }
            curves.push_back(std::move(curve));
        } else if (entry.contains("Parameter")) {
            result.notes.push_back(where + ": dynamic parameters (\"Parameter\") are not mapped");
        } else {
            fail(where + ": an entry holds an \"Event\", a \"Parameter\" or a \"ParameterCurve\"");
        }
    }

    format::Sensation& s = result.sensation;
    s.name = detail::sensation_name(options, "imported");
    for (const Pending& pe : events) {
        const Json& e = *pe.event;
        const std::string& where = pe.where;
        if (!e.contains("EventType") || !e["EventType"].is_string()) fail(where + ": needs a string \"EventType\"");
        const std::string type = e["EventType"].get<std::string>();
        if (type == "AudioCustom" || type == "AudioContinuous") {
            result.notes.push_back(where + ": the audio event (" + type + ") is not mapped");
            continue;
        }
        if (type != "HapticTransient" && type != "HapticContinuous") {
            fail(where + ": EventType \"" + type +
                 "\" is not an AHAP event type (HapticTransient, HapticContinuous, AudioCustom, AudioContinuous)");
        }
        const double t = checked(number(e, where, "Time"), where, "Time (s)", 0, kMaxSeconds);
        const EventParams ep = read_event_params(e, where, result.notes);
        const double hz = kMinHz + kHzPerSharpness * ep.sharpness;
        if (s.effects.size() + 1 > format::kMaxFileEffects) {
            fail("the pattern gives more than " + std::to_string(format::kMaxFileEffects) + " waves (allowed at most " +
                 std::to_string(format::kMaxFileEffects) + ")");
        }
        if (type == "HapticTransient") {
            const double period = 1.0 / hz;
            EffectParams p = sine_on(axis, t, period, hz, ep.intensity, where);
            p.has_envelope = true;
            p.envelope = {p.periodic.magnitude, 0, 0, p.duration_us};
            s.effects.push_back({p, {}, {}});
            continue;
        }
        double d = checked(number(e, where, "EventDuration"), where, "EventDuration (s)", 0, kMaxSeconds);
        if (d <= 0) fail(where + ": EventDuration = 0: a continuous event lasts (allowed > 0 .. 65 s)");
        if (t + d > kMaxSeconds) {
            fail(where + ": the event ends at " + std::to_string(t + d) + " s (allowed at most 65 s)");
        }
        double release = ep.release_s;
        if (!ep.sustained) {  // rises over the attack, then falls to 0 over the decay
            d = std::min(d, ep.attack_s + ep.decay_s);
            release = ep.decay_s;
        }
        // The intensity curves that overlap this event.
        std::vector<double> cuts = {t, t + d};
        const Curve* curve = nullptr;
        for (const Curve& c : curves) {
            if (c.points.front().time_s < t + d && c.end_s() > t) {
                if (curve) {
                    result.notes.push_back(where + ": more than one HapticIntensityControl curve overlaps the event; "
                                           "the first is mapped");
                    break;
                }
                curve = &c;
            }
        }
        if (!curve) {
            EffectParams p = sine_on(axis, t, d, hz, ep.intensity, where);
            const int64_t attack = std::min(to_us(ep.attack_s), p.duration_us);
            const int64_t fade = std::min(to_us(release), p.duration_us - attack);
            if (attack > 0 || fade > 0) {
                p.has_envelope = true;
                p.envelope = {0, attack, 0, fade};
            }
            s.effects.push_back({p, {}, {}});
            continue;
        }
        if (ep.attack_s > 0 || release > 0) {
            result.notes.push_back(where + ": AttackTime/DecayTime/ReleaseTime give way to the HapticIntensityControl "
                                           "curve over the event");
        }
        for (const CurvePoint& cp : curve->points) {
            if (cp.time_s > t && cp.time_s < t + d) cuts.push_back(cp.time_s);
        }
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        for (size_t k = 0; k + 1 < cuts.size(); ++k) {
            const double a = cuts[k], b = cuts[k + 1];
            if (to_us(b) - to_us(a) < 1) continue;
            if (s.effects.size() + 1 > format::kMaxFileEffects) {
                fail("the pattern gives more than " + std::to_string(format::kMaxFileEffects) +
                     " waves (allowed at most " + std::to_string(format::kMaxFileEffects) + ")");
            }
            const double va = ep.intensity * curve->at(a), vb = ep.intensity * curve->at(b);
            EffectParams p = sine_on(axis, a, b - a, hz, std::max(va, vb), where);
            p.duration_us = to_us(b) - to_us(a);
            // The phase that continues the event's sine from its start.
            const double cycles = (a - t) * hz;
            p.periodic.phase = static_cast<int32_t>(std::lround((cycles - std::floor(cycles)) * 36000.0)) % 36000;
            if (std::abs(va - vb) * kFullScale >= 0.5) {
                p.has_envelope = true;
                if (va < vb) p.envelope = {to_level(va), p.duration_us, 0, 0};
                else p.envelope = {0, 0, to_level(vb), p.duration_us};
            }
            s.effects.push_back({p, {}, {}});
        }
    }
    if (s.effects.empty()) fail("the pattern holds no haptic event (HapticTransient or HapticContinuous)");
    s.compound = s.effects.size() > 1;
    s.description = "Imported from an AHAP pattern on " + std::string(axis_name(axis));
    detail::check_sensation(s, "sensation \"" + s.name + "\"");
    return result;
}

}  // namespace feel::import
