// The field walk behind every generated effect (effect_code.hpp).
#include "effect_code.hpp"

#include <cctype>
#include <functional>
#include <span>
#include <stdexcept>
#include <string_view>

#include "feel/axis.hpp"
#include "feel/effect_type.hpp"
#include "format/effect_fields.hpp"

namespace feel::codegen {
namespace {

using format::detail::BlockExtra;
using format::detail::BlockShape;
using format::detail::FieldSpec;
using format::detail::ValueKind;

// How a field's value is written.
enum class Literal {
    integer,
    duration,     // kInfiniteUs by name
    iterations,   // kInfiniteIterations by name
    boolean,
    effect_type,  // feel::EffectType::sine / FEEL_TYPE_SINE
    axis,         // feel::Axis::x / FEEL_AXIS_X
    direction,    // feel::DirectionKind::polar / FEEL_DIRECTION_POLAR
    trigger,      // feel::TriggerKind::button / FEEL_TRIGGER_BUTTON
    choice,       // an enumerator of the format's choices (offset mode, wall sense, sweep sense)
};

struct Field {
    std::string cpp_path;
    std::string c_path;
    Literal literal = Literal::integer;
    std::span<const std::string_view> choices{};
    std::string_view cpp_enum{};  // choice: the C++ enum's name
    std::string_view c_prefix{};  // choice: the C constants' prefix
    std::function<int64_t(const EffectParams&)> get;
    std::function<void(EffectParams&, int64_t)> set;
};

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// The C++ enum and C prefix of the format's choice fields, by field name.
void name_choice(Field& f, std::string_view field_name) {
    if (field_name == "offset_mode") {
        f.cpp_enum = "feel::OffsetMode";
        f.c_prefix = "FEEL_OFFSET_";
    } else if (field_name == "sense") {
        f.cpp_enum = "feel::WallSense";
        f.c_prefix = "FEEL_WALL_SENSE_";
    } else if (field_name == "sweep_sense") {
        f.cpp_enum = "feel::SweepSense";
        f.c_prefix = "FEEL_SWEEP_";
    } else {
        throw std::logic_error("codegen: the format's choice field \"" + std::string(field_name) +
                               "\" has no C++ enum or C constants here");
    }
}

// A field of the format's table. `cpp_block` is where its block lives in EffectParams
// ("conditions[1]", "periodic", "dynamic.control_law[0]"); C names a few fields differently.
Field table_field(const FieldSpec& spec, const std::string& cpp_block, std::string_view key, int slot) {
    Field f;
    f.cpp_path = cpp_block + "." + std::string(spec.name);
    f.c_path = f.cpp_path;
    if (key == "constant") f.c_path = "constant_magnitude";
    if (key == "ramp") f.c_path = "ramp_" + std::string(spec.name);
    if (key == "barrier" && spec.name == "offset_mode") f.c_path = "barrier_offset_mode";
    switch (spec.kind) {
        case ValueKind::i32:
        case ValueKind::i64: f.literal = Literal::integer; break;
        case ValueKind::boolean: f.literal = Literal::boolean; break;
        case ValueKind::choice:
            f.literal = Literal::choice;
            f.choices = spec.choices;
            name_choice(f, spec.name);
            break;
    }
    f.get = [get = spec.get, slot](const EffectParams& p) { return get(p, slot); };
    f.set = [set = spec.set, slot](EffectParams& p, int64_t v) { set(p, slot, v); };
    return f;
}

template <class Get, class Set>
Field common(std::string path, Literal literal, Get get, Set set) {
    Field f;
    f.cpp_path = path;
    f.c_path = std::move(path);
    f.literal = literal;
    f.get = get;
    f.set = set;
    return f;
}

// Every field of an effect of type `type`: the Effect Structure (§6.3), then the type's block.
std::vector<Field> fields_of(EffectType type) {
    std::vector<Field> out;
    out.push_back(common("type", Literal::effect_type, [](const EffectParams& p) { return int64_t{static_cast<uint8_t>(p.type)}; },
                         [](EffectParams& p, int64_t v) { p.type = static_cast<EffectType>(v); }));
    out.push_back(common("duration_us", Literal::duration, [](const EffectParams& p) { return p.duration_us; },
                         [](EffectParams& p, int64_t v) { p.duration_us = v; }));
    out.push_back(common("start_delay_us", Literal::integer, [](const EffectParams& p) { return p.start_delay_us; },
                         [](EffectParams& p, int64_t v) { p.start_delay_us = v; }));
    out.push_back(common("gain", Literal::integer, [](const EffectParams& p) { return int64_t{p.gain}; },
                         [](EffectParams& p, int64_t v) { p.gain = static_cast<int32_t>(v); }));
    out.push_back(common("iterations", Literal::iterations, [](const EffectParams& p) { return int64_t{p.iterations}; },
                         [](EffectParams& p, int64_t v) { p.iterations = static_cast<int32_t>(v); }));
    out.push_back(common("axis_count", Literal::integer, [](const EffectParams& p) { return int64_t{p.axis_count}; },
                         [](EffectParams& p, int64_t v) { p.axis_count = static_cast<int32_t>(v); }));
    for (int i = 0; i < kMaxAxes; ++i) {
        out.push_back(common("axes[" + std::to_string(i) + "]", Literal::axis,
                             [i](const EffectParams& p) { return int64_t{static_cast<uint8_t>(p.axes[i])}; },
                             [i](EffectParams& p, int64_t v) { p.axes[i] = static_cast<Axis>(v); }));
    }
    out.push_back(common("direction.kind", Literal::direction,
                         [](const EffectParams& p) { return int64_t{static_cast<uint8_t>(p.direction.kind)}; },
                         [](EffectParams& p, int64_t v) { p.direction.kind = static_cast<DirectionKind>(v); }));
    for (int i = 0; i < 3; ++i) {
        out.push_back(common("direction.value[" + std::to_string(i) + "]", Literal::integer,
                             [i](const EffectParams& p) { return int64_t{p.direction.value[i]}; },
                             [i](EffectParams& p, int64_t v) { p.direction.value[i] = static_cast<int32_t>(v); }));
    }
    out.push_back(common("trigger.kind", Literal::trigger,
                         [](const EffectParams& p) { return int64_t{static_cast<uint8_t>(p.trigger.kind)}; },
                         [](EffectParams& p, int64_t v) { p.trigger.kind = static_cast<TriggerKind>(v); }));
    out.push_back(common("trigger.index", Literal::integer, [](const EffectParams& p) { return int64_t{p.trigger.index}; },
                         [](EffectParams& p, int64_t v) { p.trigger.index = static_cast<int32_t>(v); }));
    out.push_back(common("trigger_repeat_interval_us", Literal::integer,
                         [](const EffectParams& p) { return p.trigger_repeat_interval_us; },
                         [](EffectParams& p, int64_t v) { p.trigger_repeat_interval_us = v; }));
    out.push_back(common("has_envelope", Literal::boolean, [](const EffectParams& p) { return int64_t{p.has_envelope}; },
                         [](EffectParams& p, int64_t v) { p.has_envelope = v != 0; }));
    for (const FieldSpec& spec : format::detail::envelope_fields()) out.push_back(table_field(spec, "envelope", "envelope", 0));

    const format::detail::BlockLayout layout = format::detail::block_layout(type);
    const std::string key(layout.key);
    if (layout.extra == BlockExtra::control_law) {
        for (int slot = 0; slot < kMaxAxes; ++slot) {
            const std::string block = "dynamic.control_law[" + std::to_string(slot) + "]";
            for (const FieldSpec& spec : format::detail::control_law_fields())
                out.push_back(table_field(spec, block, "control_law", slot));
        }
    }
    const int slots = layout.shape == BlockShape::object ? 1 : kMaxAxes;
    for (int slot = 0; slot < slots; ++slot) {
        const std::string block = layout.shape == BlockShape::object ? key : key + "[" + std::to_string(slot) + "]";
        for (const FieldSpec& spec : layout.fields) out.push_back(table_field(spec, block, key, slot));
    }
    if (layout.extra == BlockExtra::samples) {
        // Not a field of the file (the length of "samples"), but of the struct.
        out.push_back(common("custom.sample_count", Literal::integer,
                             [](const EffectParams& p) { return int64_t{p.custom.sample_count}; },
                             [](EffectParams& p, int64_t v) { p.custom.sample_count = static_cast<int32_t>(v); }));
    }
    return out;
}

std::string literal(const Field& f, int64_t v, Dialect d) {
    const bool cpp = d == Dialect::cpp;
    switch (f.literal) {
        case Literal::integer: return std::to_string(v);
        case Literal::duration:
            if (v == kInfiniteUs) return cpp ? "feel::kInfiniteUs" : "FEEL_INFINITE";
            return std::to_string(v);
        case Literal::iterations:
            if (v == kInfiniteIterations) return cpp ? "feel::kInfiniteIterations" : "FEEL_INFINITE_ITERATIONS";
            return std::to_string(v);
        case Literal::boolean: return v != 0 ? "true" : "false";
        case Literal::effect_type: return type_literal(static_cast<EffectType>(v), d);
        case Literal::axis: {
            const std::string_view name = axis_name(static_cast<Axis>(v));
            return cpp ? "feel::Axis::" + std::string(name) : "FEEL_AXIS_" + upper(name);
        }
        case Literal::direction: {
            static constexpr std::string_view kNames[] = {"none", "polar", "cartesian", "spherical", "moments"};
            const std::string_view name = kNames[static_cast<size_t>(v)];
            return cpp ? "feel::DirectionKind::" + std::string(name) : "FEEL_DIRECTION_" + upper(name);
        }
        case Literal::trigger: {
            static constexpr std::string_view kNames[] = {"none", "button", "hat"};
            const std::string_view name = kNames[static_cast<size_t>(v)];
            return cpp ? "feel::TriggerKind::" + std::string(name) : "FEEL_TRIGGER_" + upper(name);
        }
        case Literal::choice: {
            const std::string_view name = f.choices[static_cast<size_t>(v)];
            return cpp ? std::string(f.cpp_enum) + "::" + std::string(name) : std::string(f.c_prefix) + upper(name);
        }
    }
    return std::to_string(v);
}

}  // namespace

std::vector<Assignment> assignments(const EffectParams& start, const EffectParams& effect, Dialect dialect) {
    std::vector<Assignment> out;
    EffectParams applied = start;
    for (const Field& f : fields_of(effect.type)) {
        const int64_t want = f.get(effect);
        if (f.get(start) == want) continue;
        f.set(applied, want);
        out.push_back({dialect == Dialect::cpp ? f.cpp_path : f.c_path, literal(f, want, dialect)});
    }
    if (!(applied == effect)) {
        throw std::logic_error("codegen: the assignments for a " + std::string(effect_type_name(effect.type)) +
                               " effect do not reproduce it (a field is missing from the walk)");
    }
    return out;
}

std::string type_literal(EffectType type, Dialect dialect) {
    const std::string_view name = effect_type_name(type);
    return dialect == Dialect::cpp ? "feel::EffectType::" + std::string(name) : "FEEL_TYPE_" + upper(name);
}

std::string identifier(std::string_view name) {
    std::string out;
    if (!name.empty() && std::isdigit(static_cast<unsigned char>(name.front()))) out = "s_";
    for (char c : name) out += (c == '-' || c == '.') ? '_' : c;
    return out;
}

std::string comment_text(std::string_view text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n' || c == '\r') {
            out += ' ';
        } else if (c == '*' && i + 1 < text.size() && text[i + 1] == '/') {
            out += "* ";  // never close a C comment
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            out += "/ ";
        } else {
            out += c;
        }
    }
    return out;
}

std::string comment_lines(std::string_view text, std::string_view lead, size_t width) {
    const std::string flat = comment_text(text);
    std::string out;
    std::string line(lead);
    size_t at = 0;
    while (at < flat.size()) {
        const size_t space = flat.find(' ', at);
        const std::string_view word = std::string_view(flat).substr(at, space == std::string::npos ? std::string::npos : space - at);
        at = space == std::string::npos ? flat.size() : space + 1;
        if (word.empty()) continue;
        if (line.size() > lead.size() && line.size() + 1 + word.size() > width) {
            out += line + "\n";
            line = lead;
        }
        if (line.size() > lead.size()) line += ' ';
        line += word;
    }
    return out + line + "\n";
}

std::string string_literal(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

}  // namespace feel::codegen
