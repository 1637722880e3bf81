// The field description (field_schema.hpp): the format's field table, with the
// validator's ranges probed from a valid effect of each type.
#include "field_schema.hpp"

#include <cstring>
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
    switch (f.kind) {
        case ValueKind::boolean: d["kind"] = "boolean"; break;
        case ValueKind::choice: {
            d["kind"] = "choice";
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
};
constexpr CommonField kCommon[] = {
    {"duration_us", true, true, [](EffectParams& p, int, int64_t v) { p.duration_us = v; }},
    {"start_delay_us", false, false, [](EffectParams& p, int, int64_t v) { p.start_delay_us = v; }},
    {"iterations", false, true,
     [](EffectParams& p, int, int64_t v) { p.iterations = static_cast<int32_t>(v); }},
    {"gain", false, false, [](EffectParams& p, int, int64_t v) { p.gain = static_cast<int32_t>(v); }},
    {"trigger_repeat_interval_us", false, false,
     [](EffectParams& p, int, int64_t v) {
         p.trigger = {TriggerKind::button, 1};
         p.trigger_repeat_interval_us = v;
     }},
};

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
    json common = json::array();
    for (const CommonField& c : kCommon) {
        json d = {{"name", c.name}, {"kind", "integer"}, {"required", c.required},
                  {"infinite", c.infinite}, {"unit", unit_of(c.name)}};
        if (any_valid != nullptr) probe_range(d, c.name, *any_valid, c.set, 0, int64_t{1} << 40);
        common.push_back(d);
    }
    return {{"types", types}, {"common", common}};
}

}  // namespace feel::studio
