// The JSON Schema of feel/1 (docs/feel-1.schema.json), generated from the field tables the
// reader and the writer walk (effect_fields.hpp), so that it lists exactly the fields, kinds,
// choices, required fields and aliases a file is read with.
//
// What a schema can say and the reader checks: the structure, every field's JSON kind,
// choices, which block each type takes, required fields, unknown fields (through
// unevaluatedProperties, draft 2020-12, because each type adds its block in an if/then).
// What only the reader checks: the numeric ranges (the one validator, validate_effect, is
// the judge; its messages name the range), the counts that depend on the effect's axes, and
// the limits on a file's size. So a file the schema refuses is refused by the reader, and an
// editor completes and checks fields as the reader would; the reader still has the last word.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "effect_fields.hpp"
#include "feel/effect_type.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::format {
namespace {

using detail::FieldSpec;
using detail::ValueKind;
using json = nlohmann::json;

json field_schema(const FieldSpec& f) {
    switch (f.kind) {
        case ValueKind::boolean: return {{"type", "boolean"}};
        case ValueKind::choice: {
            json choices = json::array();
            for (std::string_view c : f.choices) choices.push_back(c);
            return {{"enum", choices}};
        }
        case ValueKind::i32:
        case ValueKind::i64: break;
    }
    return {{"type", "integer"}};
}

// An object of table fields: properties (aliases too), required fields (a field with an
// alias is present under one of its names, never both), nothing else.
json fields_object(std::span<const FieldSpec> fields, json extra_properties = json::object()) {
    json properties = std::move(extra_properties);
    json required = json::array();
    json all_of = json::array();
    for (const FieldSpec& f : fields) {
        properties[std::string(f.name)] = field_schema(f);
        if (f.alias.empty()) {
            if (f.required) required.push_back(f.name);
            continue;
        }
        properties[std::string(f.alias)] = field_schema(f);
        all_of.push_back({{"not", {{"required", {f.name, f.alias}}}}});
        if (f.required) all_of.push_back({{"anyOf", json::array({json{{"required", json::array({f.name})}},
                                                        json{{"required", json::array({f.alias})}}})}});
    }
    json o = {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
    if (!required.empty()) o["required"] = required;
    if (!all_of.empty()) o["allOf"] = all_of;
    return o;
}

json integer_or_infinite() {
    return {{"anyOf", json::array({json{{"type", "integer"}}, json{{"const", "infinite"}}})}};
}

json int_array(int min_items, int max_items) {
    return {{"type", "array"}, {"items", {{"type", "integer"}}}, {"minItems", min_items}, {"maxItems", max_items}};
}

// The block a type takes, as its if/then: the block (and the duration) is required, the
// envelope allowed only where the type takes one.
json type_rule(EffectType t) {
    const detail::BlockLayout layout = detail::block_layout(t);
    json extra = json::object();
    if (layout.extra == detail::BlockExtra::samples) extra["samples"] = {{"type", "array"}, {"items", {{"type", "integer"}}}};
    if (layout.extra == detail::BlockExtra::control_law) {
        extra["control_law"] = {{"type", "array"},
                                {"minItems", 1},
                                {"maxItems", kMaxAxes},
                                {"items", fields_object(detail::control_law_fields())}};
    }
    json block = fields_object(layout.fields, extra);
    if (layout.extra == detail::BlockExtra::samples) block["required"].push_back("samples");
    if (layout.extra == detail::BlockExtra::control_law) block["required"].push_back("control_law");
    switch (layout.shape) {
        case detail::BlockShape::object: break;
        case detail::BlockShape::per_axis:
            block = {{"type", "array"}, {"minItems", 1}, {"maxItems", kMaxAxes}, {"items", block}};
            break;
        case detail::BlockShape::one_block:
            block = {{"type", "array"}, {"minItems", 1}, {"maxItems", 1}, {"items", block}};
            break;
    }
    json then = {{"properties", {{std::string(layout.key), block}}}, {"required", json::array({layout.key})}};
    if (supports_envelope(t)) then["properties"]["envelope"] = {{"$ref", "#/$defs/envelope"}};
    // vector_force alone may leave its duration out: it is endless by default.
    if (t != EffectType::vector_force) then["required"].push_back("duration_us");
    return {{"if", {{"properties", {{"type", {{"const", effect_type_name(t)}}}}}}}, {"then", then}};
}

json effect_schema() {
    json type_names = json::array();
    json rules = json::array();
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        type_names.push_back(effect_type_name(t));
        rules.push_back(type_rule(t));
    }
    const json axis = {{"enum", {"x", "y", "z", "rx", "ry", "rz"}}};
    const json direction = {
        {"type", "object"},
        {"minProperties", 1},
        {"maxProperties", 1},
        {"additionalProperties", false},
        {"properties",
         {{"polar", {{"type", "integer"}}},
          {"cartesian", int_array(1, 3)},
          {"spherical", int_array(2, 2)},
          {"moments", int_array(1, 3)}}}};
    const json trigger = {
        {"anyOf", json::array({json{{"type", "integer"}}, json{{"enum", {"hat1", "hat2", "hat3", "hat4"}}}})}};
    return {{"type", "object"},
            {"required", {"type", "axes"}},
            {"properties",
             {{"description", {{"type", "string"}}},
              {"type", {{"enum", type_names}}},
              {"duration_us", integer_or_infinite()},
              {"start_delay_us", {{"type", "integer"}}},
              {"iterations", integer_or_infinite()},
              {"axes", {{"type", "array"}, {"minItems", 1}, {"maxItems", kMaxAxes}, {"items", axis}}},
              {"direction", direction},
              {"gain", {{"type", "integer"}}},
              {"trigger_button", trigger},
              {"trigger_repeat_interval_us", {{"type", "integer"}}}}},
            {"allOf", rules},
            {"unevaluatedProperties", false}};
}

}  // namespace

std::string json_schema() {
    const json compound = {
        {"type", "object"},
        {"required", json::array({"effects"})},
        {"additionalProperties", false},
        {"properties",
         {{"description", {{"type", "string"}}},
          {"effects",
           {{"type", "array"},
            {"minItems", 1},
            {"items", {{"$ref", "#/$defs/effect"}, {"not", {{"required", json::array({"description"})}}}}}}}}}};
    const json schema = {
        {"$schema", "https://json-schema.org/draft/2020-12/schema"},
        {"title", "feel/1 sensation file"},
        {"description",
         "Generated by `feel schema` from the format's field table (src/format/effect_fields.cpp); do not edit. "
         "Numeric ranges are checked by the reader (docs/sensation-format.md)."},
        {"type", "object"},
        {"required", {"format", "sensations"}},
        {"additionalProperties", false},
        {"properties",
         {{"format", {{"const", kFormatVersion}}},
          {"sensations",
           {{"type", "object"},
            {"propertyNames", {{"pattern", "^[A-Za-z0-9_.-]{1,64}$"}}},
            {"additionalProperties",
             {{"if", {{"required", json::array({"effects"})}}},
              {"then", {{"$ref", "#/$defs/compound"}}},
              {"else", {{"$ref", "#/$defs/effect"}}}}}}}}},
        {"$defs",
         {{"effect", effect_schema()},
          {"compound", compound},
          {"envelope", fields_object(detail::envelope_fields())}}}};
    return schema.dump(2) + "\n";
}

}  // namespace feel::format
