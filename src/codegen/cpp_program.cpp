// The C++ program: the §8 wrapper functions and the host API (codegen.hpp).
//
// Each effect is written as the §8 wrapper call that comes closest to it, followed by
// assignments for whatever the wrapper does not set (a gain, a start delay, a third axis).
// "Closest" is decided by running the wrappers here: every wrapper of the effect's type is
// called with the arguments read off the effect, and the one whose result needs the fewest
// assignments wins. A wrapper that refuses its arguments (a negative magnitude is outside
// §8's 1..10000, a force profile has no wrapper) is not a candidate; with none left the
// effect starts from a default feel::EffectParams. Because the generator calls the very
// functions the program will call, and effect_code.cpp checks that the assignments complete
// the wrapper's result into the effect, the program builds exactly the effect of the file.
#include <stdexcept>
#include <string>
#include <vector>

#include "effect_code.hpp"
#include "feel/iforce.hpp"
#include "generated_program.hpp"

namespace feel::codegen {
namespace {

namespace fi = feel::iforce;

struct Start {
    std::string call;  // the initializer: "fi::x_spring(...)" or "feel::EffectParams{}"
    EffectParams params;
};

std::string arg(int32_t v) { return std::to_string(v); }
std::string arg(int64_t v) { return v == kInfiniteUs ? "feel::kInfiniteUs" : std::to_string(v); }
std::string arg(bool v) { return v ? "true" : "false"; }
std::string arg(WallSense s) { return s == WallSense::positive ? "feel::WallSense::positive" : "feel::WallSense::negative"; }
std::string arg(SweepSense s) {
    return s == SweepSense::clockwise ? "feel::SweepSense::clockwise" : "feel::SweepSense::counterclockwise";
}
std::string arg(Waveform w) {
    static constexpr const char* kNames[] = {"sine", "square", "triangle", "saw_up", "saw_down"};
    return std::string("feel::Waveform::") + kNames[static_cast<size_t>(w)];
}
std::string arg(Axis a) { return "feel::Axis::" + std::string(axis_name(a)); }
std::string arg(Trigger t) {
    switch (t.kind) {
        case TriggerKind::none: return "fi::kNoTrigger";
        case TriggerKind::button: return "fi::button_trigger(" + std::to_string(t.index) + ")";
        case TriggerKind::hat: return "fi::hat_trigger(" + std::to_string(t.index) + ")";
    }
    return "fi::kNoTrigger";
}

// Calls the wrapper; if it accepts the arguments, its call and result are a candidate.
template <class F, class... A>
void consider(std::vector<Start>& out, std::string_view name, F wrapper, A... args) {
    try {
        EffectParams p = wrapper(args...);
        std::string call = "fi::" + std::string(name) + "(";
        bool first = true;
        ((call += (first ? "" : ", ") + arg(args), first = false), ...);
        out.push_back({call + ")", p});
    } catch (const std::invalid_argument&) {
        // not this wrapper: its §8 ranges exclude the effect
    }
}

// The §8 wrappers that make effects of p's type, called with p's values.
std::vector<Start> candidates(const EffectParams& p) {
    std::vector<Start> out;
    const ConditionBlock& c = p.conditions[0];
    const ConditionBlock& c1 = p.conditions[1];
    const int32_t angle = p.direction.kind == DirectionKind::polar ? p.direction.value[0] : 0;
    const Envelope& env = p.envelope;
    const WallBlock& w = p.wall;
    const BarrierBlock& b = p.barrier;
    const DynamicBlock& d = p.dynamic;
    const PeriodicBlock& pe = p.periodic;
    const auto cond6 = [&](auto wrapper, std::string_view name) {
        consider(out, name, wrapper, c.pos_coefficient, c.neg_coefficient, c.offset, c.pos_saturation,
                 c.neg_saturation, c.deadband);
    };
    const auto cond12 = [&](auto wrapper, std::string_view name) {
        consider(out, name, wrapper, c.pos_coefficient, c.neg_coefficient, c.offset, c.pos_saturation,
                 c.neg_saturation, c.deadband, c1.pos_coefficient, c1.neg_coefficient, c1.offset,
                 c1.pos_saturation, c1.neg_saturation, c1.deadband);
    };
    switch (p.type) {
        case EffectType::spring:
            cond6([](auto... a) { return fi::x_spring(a...); }, "x_spring");
            cond6([](auto... a) { return fi::y_spring(a...); }, "y_spring");
            cond12([](auto... a) { return fi::spring(a...); }, "spring");
            consider(out, "center_spring", [](auto... a) { return fi::center_spring(a...); }, c.pos_coefficient,
                     c.pos_saturation, c.deadband);
            consider(out, "spring_at_current_location", [](auto... a) { return fi::spring_at_current_location(a...); },
                     c.pos_coefficient, c.pos_saturation, c.deadband);
            break;
        case EffectType::angle_spring:
            consider(out, "angle_spring", [](auto... a) { return fi::angle_spring(a...); }, c.pos_coefficient,
                     c.neg_coefficient, c.offset, c.pos_saturation, c.neg_saturation, c.deadband, angle);
            break;
        case EffectType::damper:
            cond6([](auto... a) { return fi::x_damper(a...); }, "x_damper");
            cond6([](auto... a) { return fi::y_damper(a...); }, "y_damper");
            cond12([](auto... a) { return fi::damper(a...); }, "damper");
            break;
        case EffectType::inertia:
            consider(out, "x_inertia", [](auto... a) { return fi::x_inertia(a...); }, c.pos_coefficient, c.pos_saturation);
            consider(out, "y_inertia", [](auto... a) { return fi::y_inertia(a...); }, c.pos_coefficient, c.pos_saturation);
            consider(out, "inertia", [](auto... a) { return fi::inertia(a...); }, c.pos_coefficient, c.pos_saturation);
            break;
        case EffectType::friction:
            consider(out, "friction", [](auto... a) { return fi::friction(a...); }, c.pos_coefficient);
            consider(out, "x_friction", [](auto... a) { return fi::x_friction(a...); }, c.pos_coefficient, c.neg_coefficient);
            consider(out, "y_friction", [](auto... a) { return fi::y_friction(a...); }, c.pos_coefficient, c.neg_coefficient);
            break;
        case EffectType::texture: {
            const TextureBlock& t = p.texture;
            consider(out, "texture", [](auto... a) { return fi::texture(a...); }, t.pos_roughness, t.spacing, t.density, angle);
            consider(out, "x_texture", [](auto... a) { return fi::x_texture(a...); }, t.pos_roughness, t.neg_roughness,
                     t.spacing, t.density);
            consider(out, "y_texture", [](auto... a) { return fi::y_texture(a...); }, t.pos_roughness, t.neg_roughness,
                     t.spacing, t.density);
            break;
        }
        case EffectType::angle_wall:
            consider(out, "wall", [](auto... a) { return fi::wall(a...); }, w.hardness, w.sense, w.offset, w.angle);
            break;
        case EffectType::axis_wall:
            consider(out, "horizontal_wall", [](auto... a) { return fi::horizontal_wall(a...); }, w.hardness, w.sense,
                     w.offset, w.surface_friction, w.surface_texture, w.clipping);
            consider(out, "vertical_wall", [](auto... a) { return fi::vertical_wall(a...); }, w.hardness, w.sense,
                     w.offset, w.surface_friction, w.surface_texture, w.clipping);
            break;
        case EffectType::angle_barrier:
            consider(out, "barrier", [](auto... a) { return fi::barrier(a...); }, b.pos_hardness, b.neg_hardness,
                     b.thickness, b.offset, b.angle);
            break;
        case EffectType::axis_barrier:
            consider(out, "horizontal_barrier", [](auto... a) { return fi::horizontal_barrier(a...); }, b.pos_hardness,
                     b.neg_hardness, b.thickness, b.offset, b.surface_friction, b.surface_texture);
            consider(out, "vertical_barrier", [](auto... a) { return fi::vertical_barrier(a...); }, b.pos_hardness,
                     b.neg_hardness, b.thickness, b.offset, b.surface_friction, b.surface_texture);
            break;
        case EffectType::vector_force:
            consider(out, "vector_force", [](auto... a) { return fi::vector_force(a...); }, p.constant.magnitude,
                     p.duration_us, angle);
            break;
        case EffectType::constant:
            consider(out, "constant_force", [](auto... a) { return fi::constant_force(a...); }, p.constant.magnitude,
                     p.duration_us, angle);
            consider(out, "constant_force_trigger", [](auto... a) { return fi::constant_force_trigger(a...); },
                     p.constant.magnitude, p.duration_us, angle, p.trigger, p.trigger_repeat_interval_us);
            consider(out, "envelope_constant", [](auto... a) { return fi::envelope_constant(a...); },
                     p.constant.magnitude, p.duration_us, angle, env.impulse_level, env.settle_time_us, env.fade_level,
                     env.fade_time_us, p.trigger, p.trigger_repeat_interval_us);
            break;
        case EffectType::ramp:
            consider(out, "ramp", [](auto... a) { return fi::ramp(a...); }, p.ramp.start, p.ramp.end, p.duration_us,
                     angle, p.trigger, p.trigger_repeat_interval_us);
            consider(out, "ramp_envelope", [](auto... a) { return fi::ramp_envelope(a...); }, p.ramp.start, p.ramp.end,
                     p.duration_us, angle, env.impulse_level, env.settle_time_us, env.fade_level, env.fade_time_us,
                     p.trigger, p.trigger_repeat_interval_us);
            break;
        case EffectType::sine:
        case EffectType::square:
        case EffectType::triangle:
        case EffectType::saw_up:
        case EffectType::saw_down: {
            const Waveform wf = waveform_of(p.type);
            consider(out, "periodic", [](auto... a) { return fi::periodic(a...); }, wf, pe.magnitude, pe.offset,
                     pe.phase, pe.period_us, p.duration_us, angle, p.trigger, p.trigger_repeat_interval_us);
            consider(out, "envelope_periodic", [](auto... a) { return fi::envelope_periodic(a...); }, wf, pe.magnitude,
                     pe.offset, pe.phase, pe.period_us, p.duration_us, angle, env.impulse_level, env.settle_time_us,
                     env.fade_level, env.fade_time_us, p.trigger, p.trigger_repeat_interval_us);
            consider(out, "delayed_periodic", [](auto... a) { return fi::delayed_periodic(a...); }, p.start_delay_us, wf,
                     pe.magnitude, pe.offset, pe.phase, pe.period_us, p.duration_us, angle, p.trigger,
                     p.trigger_repeat_interval_us);
            break;
        }
        case EffectType::sweep_sine:
        case EffectType::sweep_square:
        case EffectType::sweep_triangle:
        case EffectType::sweep_saw_up:
        case EffectType::sweep_saw_down:
            consider(out, "sweep_periodic", [](auto... a) { return fi::sweep_periodic(a...); }, pe.sweep_start_angle,
                     pe.sweep_end_angle, pe.sweep_sense, waveform_of(p.type), pe.magnitude, pe.offset, pe.period_us,
                     pe.phase, p.duration_us);
            break;
        case EffectType::dynamic_recoil:
            consider(out, "dynamic_recoil", [](auto... a) { return fi::dynamic_recoil(a...); }, d.blast_direction,
                     d.blast_intensity, d.dynamic_mass, d.blast_resonance, d.blast_decay);
            break;
        case EffectType::dynamic_impact:
            consider(out, "dynamic_impact", [](auto... a) { return fi::dynamic_impact(a...); }, d.impact_direction,
                     d.impact_intensity, d.dynamic_mass, d.elasticity, d.collision_absorption);
            break;
        case EffectType::dynamic_liquid:
            consider(out, "dynamic_liquid", [](auto... a) { return fi::dynamic_liquid(a...); }, d.density, d.settle,
                     d.viscosity);
            break;
        case EffectType::dynamic_inertia:
            consider(out, "dynamic_inertia", [](auto... a) { return fi::dynamic_inertia(a...); }, d.inertia, d.play);
            break;
        case EffectType::dynamic_center_drift:
            consider(out, "dynamic_center_drift", [](auto... a) { return fi::dynamic_center_drift(a...); }, d.stiffness,
                     d.drift_resistance);
            break;
        case EffectType::dynamic_sling:
            consider(out, "dynamic_sling", [](auto... a) { return fi::dynamic_sling(a...); }, d.ball_mass,
                     d.string_length, d.string_compliance, d.ball_damping, d.interim_reporting);
            break;
        case EffectType::dynamic_paddle:
            consider(out, "dynamic_paddle", [](auto... a) { return fi::dynamic_paddle(a...); }, d.ball_mass,
                     d.initial_velocity, d.initial_velocity_direction, d.paddle_compliance, d.paddle_damping, d.gravity,
                     d.interim_reporting);
            break;
        case EffectType::dynamic_control_law: {
            const ControlLawBlock& l = d.control_law[0];
            consider(out, "dynamic_control_law", [](auto... a) { return fi::dynamic_control_law(a...); }, l.mass,
                     l.k_pos, l.k_neg, l.b, l.vel_init, l.pos_init, l.half_cycles, l.length, l.drag, l.gravity,
                     d.interim_reporting, p.axes[0]);
            break;
        }
        default: break;  // smart_pop, force_profile: no §8 wrapper
    }
    return out;
}

// The effect's statements: its initializer and the assignments after it.
std::string effect_statements(const format::EffectSpec& spec, const std::string& what, const std::string& samples_name) {
    const EffectParams& p = spec.params;
    // A wrapper whenever one accepts the values (the program reads as §8 code), the one that
    // needs the fewest assignments; a default EffectParams only when no wrapper does.
    Start best{"feel::EffectParams{}", EffectParams{}};
    std::vector<Assignment> best_fix = assignments(best.params, p, Dialect::cpp);
    bool wrapped = false;
    for (Start& s : candidates(p)) {
        std::vector<Assignment> fix = assignments(s.params, p, Dialect::cpp);
        if (!wrapped || fix.size() < best_fix.size()) {
            best = std::move(s);
            best_fix = std::move(fix);
            wrapped = true;
        }
    }
    std::string out = "    {\n        feel::EffectParams e = " + best.call + ";\n";
    for (const Assignment& a : best_fix) out += "        e." + a.path + " = " + a.value + ";\n";
    out += "        effects.push_back(create(device, e, " + string_literal(what) +
           (samples_name.empty() ? "" : ", " + samples_name) + "));\n    }\n";
    return out;
}

}  // namespace

std::string cpp_program(const ExportPlan& plan) {
    std::string out;
    out += "// Generated by `feel export --lang cpp` from " + comment_text(plan.file_path) + " (feel/1).\n";
    out += "// The sensations' effects built with the I-FORCE 2.0 wrapper functions of §8 (feel::iforce,\n"
           "// docs/wrappers.md) and created on a device through the host API (docs/host-api.md).\n"
           "// Build: target_link_libraries(game PRIVATE feel::feel)  (find_package(feel)).\n"
           "// Run:   game [DEVICE [SENSATION]]: DEVICE sim:iforce2 (default), unix:PATH or tcp:HOST:PORT;\n"
           "//        SENSATION is played; the effects stay on the device until Enter (or end of input).\n";
    out += R"(#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "feel/host/device.hpp"
#include "feel/iforce.hpp"

namespace fi = feel::iforce;

namespace {

// CreateEffect + Download; a refusal is printed (the field and its range) and ends the program.
feel::host::Effect create(feel::host::Device& device, const feel::EffectParams& params, const char* what,
                          std::span<const int16_t> samples = {}) {
    feel::host::Result<feel::host::Effect> effect = device.create_effect(params, samples);
    if (!effect) {
        std::fprintf(stderr, "%s: %s\n", what, effect.status().message.c_str());
        std::exit(1);
    }
    return std::move(effect).value();
}
)";
    for (const ExportedSensation& es : plan.sensations) {
        const format::Sensation& s = *es.sensation;
        std::string samples_decls;
        std::string body;
        for (size_t i = 0; i < s.effects.size(); ++i) {
            const format::EffectSpec& spec = s.effects[i];
            std::string samples_name;
            if (!spec.samples.empty()) {
                samples_name = "k_" + es.ident + "_samples_" + std::to_string(i);
                samples_decls += "\n// The force profile's samples (§6.6.d), interleaved by channel, ±10000.\n"
                                 "constexpr int16_t " + samples_name + "[] = {\n" +
                                 sample_initializer(spec.samples, "    ") + "\n};\n";
            }
            const std::string what = s.compound ? s.name + ", effect " + std::to_string(i) : s.name;
            body += effect_statements(spec, what, samples_name);
        }
        out += samples_decls;
        out += "\n" + comment_lines("\"" + s.name + "\"" + (s.description ? ": " + *s.description : std::string()), "// ");
        out += "std::vector<feel::host::Effect> create_" + es.ident + "(feel::host::Device& device) {\n";
        out += "    std::vector<feel::host::Effect> effects;\n" + body + "    return effects;\n}\n";
    }
    out += R"(
}  // namespace

int main(int argc, char** argv) {
    const char* address = argc > 1 ? argv[1] : "sim:iforce2";
    feel::host::Result<feel::host::Device> device = feel::host::Device::open(address);
    if (!device) {
        std::fprintf(stderr, "%s\n", device.status().message.c_str());
        return 1;
    }
    std::vector<std::pair<std::string_view, std::vector<feel::host::Effect>>> sensations;
)";
    for (const ExportedSensation& es : plan.sensations) {
        out += "    sensations.emplace_back(" + string_literal(es.sensation->name) + ", create_" + es.ident +
               "(device.value()));\n";
    }
    out += R"(    if (argc > 2) {
        bool found = false;
        for (auto& [name, effects] : sensations) {
            if (name != argv[2]) continue;
            found = true;
            for (feel::host::Effect& effect : effects) {
                if (feel::host::Status s = effect.start(); !s.ok()) {
                    std::fprintf(stderr, "play %s: %s\n", argv[2], s.message.c_str());
                    return 1;
                }
            }
        }
        if (!found) {
            std::fprintf(stderr, "no sensation \"%s\" here\n", argv[2]);
            return 2;
        }
    }
    std::printf("ready: %zu sensations on %s; Enter ends\n", sensations.size(), address);
    std::fflush(stdout);
    for (int c = std::getchar(); c != EOF && c != '\n'; c = std::getchar()) {
    }
    return 0;
}
)";
    return out;
}

}  // namespace feel::codegen
