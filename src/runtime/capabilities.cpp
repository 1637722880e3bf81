// A device's capabilities from its profile, and their text form (feel caps).
#include "feel/runtime/capabilities.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace feel::runtime {

std::string_view travel_unit(sim::AxisKind kind) noexcept {
    return kind == sim::AxisKind::rotary ? "rad" : "m";
}

std::string_view force_unit(sim::AxisKind kind) noexcept {
    return kind == sim::AxisKind::rotary ? "N·m" : "N";
}

std::string_view effect_class_label(EffectClass c) noexcept {
    switch (c) {
        case EffectClass::condition: return "Conditions";
        case EffectClass::wave: return "Waves";
        case EffectClass::dynamic: return "Dynamics";
    }
    return "unknown class";
}

bool Capabilities::supports(EffectClass c) const noexcept {
    return enum_effects(*this, [](EffectType) { return false; }, c) > 0;
}

int32_t Capabilities::supported_type_count() const noexcept {
    return enum_effects(*this, [](EffectType) { return true; });
}

Capabilities capabilities_for(const sim::DeviceProfile& profile) {
    if (std::string e = sim::check_device_profile(profile); !e.empty()) {
        throw std::invalid_argument("device profile \"" + std::string(profile.name) + "\": " + e);
    }
    // The engine's budgets, read back from the config the engine gets, so the capabilities
    // cannot drift from what create() enforces.
    const EngineConfig engine = sim::engine_config_for(profile);

    Capabilities c;
    c.device = profile.name;
    c.description = profile.description;
    c.device_class = profile.device_class;
    c.class_name = sim::device_class_name(profile.device_class);
    c.axis_count = profile.axis_count;
    for (int i = 0; i < profile.axis_count; ++i) {
        const sim::AxisModel& a = profile.axes[i];
        c.axes[i] = AxisCapability{
            .axis = a.axis,
            .kind = a.kind,
            .half_travel = a.half_travel,
            .max_force = a.max_force,
            .sensor_counts = a.sensor_counts,
            .resolution = 2.0 * a.half_travel / a.sensor_counts,
        };
    }
    c.button_count = profile.button_count;
    c.hat_count = profile.hat_count;
    c.dead_man_switch = profile.dead_man_switch;
    c.supported_types = engine.supported_types;
    c.effect_slots = engine.max_effects;
    c.pool_bytes = engine.pool_bytes;
    c.sample_memory = engine.max_samples;
    c.local_reflexes = profile.local_reflexes;
    // The engine reports a dynamic's mass while it plays (§5.2) on every device that plays
    // dynamics; a device without Dynamics has nothing to report.
    c.interim_reports = c.supports(EffectClass::dynamic);
    c.interim_report_hz = c.interim_reports ? engine.interim_report_hz : 0.0f;
    c.loop_rate_hz = profile.default_loop_rate_hz;
    c.max_loop_rate_hz = profile.max_loop_rate_hz;
    c.firmware_version = profile.firmware_version;
    c.protocol_version = kProtocolVersion;
    return c;
}

namespace {

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// "linear, travel ±0.05 m, max force 4.45 N, 4096 sensor steps of 2.441e-05 m"; rotary
// axes add degrees, which is how people read a wheel.
std::string describe_axis(const AxisCapability& a) {
    const std::string unit(travel_unit(a.kind));
    std::string s = a.kind == sim::AxisKind::rotary ? "rotary" : "linear";
    s += ", travel ±" + number(a.half_travel) + " " + unit;
    if (a.kind == sim::AxisKind::rotary) {
        s += " (±" + number(a.half_travel * 180.0 / std::numbers::pi) + "°)";
    }
    s += ", max force " + number(a.max_force) + " " + std::string(force_unit(a.kind));
    s += ", " + std::to_string(a.sensor_counts) + " sensor steps of " + number(a.resolution) +
         " " + unit;
    return s;
}

void line(std::ostream& out, std::string_view key, const std::string& value) {
    constexpr int kKeyWidth = 18;
    out << key << ':';
    for (int pad = static_cast<int>(key.size()) + 1; pad < kKeyWidth; ++pad) out << ' ';
    out << ' ' << value << '\n';
}

}  // namespace

void print_capabilities(std::ostream& out, const Capabilities& caps) {
    line(out, "device", std::string(caps.device));
    line(out, "description", std::string(caps.description));
    line(out, "class", std::string(caps.class_name));
    line(out, "firmware", std::string(caps.firmware_version));
    line(out, "protocol", std::string(caps.protocol_version));
    line(out, "axes", std::to_string(caps.axis_count));
    for (int i = 0; i < caps.axis_count; ++i) {
        line(out, "  " + std::string(axis_name(caps.axes[i].axis)), describe_axis(caps.axes[i]));
    }
    line(out, "buttons", std::to_string(caps.button_count));
    line(out, "hats", std::to_string(caps.hat_count));
    line(out, "dead-man switch", caps.dead_man_switch ? "yes" : "no");
    line(out, "force scale", "±" + std::to_string(caps.max_force_normalized) +
                                 " = each axis's max force");
    line(out, "effect slots", std::to_string(caps.effect_slots));
    line(out, "parameter memory", std::to_string(caps.pool_bytes) + " bytes");
    line(out, "sample memory", std::to_string(caps.sample_memory) + " samples");
    line(out, "local reflexes", caps.local_reflexes ? "yes" : "no (the host emulates them)");
    line(out, "loop rate", std::to_string(caps.loop_rate_hz) + " Hz (max " +
                               std::to_string(caps.max_loop_rate_hz) + " Hz)");
    line(out, "interim reports",
         caps.interim_reports ? number(caps.interim_report_hz) + " Hz" : "none (no Dynamics)");
    line(out, "effect types", std::to_string(caps.supported_type_count()) + " of " +
                                  std::to_string(kEffectTypeCount));
    for (EffectClass cls : {EffectClass::condition, EffectClass::wave, EffectClass::dynamic}) {
        std::string types;
        const int32_t n = enum_effects(caps, [&](EffectType t) {
            types += (types.empty() ? "" : " ") + std::string(effect_type_name(t));
            return true;
        }, cls);
        line(out, "  " + std::string(effect_class_label(cls)),
             n == 0 ? std::string("none") : "(" + std::to_string(n) + ") " + types);
    }
}

std::string format_capabilities(const Capabilities& caps) {
    std::ostringstream out;
    print_capabilities(out, caps);
    return out.str();
}

}  // namespace feel::runtime
