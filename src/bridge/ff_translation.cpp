#include "ff_translation.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include "evdev_units.hpp"

namespace feel::bridge {
namespace {

std::string hex(unsigned v) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04x", v);
    return text;
}

Translation refuse(std::string message) {
    Translation t;
    t.error = -EINVAL;
    t.message = std::move(message);
    return t;
}

// The feel type of an FF_PERIODIC waveform, and its inverse (the wave upside down).
struct WaveChoice {
    EffectType type;
    EffectType inverted;
    bool inverted_by_phase;  // sine, square, triangle: upside down is half a period on
};
std::optional<WaveChoice> wave_of(uint16_t waveform) {
    switch (waveform) {
        case FF_SQUARE: return WaveChoice{EffectType::square, EffectType::square, true};
        case FF_TRIANGLE: return WaveChoice{EffectType::triangle, EffectType::triangle, true};
        case FF_SINE: return WaveChoice{EffectType::sine, EffectType::sine, true};
        // feel's saws are 2p-1 and 1-2p of the cycle fraction p: each is the other upside down.
        case FF_SAW_UP: return WaveChoice{EffectType::saw_up, EffectType::saw_down, false};
        case FF_SAW_DOWN: return WaveChoice{EffectType::saw_down, EffectType::saw_up, false};
        default: return std::nullopt;
    }
}

// The envelope, when the ff_effect has one (any field not zero). Levels above evdev's
// 15-bit range are refused, not clamped.
std::string set_envelope(const ff_envelope& e, EffectParams& p) {
    for (auto [name, level] : {std::pair<const char*, uint16_t>{"attack_level", e.attack_level},
                               std::pair<const char*, uint16_t>{"fade_level", e.fade_level}}) {
        if (level > kEvdevMaxEnvelopeLevel) {
            return std::string("ff_effect envelope.") + name + " = " + std::to_string(level) +
                   " is out of range (allowed 0..32767)";
        }
    }
    p.has_envelope = e.attack_length != 0 || e.attack_level != 0 || e.fade_length != 0 || e.fade_level != 0;
    p.envelope.impulse_level = evdev_envelope_level(e.attack_level);
    p.envelope.settle_time_us = evdev_ms_to_us(e.attack_length);
    p.envelope.fade_level = evdev_envelope_level(e.fade_level);
    p.envelope.fade_time_us = evdev_ms_to_us(e.fade_length);
    return {};
}

// A wave's axes and direction: the x-y plane with evdev's angle as feel's polar direction
// on a device with two axes or more; on a one-axis device, the component of that direction
// along the axis (a cartesian direction), which must not be zero.
std::string set_wave_axes(uint16_t direction, const host::DeviceCaps& caps, EffectParams& p) {
    if (caps.axis_count >= 2) {
        p.axis_count = 2;
        p.axes[0] = Axis::x;
        p.axes[1] = Axis::y;
        p.direction.kind = DirectionKind::polar;
        p.direction.value[0] = evdev_angle(direction);
        return {};
    }
    p.axis_count = 1;
    p.axes[0] = caps.axes[0].axis;
    const double radians = evdev_angle(direction) * (std::numbers::pi / 18000.0);
    const auto component = static_cast<int32_t>(std::lround(std::sin(radians) * kFullScale));
    if (component == 0) {
        return "ff_effect direction = " + hex(direction) +
               " points along no axis of this one-axis device (a force along its axis comes from 0x4000 or 0xc000)";
    }
    p.direction.kind = DirectionKind::cartesian;
    p.direction.value[0] = component;
    return {};
}

void set_condition(const ff_condition_effect& c, ConditionBlock& b) {
    b.pos_coefficient = evdev_signed_level(c.right_coeff);
    b.neg_coefficient = evdev_signed_level(c.left_coeff);
    b.offset = evdev_signed_level(c.center);
    b.pos_saturation = evdev_unsigned_level(c.right_saturation);
    b.neg_saturation = evdev_unsigned_level(c.left_saturation);
    b.deadband = evdev_unsigned_level(c.deadband);
}

std::optional<EffectType> condition_type(uint16_t type) {
    switch (type) {
        case FF_SPRING: return EffectType::spring;
        case FF_DAMPER: return EffectType::damper;
        case FF_INERTIA: return EffectType::inertia;
        case FF_FRICTION: return EffectType::friction;
        default: return std::nullopt;
    }
}

std::string type_name(uint16_t type) {
    switch (type) {
        case FF_RUMBLE: return "FF_RUMBLE";
        case FF_PERIODIC: return "FF_PERIODIC";
        case FF_CONSTANT: return "FF_CONSTANT";
        case FF_SPRING: return "FF_SPRING";
        case FF_FRICTION: return "FF_FRICTION";
        case FF_DAMPER: return "FF_DAMPER";
        case FF_INERTIA: return "FF_INERTIA";
        case FF_RAMP: return "FF_RAMP";
        default: return "type " + hex(type);
    }
}

std::string not_on_device(EffectType t, const host::DeviceCaps& caps) {
    return std::string("this device (") + caps.device + ") does not play " + std::string(effect_type_name(t));
}

// evdev's times reach 65535 ms; feel's stop at 65 s (the primer's "0 to 65 million" µs).
constexpr uint16_t kMaxTimeMs = static_cast<uint16_t>(kMaxTimeUs / 1000);

std::string time_too_long(const char* field, uint16_t ms) {
    if (ms <= kMaxTimeMs) return {};
    return std::string("ff_effect ") + field + " = " + std::to_string(ms) + " ms is out of range (allowed 0..65000 ms)";
}

// The times of the effect's own kind (evdev leaves the others' bytes to the union).
std::string check_times(const ff_effect& e) {
    std::string why = time_too_long("replay.length", e.replay.length);
    if (why.empty()) why = time_too_long("replay.delay", e.replay.delay);
    if (why.empty() && e.type != FF_RUMBLE && e.trigger.button != 0) why = time_too_long("trigger.interval", e.trigger.interval);
    const ff_envelope* envelope = e.type == FF_CONSTANT ? &e.u.constant.envelope
                                  : e.type == FF_RAMP   ? &e.u.ramp.envelope
                                  : e.type == FF_PERIODIC ? &e.u.periodic.envelope
                                                          : nullptr;
    if (why.empty() && envelope != nullptr) why = time_too_long("envelope.attack_length", envelope->attack_length);
    if (why.empty() && envelope != nullptr) why = time_too_long("envelope.fade_length", envelope->fade_length);
    if (why.empty() && e.type == FF_PERIODIC) why = time_too_long("u.periodic.period", e.u.periodic.period);
    return why;
}

// The fields every effect shares: replay, trigger.
std::string set_common(const ff_effect& e, EffectParams& p) {
    p.duration_us = e.replay.length == 0 ? kInfiniteUs : evdev_ms_to_us(e.replay.length);
    p.start_delay_us = evdev_ms_to_us(e.replay.delay);
    p.gain = kFullScale;
    if (e.trigger.button != 0) {
        const int32_t button = button_of_key(e.trigger.button);
        if (button == 0) {
            return "ff_effect trigger.button = " + hex(e.trigger.button) +
                   " is not a joystick button (allowed 0 for none, BTN_TRIGGER 0x120..0x12f, "
                   "BTN_TRIGGER_HAPPY1 0x2c0..0x2cf)";
        }
        p.trigger.kind = TriggerKind::button;
        p.trigger.index = button;
        p.trigger_repeat_interval_us = evdev_ms_to_us(e.trigger.interval);
    }
    return {};
}

}  // namespace

int32_t button_of_key(uint16_t code) noexcept {
    if (code >= BTN_TRIGGER && code <= BTN_DEAD) return code - BTN_TRIGGER + 1;
    if (code >= BTN_TRIGGER_HAPPY1 && code < BTN_TRIGGER_HAPPY1 + 16) return code - BTN_TRIGGER_HAPPY1 + 17;
    return 0;
}

uint16_t key_of_button(int32_t button) noexcept {
    if (button >= 1 && button <= 16) return static_cast<uint16_t>(BTN_TRIGGER + button - 1);
    if (button >= 17 && button <= 32) return static_cast<uint16_t>(BTN_TRIGGER_HAPPY1 + button - 17);
    return 0;
}

uint16_t abs_of_axis(int32_t axis_index) noexcept {
    static constexpr uint16_t codes[kMaxAxes] = {ABS_X, ABS_Y, ABS_Z, ABS_RX, ABS_RY, ABS_RZ};
    return axis_index >= 0 && axis_index < kMaxAxes ? codes[axis_index] : ABS_X;
}

int32_t iterations_of_count(int32_t value) noexcept { return value <= 254 ? value : kInfiniteIterations; }

Translation translate_effect(const ff_effect& e, const host::DeviceCaps& caps) {
    if (caps.axis_count < 1) return refuse("the device has no axes");
    if (std::string why = check_times(e); !why.empty()) return refuse(why);
    EffectParams p;
    if (e.type != FF_RUMBLE) {
        // FF_RUMBLE has neither trigger nor direction (games leave them uninitialised).
        if (std::string why = set_common(e, p); !why.empty()) return refuse(why);
    }
    const auto need = [&](EffectType t) -> std::string {
        p.type = t;
        return caps.supports(t) ? std::string() : not_on_device(t, caps);
    };
    Translation out;
    switch (e.type) {
        case FF_CONSTANT: {
            if (std::string why = need(EffectType::constant); !why.empty()) return refuse(why);
            p.constant.magnitude = evdev_signed_level(e.u.constant.level);
            if (std::string why = set_envelope(e.u.constant.envelope, p); !why.empty()) return refuse(why);
            if (std::string why = set_wave_axes(e.direction, caps, p); !why.empty()) return refuse(why);
            break;
        }
        case FF_RAMP: {
            if (std::string why = need(EffectType::ramp); !why.empty()) return refuse(why);
            if (e.replay.length == 0) {
                return refuse("ff_effect replay.length = 0 (endless) leaves a ramp no end to reach its end level "
                              "(allowed 1..65000 ms for FF_RAMP)");
            }
            p.ramp.start = evdev_signed_level(e.u.ramp.start_level);
            p.ramp.end = evdev_signed_level(e.u.ramp.end_level);
            if (std::string why = set_envelope(e.u.ramp.envelope, p); !why.empty()) return refuse(why);
            if (std::string why = set_wave_axes(e.direction, caps, p); !why.empty()) return refuse(why);
            break;
        }
        case FF_PERIODIC: {
            const ff_periodic_effect& w = e.u.periodic;
            const std::optional<WaveChoice> wave = wave_of(w.waveform);
            if (!wave) {
                return refuse("ff_effect u.periodic.waveform = " + hex(w.waveform) +
                              " is not offered (allowed FF_SQUARE 0x58, FF_TRIANGLE 0x59, FF_SINE 0x5a, "
                              "FF_SAW_UP 0x5b, FF_SAW_DOWN 0x5c)");
            }
            if (w.period == 0) return refuse("ff_effect u.periodic.period = 0 is out of range (allowed 1..65000 ms)");
            const bool inverted = w.magnitude < 0;
            if (std::string why = need(inverted ? wave->inverted : wave->type); !why.empty()) return refuse(why);
            const int32_t magnitude = evdev_signed_level(w.magnitude);
            p.periodic.magnitude = magnitude < 0 ? -magnitude : magnitude;
            p.periodic.offset = evdev_signed_level(w.offset);
            p.periodic.period_us = evdev_ms_to_us(w.period);
            p.periodic.phase = evdev_angle(w.phase);
            if (inverted && wave->inverted_by_phase) p.periodic.phase = (p.periodic.phase + 18000) % 36000;
            if (std::string why = set_envelope(w.envelope, p); !why.empty()) return refuse(why);
            if (std::string why = set_wave_axes(e.direction, caps, p); !why.empty()) return refuse(why);
            break;
        }
        case FF_SPRING: case FF_DAMPER: case FF_INERTIA: case FF_FRICTION: {
            if (std::string why = need(*condition_type(e.type)); !why.empty()) return refuse(why);
            p.axis_count = caps.axis_count >= 2 ? 2 : 1;
            for (int i = 0; i < p.axis_count; ++i) {
                p.axes[i] = caps.axes[i].axis;
                set_condition(e.u.condition[i], p.conditions[i]);
            }
            break;
        }
        case FF_RUMBLE: {
            if (std::string why = need(EffectType::sine); !why.empty()) return refuse(why);
            p.duration_us = e.replay.length == 0 ? kInfiniteUs : evdev_ms_to_us(e.replay.length);
            p.start_delay_us = evdev_ms_to_us(e.replay.delay);
            p.axis_count = 1;
            p.axes[0] = caps.axes[0].axis;
            p.periodic.offset = 0;
            p.periodic.phase = 0;
            EffectParams strong = p;
            strong.periodic.magnitude = evdev_unsigned_level(e.u.rumble.strong_magnitude);
            strong.periodic.period_us = kRumbleStrongPeriodUs;
            EffectParams weak = p;
            weak.periodic.magnitude = evdev_unsigned_level(e.u.rumble.weak_magnitude);
            weak.periodic.period_us = kRumbleWeakPeriodUs;
            out.effects = {strong, weak};
            return out;
        }
        default:
            return refuse("ff_effect type = " + hex(e.type) + " (" + type_name(e.type) +
                          ") is not offered (allowed FF_RUMBLE 0x50, FF_PERIODIC 0x51, FF_CONSTANT 0x52, "
                          "FF_SPRING 0x53, FF_FRICTION 0x54, FF_DAMPER 0x55, FF_INERTIA 0x56, FF_RAMP 0x57)");
    }
    out.effects.push_back(p);
    return out;
}

std::string describe_ff_effect(const ff_effect& e) {
    std::string d = type_name(e.type) + " id " + std::to_string(e.id) + ": length " + std::to_string(e.replay.length) +
                    " ms, delay " + std::to_string(e.replay.delay) + " ms";
    const auto envelope = [&](const ff_envelope& v) {
        d += ", envelope " + std::to_string(v.attack_length) + " ms " + std::to_string(v.attack_level) + " / " +
             std::to_string(v.fade_length) + " ms " + std::to_string(v.fade_level);
    };
    if (e.type != FF_RUMBLE) {
        d += ", direction " + hex(e.direction);
        if (e.trigger.button != 0) d += ", trigger " + hex(e.trigger.button) + " every " + std::to_string(e.trigger.interval) + " ms";
    }
    switch (e.type) {
        case FF_CONSTANT:
            d += ", level " + std::to_string(e.u.constant.level);
            envelope(e.u.constant.envelope);
            break;
        case FF_RAMP:
            d += ", level " + std::to_string(e.u.ramp.start_level) + " to " + std::to_string(e.u.ramp.end_level);
            envelope(e.u.ramp.envelope);
            break;
        case FF_PERIODIC:
            d += ", waveform " + hex(e.u.periodic.waveform) + ", period " + std::to_string(e.u.periodic.period) +
                 " ms, magnitude " + std::to_string(e.u.periodic.magnitude) + ", offset " +
                 std::to_string(e.u.periodic.offset) + ", phase " + hex(e.u.periodic.phase);
            envelope(e.u.periodic.envelope);
            break;
        case FF_SPRING: case FF_DAMPER: case FF_INERTIA: case FF_FRICTION:
            for (int i = 0; i < 2; ++i) {
                const ff_condition_effect& c = e.u.condition[i];
                d += ", axis " + std::to_string(i) + " coefficients " + std::to_string(c.right_coeff) + "/" +
                     std::to_string(c.left_coeff) + " saturations " + std::to_string(c.right_saturation) + "/" +
                     std::to_string(c.left_saturation) + " deadband " + std::to_string(c.deadband) + " centre " +
                     std::to_string(c.center);
            }
            break;
        case FF_RUMBLE:
            d += ", strong " + std::to_string(e.u.rumble.strong_magnitude) + ", weak " + std::to_string(e.u.rumble.weak_magnitude);
            break;
        default: break;
    }
    return d;
}

FfCapabilities ff_capabilities(const host::DeviceCaps& caps) {
    FfCapabilities c;
    const auto offer = [&](uint16_t bit, const char* name, EffectType t) {
        if (caps.supports(t)) {
            c.bits.push_back(bit);
        } else {
            c.missing.push_back(std::string(name) + " (needs " + std::string(effect_type_name(t)) + ")");
        }
    };
    offer(FF_CONSTANT, "FF_CONSTANT", EffectType::constant);
    offer(FF_RAMP, "FF_RAMP", EffectType::ramp);
    offer(FF_SPRING, "FF_SPRING", EffectType::spring);
    offer(FF_DAMPER, "FF_DAMPER", EffectType::damper);
    offer(FF_INERTIA, "FF_INERTIA", EffectType::inertia);
    offer(FF_FRICTION, "FF_FRICTION", EffectType::friction);
    offer(FF_SQUARE, "FF_SQUARE", EffectType::square);
    offer(FF_TRIANGLE, "FF_TRIANGLE", EffectType::triangle);
    offer(FF_SINE, "FF_SINE", EffectType::sine);
    offer(FF_SAW_UP, "FF_SAW_UP", EffectType::saw_up);
    offer(FF_SAW_DOWN, "FF_SAW_DOWN", EffectType::saw_down);
    // FF_PERIODIC with any of its waveforms; FF_RUMBLE plays as sines; FF_AUTOCENTER is a spring.
    bool any_wave = false;
    for (EffectType t : {EffectType::square, EffectType::triangle, EffectType::sine, EffectType::saw_up,
                         EffectType::saw_down}) {
        any_wave = any_wave || caps.supports(t);
    }
    if (any_wave) c.bits.push_back(FF_PERIODIC);
    else c.missing.emplace_back("FF_PERIODIC (needs a periodic wave)");
    offer(FF_RUMBLE, "FF_RUMBLE", EffectType::sine);
    c.bits.push_back(FF_GAIN);
    offer(FF_AUTOCENTER, "FF_AUTOCENTER", EffectType::spring);
    return c;
}

EffectParams autocenter_spring(uint16_t strength, const host::DeviceCaps& caps) {
    EffectParams p;
    p.type = EffectType::spring;
    p.duration_us = kInfiniteUs;
    p.axis_count = caps.axis_count >= 2 ? 2 : 1;
    for (int i = 0; i < p.axis_count; ++i) {
        p.axes[i] = caps.axes[i].axis;
        p.conditions[i].pos_coefficient = evdev_unsigned_level(strength);
        p.conditions[i].neg_coefficient = evdev_unsigned_level(strength);
    }
    return p;
}

}  // namespace feel::bridge
