// Reading one effect: JSON structure first, then feel::validate_effect().
//
// The reader's own checks are only those the validator cannot make because they are
// about the text: a field's JSON type, unknown or missing fields, array lengths that
// become counts (axes, conditions, samples). Every range and every rule that ties fields
// together is the validator's, so a file accepts exactly what the engine accepts.
//
// Integers wider than their int32 field. The validator sees EffectParams, whose fields
// are int32; a file can say 5000000000. Narrowing would wrap, and the validator would
// quote the wrong value. So the reader stores the nearest int32 (which is out of every
// range of units.hpp) and remembers the file's value; when the validator rejects that
// field, the message quotes what the file said. If the validator somehow accepted it,
// the reader still fails: nothing is ever clamped into a valid effect.
#include "effect_reader.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "effect_fields.hpp"
#include "feel/effect_validation.hpp"

namespace feel::format::detail {
namespace {

constexpr std::string_view kEffectKeys[] = {
    "type",      "duration_us", "start_delay_us", "iterations",
    "axes",      "direction",   "gain",           "trigger_button",
    "trigger_repeat_interval_us", "envelope"};

constexpr int64_t kInt32Min = std::numeric_limits<int32_t>::min();
constexpr int64_t kInt32Max = std::numeric_limits<int32_t>::max();

std::string join(std::span<const std::string_view> names) {
    std::string out;
    for (std::string_view n : names) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

std::string all_type_names() {
    std::string out;
    for (int i = 0; i < kEffectTypeCount; ++i) {
        if (i) out += ", ";
        out += effect_type_name(static_cast<EffectType>(i));
    }
    return out;
}

// "a spring takes" / "an angle_spring takes"
std::string a_type(EffectType t) {
    const std::string_view n = effect_type_name(t);
    const bool vowel = n.find_first_of("aeiou") == 0;
    return std::string(vowel ? "an " : "a ") + std::string(n);
}


class EffectReader {
public:
    EffectReader(const Where& where, EffectSpec& out) : where_(where), spec_(out), p_(out.params) {}

    void read(const JsonValue& obj, bool allow_description) {
        if (!obj.is_object()) where_.fail("", "expected an effect object, found " + describe(obj));
        read_type(obj);
        const BlockLayout layout = detail::block_layout(p_.type);
        check_keys(obj, layout, allow_description);
        read_timing(obj);
        read_axes(obj);
        read_direction(obj);
        read_trigger(obj);
        if (const JsonValue* env = obj.find("envelope")) {
            p_.has_envelope = true;
            read_fields(*env, detail::envelope_fields(), 0, "envelope", "/envelope", {});
        }
        read_block(obj, layout);
        validate();
    }

private:
    // --- values ---

    int64_t integer(const JsonValue& v, const std::string& path) const {
        if (v.kind == JsonValue::Kind::integer) return v.integer;
        if (v.kind == JsonValue::Kind::big_integer) {
            where_.fail(path, v.text + " does not fit in a 64-bit integer");
        }
        where_.fail(path, "expected an integer, found " + describe(v));
    }

    // Stores v into an int32 field; see the file comment for values that do not fit.
    int32_t narrow(int64_t v, const std::string& path) {
        if (v >= kInt32Min && v <= kInt32Max) return static_cast<int32_t>(v);
        overflows_.push_back({path, v});
        return v < 0 ? static_cast<int32_t>(kInt32Min) : static_cast<int32_t>(kInt32Max);
    }

    void store(const FieldSpec& f, int slot, const JsonValue& v, const std::string& path) {
        switch (f.kind) {
            case ValueKind::i32:
                f.set(p_, slot, narrow(integer(v, path), path));
                return;
            case ValueKind::i64:
                f.set(p_, slot, integer(v, path));
                return;
            case ValueKind::boolean:
                if (v.kind != JsonValue::Kind::boolean) {
                    where_.fail(path, "expected true or false, found " + describe(v));
                }
                f.set(p_, slot, v.boolean ? 1 : 0);
                return;
            case ValueKind::choice:
                for (size_t i = 0; i < f.choices.size(); ++i) {
                    if (v.is_string() && v.text == f.choices[i]) {
                        f.set(p_, slot, static_cast<int64_t>(i));
                        return;
                    }
                }
                std::string allowed;
                for (std::string_view c : f.choices) allowed += (allowed.empty() ? "" : " or ") + quote(c);
                where_.fail(path, "expected " + allowed + ", found " + describe(v));
        }
    }

    // "axis_wall and angle_wall have it; " when other types' blocks have a field named
    // `key` (a field put on the wrong sibling type, e.g. offset_mode on a barrier), else "".
    [[nodiscard]] std::string siblings_having(const std::string& key, std::span<const FieldSpec> here) const {
        auto has = [&key](std::span<const FieldSpec> fields) {
            return std::any_of(fields.begin(), fields.end(), [&](const FieldSpec& f) { return f.name == key; });
        };
        std::vector<std::string_view> names;
        for (int i = 0; i < kEffectTypeCount; ++i) {
            const auto t = static_cast<EffectType>(i);
            if (t == p_.type) continue;
            const detail::BlockLayout layout = detail::block_layout(t);
            const bool law = layout.extra == detail::BlockExtra::control_law &&
                             here.data() != detail::control_law_fields().data() && has(detail::control_law_fields());
            if (has(layout.fields) || law) names.push_back(effect_type_name(t));
        }
        if (names.empty()) return "";
        std::string list;
        for (size_t i = 0; i < names.size(); ++i) {
            if (i > 0) list += i + 1 == names.size() ? " and " : ", ";
            list += names[i];
        }
        return list + (names.size() == 1 ? " has it; " : " have it; ");
    }

    void mark_explicit(std::string pointer) { spec_.explicit_fields.push_back(std::move(pointer)); }

    // An object of table fields. `extra` names one more member the caller reads itself.
    void read_fields(const JsonValue& obj, std::span<const FieldSpec> fields, int slot,
                     const std::string& path, const std::string& pointer, std::string_view extra) {
        if (!obj.is_object()) where_.fail(path, "expected an object, found " + describe(obj));
        for (const std::string& key : obj.keys) {
            const bool known = key == extra || std::any_of(fields.begin(), fields.end(), [&](const FieldSpec& f) {
                                   return f.name == key || (!f.alias.empty() && f.alias == key);
                               });
            if (!known) {
                // Listed in canonical order: control_law leads its block, samples ends its.
                std::string allowed = extra == "control_law" ? "control_law" : "";
                for (const FieldSpec& f : fields) allowed += (allowed.empty() ? "" : ", ") + std::string(f.name);
                if (extra == "samples") allowed += ", samples";
                where_.fail(path, "unknown field " + quote(key) + " (" + siblings_having(key, fields) +
                                      "allowed here: " + allowed + ")");
            }
        }
        for (const FieldSpec& f : fields) {
            std::string field_path = path + "." + std::string(f.name);
            const JsonValue* v = obj.find(f.name);
            if (const JsonValue* aliased = f.alias.empty() ? nullptr : obj.find(f.alias)) {
                if (v != nullptr) {
                    where_.fail(path, "both " + quote(f.name) + " and its alias " + quote(f.alias) +
                                          " are given (give one of them)");
                }
                v = aliased;
                std::string alias_path = path + "." + std::string(f.alias);
                aliased_.push_back({field_path, alias_path});
                field_path = std::move(alias_path);
            }
            if (v == nullptr) {
                if (f.required) where_.fail(field_path, "required field is missing");
                continue;
            }
            if (!f.required) mark_explicit(pointer + "/" + std::string(f.name));
            store(f, slot, *v, field_path);
        }
    }

    // --- effect-level fields ---

    void read_type(const JsonValue& obj) {
        const JsonValue* t = obj.find("type");
        if (t == nullptr) {
            where_.fail("type", "required field is missing (an effect names its type, e.g. "
                                "\"sine\"; a compound sensation lists its effects in \"effects\")");
        }
        if (!t->is_string()) where_.fail("type", "expected the name of an effect type, found " + describe(*t));
        const std::optional<EffectType> type = effect_type_from_name(t->text);
        if (!type) {
            where_.fail("type", quote(t->text) + " is not an effect type (the types are: " +
                                    all_type_names() + ")");
        }
        p_.type = *type;
    }

    void check_keys(const JsonValue& obj, const BlockLayout& layout, bool allow_description) const {
        for (const std::string& key : obj.keys) {
            if (std::find(std::begin(kEffectKeys), std::end(kEffectKeys), key) != std::end(kEffectKeys)) continue;
            if (key == layout.key) continue;
            if (key == "description" && allow_description) continue;
            const auto blocks = detail::all_block_keys();
            if (std::find(blocks.begin(), blocks.end(), key) != blocks.end()) {
                where_.fail(key, "block " + quote(key) + " does not apply to type " +
                                     quote(effect_type_name(p_.type)) + " (" + a_type(p_.type) +
                                     " takes " + quote(layout.key) + ")");
            }
            if (key == "effects") {
                where_.fail(key, "a sensation is either one effect or a compound {\"effects\": "
                                 "[...]}, not both");
            }
            std::string allowed = join(kEffectKeys) + ", " + std::string(layout.key);
            if (allow_description) allowed = "description, " + allowed;
            where_.fail("", "unknown field " + quote(key) + " (allowed here: " + allowed + ")");
        }
    }

    // An integer or "infinite" (which is `infinite`); the integer must not be the sentinel.
    int64_t integer_or_infinite(const JsonValue& v, const std::string& path, int64_t infinite, Range r) const {
        if (v.is_string()) {
            if (v.text == "infinite") return infinite;
            where_.fail(path, "expected an integer or \"infinite\", found " + describe(v));
        }
        if (v.kind != JsonValue::Kind::integer && v.kind != JsonValue::Kind::big_integer) {
            where_.fail(path, "expected an integer or \"infinite\", found " + describe(v));
        }
        const int64_t n = integer(v, path);
        if (n == infinite) where_.fail_range(path, n, r);  // spell endless as "infinite"
        return n;
    }

    void optional_i64(const JsonValue& obj, const char* key, int64_t& dst) {
        if (const JsonValue* v = obj.find(key)) {
            mark_explicit(std::string("/") + key);
            dst = integer(*v, key);
        }
    }

    void read_timing(const JsonValue& obj) {
        if (const JsonValue* d = obj.find("duration_us")) {
            // vector_force alone may omit its duration (it defaults to infinite).
            if (p_.type == EffectType::vector_force) mark_explicit("/duration_us");
            p_.duration_us = integer_or_infinite(*d, "duration_us", kInfiniteUs, range::kDurationUs);
        } else if (p_.type == EffectType::vector_force) {
            p_.duration_us = kInfiniteUs;
        } else {
            where_.fail("duration_us", "required field is missing (1.." + std::to_string(kMaxTimeUs) +
                                           " microseconds or \"infinite\")");
        }
        optional_i64(obj, "start_delay_us", p_.start_delay_us);
        if (const JsonValue* it = obj.find("iterations")) {
            mark_explicit("/iterations");
            const int64_t n = integer_or_infinite(*it, "iterations", kInfiniteIterations, range::kIterations);
            p_.iterations = narrow(n, "iterations");
        }
        if (const JsonValue* g = obj.find("gain")) {
            mark_explicit("/gain");
            p_.gain = narrow(integer(*g, "gain"), "gain");
        }
    }

    void read_axes(const JsonValue& obj) {
        const JsonValue* a = obj.find("axes");
        if (a == nullptr) where_.fail("axes", "required field is missing (e.g. [\"x\", \"y\"])");
        if (!a->is_array()) where_.fail("axes", "expected an array of axis names, found " + describe(*a));
        const size_t n = a->items.size();
        if (!range::kAxisCount.contains(static_cast<int64_t>(n))) {
            where_.fail("axes", std::to_string(n) + " axes is out of range (allowed " +
                                    range_text(range::kAxisCount) + ")");
        }
        for (size_t i = 0; i < n; ++i) {
            const JsonValue& v = a->items[i];
            const std::optional<Axis> axis = v.is_string() ? axis_from_name(v.text) : std::nullopt;
            if (!axis) {
                where_.fail("axes[" + std::to_string(i) + "]",
                            "expected one of \"x\", \"y\", \"z\", \"rx\", \"ry\", \"rz\", found " + describe(v));
            }
            p_.axes[i] = *axis;
        }
        p_.axis_count = static_cast<int32_t>(n);
    }

    void read_direction(const JsonValue& obj) {
        const JsonValue* d = obj.find("direction");
        if (d == nullptr) return;
        if (!d->is_object() || d->keys.size() != 1) {
            where_.fail("direction", "expected an object with exactly one of \"polar\", \"cartesian\", "
                                     "\"spherical\" or \"moments\", found " +
                                         (d->is_object() ? std::to_string(d->keys.size()) + " members"
                                                         : describe(*d)));
        }
        const std::string& form = d->keys[0];
        const JsonValue& v = d->items[0];
        if (form != "polar" && form != "cartesian" && form != "moments" && form != "spherical") {
            where_.fail("direction", "unknown direction form " + quote(form) +
                                         " (allowed: polar, cartesian, spherical, moments)");
        }
        const std::string path = "direction." + form;
        Direction& dir = p_.direction;
        if (form == "polar") {
            dir.kind = DirectionKind::polar;
            dir.value[0] = narrow(integer(v, path), path);
            return;
        }
        if (!v.is_array()) where_.fail(path, "expected an array of integers, found " + describe(v));
        const size_t n = v.items.size();
        if (form == "spherical") {
            dir.kind = DirectionKind::spherical;
            if (n != 2) {
                where_.fail(path, "expected [azimuth, elevation], found " + std::to_string(n) + " values");
            }
        } else {
            dir.kind = form == "cartesian" ? DirectionKind::cartesian : DirectionKind::moments;
            if (n > 3) {
                where_.fail(path, std::to_string(n) + " components is out of range (allowed 1..3, one per axis)");
            }
            if (n != static_cast<size_t>(p_.axis_count)) {
                where_.fail(path, "found " + std::to_string(n) + " components for " +
                                      std::to_string(p_.axis_count) + " axes (one component per axis)");
            }
        }
        for (size_t i = 0; i < n; ++i) {
            const std::string item = path + "[" + std::to_string(i) + "]";
            dir.value[i] = narrow(integer(v.items[i], item), item);
        }
    }

    void read_trigger(const JsonValue& obj) {
        if (const JsonValue* t = obj.find("trigger_button")) {
            if (t->is_string()) {
                const std::string& s = t->text;
                if (s.size() != 4 || s.compare(0, 3, "hat") != 0 || s[3] < '1' || s[3] > '4') {
                    where_.fail("trigger_button", "expected a button number 1..32 or \"hat1\"..\"hat4\", found " +
                                                      describe(*t));
                }
                p_.trigger = {TriggerKind::hat, s[3] - '0'};
            } else {
                if (t->kind != JsonValue::Kind::integer && t->kind != JsonValue::Kind::big_integer) {
                    where_.fail("trigger_button", "expected a button number 1..32 or \"hat1\"..\"hat4\", found " +
                                                      describe(*t));
                }
                p_.trigger = {TriggerKind::button, narrow(integer(*t, "trigger_button"), "trigger_button")};
            }
        }
        optional_i64(obj, "trigger_repeat_interval_us", p_.trigger_repeat_interval_us);
    }

    // --- the type's block ---

    void read_block(const JsonValue& obj, const BlockLayout& layout) {
        const std::string key(layout.key);
        const JsonValue* b = obj.find(key);
        if (b == nullptr) {
            where_.fail(key, "required field is missing (" + a_type(p_.type) + " takes its parameters in " +
                                 quote(key) + ")");
        }
        if (layout.shape != BlockShape::object) {
            read_block_array(*b, layout);
            return;
        }
        const std::string_view extra = layout.extra == BlockExtra::samples       ? "samples"
                                       : layout.extra == BlockExtra::control_law ? "control_law"
                                                                                 : "";
        if (layout.extra == BlockExtra::control_law) read_control_law(*b);
        read_fields(*b, layout.fields, 0, key, "/" + key, extra);
        if (layout.extra == BlockExtra::samples) read_samples(*b);
    }

    // conditions: one object per axis, or one applied along the direction when a spring,
    // damper, inertia or friction has one (§3.1), or one for angle_spring.
    void read_block_array(const JsonValue& b, const BlockLayout& layout) {
        const std::string key(layout.key);
        const bool per_axis = layout.shape == BlockShape::per_axis && !is_directed_condition(p_);
        const size_t expected = per_axis ? static_cast<size_t>(p_.axis_count) : 1;
        const char* what = per_axis ? " (one per axis)"
                           : layout.shape == BlockShape::per_axis
                               ? " (with a direction, one block applied along it; per-axis blocks take no direction)"
                               : " (one for the whole plane)";
        if (!b.is_array()) {
            where_.fail(key, "expected an array of " + std::to_string(expected) + " blocks" + what + ", found " +
                                 describe(b));
        }
        if (b.items.size() != expected) {
            where_.fail(key, "found " + std::to_string(b.items.size()) + " blocks, expected " +
                                 std::to_string(expected) + what);
        }
        for (size_t i = 0; i < expected; ++i) {
            const std::string index = std::to_string(i);
            read_fields(b.items[i], layout.fields, static_cast<int>(i), key + "[" + index + "]",
                        "/" + key + "/" + index, {});
        }
    }

    void read_control_law(const JsonValue& b) {
        if (!b.is_object()) where_.fail("dynamic", "expected an object, found " + describe(b));
        const JsonValue* law = b.find("control_law");
        const std::string path = "dynamic.control_law";
        if (law == nullptr) where_.fail(path, "required field is missing (one block per axis)");
        const size_t expected = static_cast<size_t>(p_.axis_count);
        if (!law->is_array()) where_.fail(path, "expected an array of blocks, one per axis, found " + describe(*law));
        if (law->items.size() != expected) {
            where_.fail(path, "found " + std::to_string(law->items.size()) + " blocks, expected " +
                                  std::to_string(expected) + " (one per axis)");
        }
        for (size_t i = 0; i < expected; ++i) {
            const std::string index = std::to_string(i);
            read_fields(law->items[i], detail::control_law_fields(), static_cast<int>(i), path + "[" + index + "]",
                        "/dynamic/control_law/" + index, {});
        }
    }

    void read_samples(const JsonValue& b) {
        const JsonValue* s = b.find("samples");
        const std::string path = "custom.samples";
        if (s == nullptr) where_.fail(path, "required field is missing (the force values, interleaved by channel)");
        if (!s->is_array()) where_.fail(path, "expected an array of integers, found " + describe(*s));
        const size_t n = s->items.size();
        if (!range::kSampleCount.contains(static_cast<int64_t>(n))) {
            where_.fail(path, std::to_string(n) + " samples is out of range (allowed " +
                                  range_text(range::kSampleCount) + ")");
        }
        spec_.samples.reserve(n);
        for (size_t i = 0; i < n; ++i) {
            const std::string item = path + "[" + std::to_string(i) + "]";
            const int64_t v = integer(s->items[i], item);
            constexpr int64_t lo = std::numeric_limits<int16_t>::min();
            constexpr int64_t hi = std::numeric_limits<int16_t>::max();
            if (v < lo || v > hi) overflows_.push_back({item, v});
            spec_.samples.push_back(static_cast<int16_t>(std::clamp(v, lo, hi)));
        }
        p_.custom.sample_count = static_cast<int32_t>(n);
    }

    // --- the validator ---

    void validate() const {
        const Error e = validate_effect(p_, spec_.samples);
        if (e.ok()) {
            if (!overflows_.empty()) {  // never reached while every range fits in int32
                where_.fail(overflows_.front().path,
                            std::to_string(overflows_.front().value) + " does not fit in a 32-bit integer");
            }
            return;
        }
        std::string_view field = e.field;
        for (const Aliased& a : aliased_) {
            if (a.field == field) field = a.as_written;  // name the field as the file does
        }
        if (field == "custom.sample_count") {
            // The file has no sample_count: it is the length of "samples".
            where_.fail("custom.samples", std::to_string(p_.custom.sample_count) +
                                              " samples is not a multiple of custom.channels = " +
                                              std::to_string(p_.custom.channels) +
                                              " (samples are interleaved by channel, §6.6.d)");
        }
        if (e.has_range) {
            int64_t value = e.value;
            for (const Overflow& o : overflows_) {
                if (o.path == field) value = o.value;
            }
            where_.fail_range(field, value, e.allowed);
        }
        where_.fail(field, e.rule);
    }

    // A field the file gave under its alias: the validator's name and the file's.
    struct Aliased {
        std::string field;
        std::string as_written;
    };
    std::vector<Aliased> aliased_;

    struct Overflow {
        std::string path;
        int64_t value;
    };

    const Where& where_;
    EffectSpec& spec_;
    EffectParams& p_;
    std::vector<Overflow> overflows_;
};

}  // namespace

void Where::fail(std::string_view path, std::string_view problem) const {
    std::string msg(origin);
    msg += ": ";
    if (!sensation.empty()) msg += "sensation " + quote(sensation) + ": ";
    std::string full = prefix + std::string(path);
    if (!full.empty() && full.back() == '.') full.pop_back();
    if (!full.empty()) msg += full + ": ";
    msg += problem;
    throw FormatError(msg);
}

void Where::fail_range(std::string_view field, int64_t value, Range allowed) const {
    std::string msg(origin);
    msg += ": ";
    if (!sensation.empty()) msg += "sensation " + quote(sensation) + ": ";
    msg += prefix + std::string(field) + " = " + std::to_string(value) + " is out of range (allowed " +
           range_text(allowed);
    if (field == "duration_us" || field == "iterations") msg += " or \"infinite\"";
    msg += ")";
    throw FormatError(msg);
}

std::string range_text(Range r) { return std::to_string(r.min) + ".." + std::to_string(r.max); }

void read_effect(const JsonValue& obj, const Where& where, bool allow_description, EffectSpec& out) {
    EffectReader(where, out).read(obj, allow_description);
}

}  // namespace feel::format::detail
