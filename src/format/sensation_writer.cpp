// Writing sensation files in canonical form.
//
// The writer walks the same field tables as the reader (effect_fields.cpp), in the same
// order, so every field the reader can fill is written back. A field is written when it
// is required, when it differs from its default, or when the file it came from spelled it
// out (EffectSpec::explicit_fields). Layout is nlohmann's dump(2) plus a newline: that is
// the canonical form, and write(parse(text)) == text for any text already in it.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "effect_fields.hpp"
#include "feel/effect_validation.hpp"
#include "feel/format/sensation_file.hpp"
#include "json_document.hpp"

namespace feel::format {
namespace {

using detail::BlockExtra;
using detail::BlockLayout;
using detail::BlockShape;
using detail::FieldSpec;
using detail::ValueKind;
using OrderedJson = nlohmann::ordered_json;

const EffectParams kDefaults{};

[[noreturn]] void fail(const std::string& sensation, const std::string& problem) {
    throw FormatError("cannot write sensation " + detail::quote(sensation) + ": " + problem);
}

class EffectWriter {
public:
    EffectWriter(const std::string& sensation, std::string prefix, const EffectSpec& spec)
        : sensation_(sensation), prefix_(std::move(prefix)), spec_(spec), p_(spec.params) {}

    void write(OrderedJson& j) const {
        if (const Error e = validate_effect(p_, spec_.samples)) fail(sensation_, prefix_ + e.message());
        j["type"] = std::string(effect_type_name(p_.type));
        const bool endless_vector_force = p_.type == EffectType::vector_force && p_.duration_us == kInfiniteUs;
        if (!endless_vector_force || is_explicit("/duration_us")) j["duration_us"] = time_or_infinite(p_.duration_us);
        if (p_.start_delay_us != 0 || is_explicit("/start_delay_us")) j["start_delay_us"] = p_.start_delay_us;
        if (p_.iterations != kDefaults.iterations || is_explicit("/iterations")) {
            j["iterations"] = p_.iterations == kInfiniteIterations ? OrderedJson("infinite") : OrderedJson(p_.iterations);
        }
        OrderedJson axes = OrderedJson::array();
        for (int i = 0; i < p_.axis_count; ++i) axes.push_back(std::string(axis_name(p_.axes[i])));
        j["axes"] = std::move(axes);
        if (p_.direction.kind != DirectionKind::none) j["direction"] = direction();
        if (p_.gain != kDefaults.gain || is_explicit("/gain")) j["gain"] = p_.gain;
        if (p_.trigger.kind == TriggerKind::button) j["trigger_button"] = p_.trigger.index;
        if (p_.trigger.kind == TriggerKind::hat) j["trigger_button"] = "hat" + std::to_string(p_.trigger.index);
        if (p_.trigger_repeat_interval_us != 0 || is_explicit("/trigger_repeat_interval_us")) {
            j["trigger_repeat_interval_us"] = p_.trigger_repeat_interval_us;
        }
        if (p_.has_envelope) j["envelope"] = fields(detail::envelope_fields(), 0, "/envelope");
        write_block(j);
    }

private:
    [[nodiscard]] bool is_explicit(const std::string& pointer) const {
        return std::find(spec_.explicit_fields.begin(), spec_.explicit_fields.end(), pointer) !=
               spec_.explicit_fields.end();
    }

    static OrderedJson time_or_infinite(int64_t us) { return us == kInfiniteUs ? OrderedJson("infinite") : OrderedJson(us); }

    [[nodiscard]] OrderedJson direction() const {
        const Direction& d = p_.direction;
        OrderedJson out = OrderedJson::object();
        auto components = [&](int n) {
            OrderedJson a = OrderedJson::array();
            for (int i = 0; i < n; ++i) a.push_back(d.value[i]);
            return a;
        };
        switch (d.kind) {
            case DirectionKind::polar: out["polar"] = d.value[0]; break;
            case DirectionKind::cartesian: out["cartesian"] = components(p_.axis_count); break;
            case DirectionKind::spherical: out["spherical"] = components(2); break;
            case DirectionKind::moments: out["moments"] = components(p_.axis_count); break;
            case DirectionKind::none: break;
        }
        return out;
    }

    [[nodiscard]] OrderedJson value(const FieldSpec& f, int64_t v) const {
        switch (f.kind) {
            case ValueKind::i32:
            case ValueKind::i64: return OrderedJson(v);
            case ValueKind::boolean: return OrderedJson(v != 0);
            case ValueKind::choice:
                if (v < 0 || static_cast<size_t>(v) >= f.choices.size()) {  // the validator checks every choice
                    fail(sensation_, prefix_ + std::string(f.name) + " has no name for value " + std::to_string(v));
                }
                return OrderedJson(std::string(f.choices[static_cast<size_t>(v)]));
        }
        return OrderedJson();
    }

    [[nodiscard]] OrderedJson fields(std::span<const FieldSpec> table, int slot, const std::string& pointer) const {
        OrderedJson out = OrderedJson::object();
        for (const FieldSpec& f : table) {
            const int64_t v = f.get(p_, slot);
            if (f.required || v != f.get(kDefaults, slot) || is_explicit(pointer + "/" + std::string(f.name))) {
                out[std::string(f.name)] = value(f, v);
            }
        }
        return out;
    }

    void write_block(OrderedJson& j) const {
        const BlockLayout layout = detail::block_layout(p_.type);
        const std::string key(layout.key);
        if (layout.shape != BlockShape::object) {
            const int blocks =
                layout.shape == BlockShape::per_axis && !is_directed_condition(p_) ? p_.axis_count : 1;
            OrderedJson a = OrderedJson::array();
            for (int i = 0; i < blocks; ++i) a.push_back(fields(layout.fields, i, "/" + key + "/" + std::to_string(i)));
            j[key] = std::move(a);
            return;
        }
        OrderedJson block = OrderedJson::object();
        if (layout.extra == BlockExtra::control_law) {
            OrderedJson laws = OrderedJson::array();
            for (int i = 0; i < p_.axis_count; ++i) {
                laws.push_back(fields(detail::control_law_fields(), i, "/dynamic/control_law/" + std::to_string(i)));
            }
            block["control_law"] = std::move(laws);
        }
        const OrderedJson plain = fields(layout.fields, 0, "/" + key);
        for (const auto& [name, v] : plain.items()) block[name] = v;
        if (layout.extra == BlockExtra::samples) {
            OrderedJson samples = OrderedJson::array();
            for (int16_t s : spec_.samples) samples.push_back(s);
            block["samples"] = std::move(samples);
        }
        j[key] = std::move(block);
    }

    const std::string& sensation_;
    std::string prefix_;
    const EffectSpec& spec_;
    const EffectParams& p_;
};

}  // namespace

std::string write_sensation_file(const SensationFile& file) {
    if (file.sensations.empty()) {
        throw FormatError("cannot write a sensation file with no sensations (a file defines at least one)");
    }
    size_t effect_count = 0;
    for (const Sensation& s : file.sensations) effect_count += s.effects.size();
    if (effect_count > kMaxFileEffects) {
        throw FormatError("cannot write " + std::to_string(effect_count) + " effects in one file (allowed 1.." +
                          std::to_string(kMaxFileEffects) + ": a reader would refuse it)");
    }
    OrderedJson root = OrderedJson::object();
    root["format"] = std::string(kFormatVersion);
    OrderedJson sensations = OrderedJson::object();
    std::set<std::string> names;
    for (const Sensation& s : file.sensations) {
        if (!is_valid_sensation_name(s.name)) {
            fail(s.name, "the name is not valid (use 1 to 64 letters, digits, '_', '-' or '.')");
        }
        if (!names.insert(s.name).second) fail(s.name, "the name is used twice");
        if (s.effects.empty()) fail(s.name, "it has no effects");
        if (!s.compound && s.effects.size() != 1) {
            fail(s.name, "a sensation that is not a compound has exactly one effect, found " +
                             std::to_string(s.effects.size()));
        }
        OrderedJson js = OrderedJson::object();
        if (s.description) {
            try {
                (void)OrderedJson(*s.description).dump();
            } catch (const OrderedJson::type_error&) {
                fail(s.name, "the description is not valid UTF-8");
            }
            js["description"] = *s.description;
        }
        if (s.compound) {
            OrderedJson effects = OrderedJson::array();
            for (size_t i = 0; i < s.effects.size(); ++i) {
                OrderedJson e = OrderedJson::object();
                EffectWriter(s.name, "effects[" + std::to_string(i) + "].", s.effects[i]).write(e);
                effects.push_back(std::move(e));
            }
            js["effects"] = std::move(effects);
        } else {
            EffectWriter(s.name, "", s.effects.front()).write(js);
        }
        sensations[s.name] = std::move(js);
    }
    root["sensations"] = std::move(sensations);
    return root.dump(2) + "\n";
}

}  // namespace feel::format
