// The field description (field_schema.hpp): the format's field table, with the
// validator's ranges probed from a valid effect of each type.
#include "field_schema.hpp"

#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>

#include "feel/effect_type.hpp"
#include "feel/effect_validation.hpp"
#include "format/effect_fields.hpp"

namespace feel::studio {
namespace {

using format::detail::FieldSpec;
using format::detail::ValueKind;
using json = nlohmann::json;

std::string unit_of(std::string_view name) {
    if (name.ends_with("_us")) return "µs";
    if (name.find("angle") != std::string_view::npos || name.find("direction") != std::string_view::npos ||
        name == "phase") {
        return "0.01°";
    }
    if (name == "half_cycles" || name == "channels" || name == "iterations") return "count";
    return "1/10000 of full scale";
}

// The range the validator enforces on one field, read from its errors for a value far
// above and far below. Either end stays unset when the validator names another rule.
void probe_range(json& out, std::string_view path, const EffectParams& valid,
                 void (*set)(EffectParams&, int, int64_t), int slot, int64_t huge,
                 std::span<const int16_t> samples = {}) {
    for (int64_t v : {huge, -huge}) {
        EffectParams p = valid;
        set(p, slot, v);
        const Error e = validate_effect(p, samples);
        if (!e || !e.has_range) continue;
        const std::string_view field(e.field, strnlen(e.field, sizeof e.field));
        if (!field.ends_with(path)) continue;
        out["min"] = e.allowed.min;
        out["max"] = e.allowed.max;
        return;
    }
}

json describe(const FieldSpec& f, std::string_view path, const EffectParams* valid, int slot,
              std::span<const int16_t> samples) {
    json d = {{"name", f.name}, {"required", f.required}, {"unit", unit_of(f.name)}};
    if (d["unit"] == "0.01°") {  // the form shows angles in degrees; the file keeps 0.01°
        d["scale"] = 0.01;
        d["shown_unit"] = "°";
    }
    switch (f.kind) {
        case ValueKind::boolean:
            d["kind"] = "boolean";
            d["unit"] = "";  // a yes or no has no unit
            break;
        case ValueKind::choice: {
            d["kind"] = "choice";
            d["unit"] = "";  // one of the named choices
            json c = json::array();
            for (std::string_view s : f.choices) c.push_back(s);
            d["choices"] = c;
            break;
        }
        case ValueKind::i32:
        case ValueKind::i64: {
            d["kind"] = "integer";
            if (valid != nullptr) {
                const int64_t huge = f.kind == ValueKind::i32 ? std::numeric_limits<int32_t>::max()
                                                               : int64_t{1} << 40;
                probe_range(d, path, *valid, f.set, slot, huge, samples);
            }
            break;
        }
    }
    return d;
}

std::string_view shape_name(format::detail::BlockShape s) {
    switch (s) {
        case format::detail::BlockShape::object: return "object";
        case format::detail::BlockShape::per_axis: return "per_axis";
        case format::detail::BlockShape::one_block: return "one_block";
    }
    return "object";
}

std::string_view class_name(EffectClass c) {
    switch (c) {
        case EffectClass::condition: return "condition";
        case EffectClass::wave: return "wave";
        case EffectClass::dynamic: return "dynamic";
    }
    return "wave";
}

// The fields every effect has that are not in a block table: the reader handles them
// itself (effect_reader.cpp); their ranges are probed the same way.
struct CommonField {
    const char* name;
    bool required;
    bool infinite;  // may be "infinite"
    void (*set)(EffectParams&, int, int64_t);
    int64_t huge = int64_t{1} << 40;  // far out of range, and what the field can hold
};
constexpr int64_t kHugeI32 = std::numeric_limits<int32_t>::max();
constexpr CommonField kCommon[] = {
    {"duration_us", true, true, [](EffectParams& p, int, int64_t v) { p.duration_us = v; }},
    {"start_delay_us", false, false, [](EffectParams& p, int, int64_t v) { p.start_delay_us = v; }},
    {"iterations", false, true,
     [](EffectParams& p, int, int64_t v) { p.iterations = static_cast<int32_t>(v); }, kHugeI32},
    {"gain", false, false, [](EffectParams& p, int, int64_t v) { p.gain = static_cast<int32_t>(v); }, kHugeI32},
    {"trigger_repeat_interval_us", false, false,
     [](EffectParams& p, int, int64_t v) {
         p.trigger = {TriggerKind::button, 1};
         p.trigger_repeat_interval_us = v;
     }},
};

// The direction (§6.5): one of four forms, each for the axes it fits, with its components.
// The components' ranges are probed like every other field's, from a sine on those axes
// given a valid direction of that form (its `default`, which the form starts with).
struct DirectionForm {
    const char* form;
    DirectionKind kind;
    std::initializer_list<Axis> axes;  // the axes the probe plays on
    bool exact;                        // the effect's axes must be exactly these (else a subset)
    bool per_axis;                     // one component per axis of the effect
    std::initializer_list<const char*> components;  // names, when not per axis
    int32_t defaults[3];
};
const DirectionForm kDirectionForms[] = {
    {"polar", DirectionKind::polar, {Axis::x, Axis::y}, true, false, {"angle"}, {9000, 0, 0}},
    {"spherical", DirectionKind::spherical, {Axis::x, Axis::y, Axis::z}, true, false, {"azimuth", "elevation"},
     {0, 9000, 0}},
    {"cartesian", DirectionKind::cartesian, {Axis::x, Axis::y, Axis::z}, false, true, {}, {10000, 0, 0}},
    {"moments", DirectionKind::moments, {Axis::rx, Axis::ry, Axis::rz}, false, true, {}, {10000, 0, 0}},
};

json describe_direction(const EffectParams& sine) {
    json forms = json::array();
    for (const DirectionForm& f : kDirectionForms) {
        EffectParams p = sine;
        p.axis_count = 0;
        json axes = json::array();
        for (Axis a : f.axes) {
            p.axes[p.axis_count++] = a;
            axes.push_back(axis_name(a));
        }
        p.direction.kind = f.kind;
        for (int i = 0; i < 3; ++i) p.direction.value[i] = f.defaults[i];
        json components = json::array();
        const size_t count = f.per_axis ? 1 : f.components.size();
        for (size_t i = 0; i < count; ++i) {
            const std::string name = f.per_axis ? "component" : f.components.begin()[i];
            json c = {{"name", name}, {"kind", "integer"}, {"required", true},
                      {"unit", f.per_axis ? "1/10000 of full scale" : "0.01°"}};
            if (!f.per_axis) {
                c["scale"] = 0.01;  // shown in degrees
                c["shown_unit"] = "°";
            }
            const std::string path = std::string("direction.") + f.form +
                                     (f.per_axis || f.components.size() > 1 ? "[" + std::to_string(i) + "]" : "");
            probe_range(c, path, p, [](EffectParams& q, int slot, int64_t v) {
                q.direction.value[slot] = static_cast<int32_t>(v);
            }, static_cast<int>(i), std::numeric_limits<int32_t>::max());
            components.push_back(c);
        }
        json defaults = json::array();
        for (size_t i = 0; i < (f.per_axis ? 3 : f.components.size()); ++i) defaults.push_back(f.defaults[i]);
        forms.push_back({{"form", f.form}, {"axes", axes}, {"exact_axes", f.exact}, {"per_axis", f.per_axis},
                         {"components", components}, {"default", defaults}});
    }
    return {{"forms", forms}};
}

}  // namespace

json describe_fields(const format::SensationFile& starters) {
    json types = json::array();
    const EffectParams* any_valid = nullptr;
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto type = static_cast<EffectType>(i);
        const format::EffectSpec* starter = nullptr;
        for (const format::Sensation& s : starters.sensations) {
            if (!s.effects.empty() && s.effects.front().params.type == type) starter = &s.effects.front();
        }
        if (starter == nullptr) continue;
        if (any_valid == nullptr) any_valid = &starter->params;
        const format::detail::BlockLayout layout = format::detail::block_layout(type);
        json fields = json::array();
        const std::string prefix = layout.shape == format::detail::BlockShape::object
                                       ? std::string(layout.key) + "."
                                       : std::string(layout.key) + "[0].";
        for (const FieldSpec& f : layout.fields) {
            fields.push_back(describe(f, prefix + std::string(f.name), &starter->params, 0, starter->samples));
        }
        json t = {{"type", effect_type_name(type)},
                  {"class", class_name(effect_class(type))},
                  {"block", layout.key},
                  {"shape", shape_name(layout.shape)},
                  {"envelope", supports_envelope(type)},
                  {"samples", layout.extra == format::detail::BlockExtra::samples},
                  {"fields", fields}};
        if (layout.shape == format::detail::BlockShape::per_axis) {
            // With a direction, one block applied along it (§3.1, is_directed_condition).
            EffectParams directed = starter->params;
            directed.direction.kind = DirectionKind::cartesian;
            t["one_block_with_direction"] = is_directed_condition(directed);
        }
        if (layout.extra == format::detail::BlockExtra::control_law) {
            json law = json::array();
            for (const FieldSpec& f : format::detail::control_law_fields()) {
                law.push_back(describe(f, "control_law[0]." + std::string(f.name), &starter->params, 0, {}));
            }
            t["control_law"] = law;
        }
        if (supports_envelope(type) && any_valid != nullptr) {
            EffectParams with_envelope = starter->params;
            with_envelope.has_envelope = true;
            json env = json::array();
            for (const FieldSpec& f : format::detail::envelope_fields()) {
                env.push_back(describe(f, "envelope." + std::string(f.name), &with_envelope, 0, {}));
            }
            t["envelope_fields"] = env;
        }
        types.push_back(t);
    }
    json direction = json::object();
    for (const format::Sensation& s : starters.sensations) {
        if (!s.effects.empty() && s.effects.front().params.type == EffectType::sine) {
            direction = describe_direction(s.effects.front().params);
        }
    }
    json common = json::array();
    for (const CommonField& c : kCommon) {
        json d = {{"name", c.name}, {"kind", "integer"}, {"required", c.required},
                  {"infinite", c.infinite}, {"unit", unit_of(c.name)}};
        if (any_valid != nullptr) probe_range(d, c.name, *any_valid, c.set, 0, c.huge);
        common.push_back(d);
    }
    return {{"types", types}, {"common", common}, {"direction", direction}};
}

}  // namespace feel::studio
