// Reading sensation files: the file, its sensations and their names, in one pass over
// nlohmann's SAX events. Each effect is read and validated by effect_reader.cpp.
//
// The reader never holds the JSON tree of the whole file (json_document.hpp says why):
// the top level ("format", "sensations", the sensation names) is checked event by event;
// each sensation's object becomes a bounded tree that is read into the model and dropped
// as soon as it closes; and the effects of a compound become one tree each, read as soon
// as each closes, so that a compound of many force profiles never has more than one in
// tree form. What stays is the model itself (kMaxFileEffects effects at most, samples as
// 16-bit integers), so memory is bounded by the file's size and a constant.
//
// Consequence: errors come in file order. A mistake is reported when the reader reaches
// it, before anything after it is read (a syntax error further on included).
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <unordered_set>

#include "effect_reader.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/units.hpp"
#include "json_document.hpp"

namespace feel::format {
namespace {

using detail::describe;
using detail::JsonValue;
using detail::quote;
using detail::TreeBuilder;
using detail::Where;
using Json = nlohmann::json;

[[noreturn]] void fail_file(std::string_view origin, const std::string& problem) {
    throw FormatError(std::string(origin) + ": " + problem);
}

std::string pointer_token(std::string_view token) {
    std::string out = "/";
    for (char c : token) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return out;
}

class FileReader final : public nlohmann::json_sax<Json> {
public:
    FileReader(std::string_view text, std::string_view origin) : text_(text), origin_(origin) {}

    SensationFile file;
    std::string syntax_error;  // set when nlohmann stops the parse

    // After a parse without error (so that trailing garbage is a syntax error first).
    void finish_file() {
        if (!seen_format_) fail_file(origin_, "missing \"format\": \"" + std::string(kFormatVersion) + "\"");
        if (!seen_sensations_) fail_file(origin_, "missing \"sensations\" (an object of named sensations)");
        if (file.sensations.empty()) {
            fail_file(origin_, "\"sensations\" is empty: a file defines at least one sensation");
        }
    }

    bool null() override { return scalar(JsonValue{}); }
    bool boolean(bool val) override {
        JsonValue v;
        v.kind = JsonValue::Kind::boolean;
        v.boolean = val;
        return scalar(std::move(v));
    }
    bool number_integer(number_integer_t val) override {
        JsonValue v;
        v.kind = JsonValue::Kind::integer;
        v.integer = val;
        return scalar(std::move(v));
    }
    bool number_unsigned(number_unsigned_t val) override {
        if (val > static_cast<number_unsigned_t>(std::numeric_limits<int64_t>::max())) {
            return scalar(detail::number_literal(std::to_string(val)));
        }
        return number_integer(static_cast<int64_t>(val));
    }
    bool number_float(number_float_t, const string_t& s) override { return scalar(detail::number_literal(s)); }
    bool string(string_t& val) override {
        JsonValue v;
        v.kind = JsonValue::Kind::string;
        v.text = std::move(val);
        return scalar(std::move(v));
    }
    bool binary(binary_t&) override {
        syntax_error = "binary values are not JSON";  // only binary formats produce them
        return false;
    }

    bool start_object(std::size_t) override { return open(JsonValue::Kind::object); }
    bool start_array(std::size_t) override { return open(JsonValue::Kind::array); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& k) override {
        switch (at_) {
            case At::top: return top_key(k);
            case At::sensations: return sensation_name(k);
            case At::sensation: return sensation_key(k);
            case At::effect: return tree_ok(effect_tree_.key(k), effect_tree_, effect_where());
            default: return false;  // nlohmann sends keys only inside objects
        }
    }

    bool parse_error(std::size_t position, const std::string& last_token,
                     const nlohmann::detail::exception& ex) override {
        if (ex.id == 406) return number_overflow(last_token);
        // Syntax errors read "[json.exception.parse_error.101] parse error at line 2,
        // column 5: syntax error ..."; keep nlohmann's position and explanation.
        const std::string what = ex.what();
        const std::string marker = "parse error at ";
        if (const size_t at = what.find(marker); at != std::string::npos) {
            syntax_error = "invalid JSON " + what.substr(at + marker.size() - 3);
            return false;
        }
        const size_t end = std::min(position, text_.size());
        const std::string_view before = text_.substr(0, end);
        const size_t line = 1 + static_cast<size_t>(std::count(before.begin(), before.end(), '\n'));
        const size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
        const size_t bracket = what.find("] ");
        syntax_error = "invalid JSON at line " + std::to_string(line) + ", column " +
                       std::to_string(end - line_start) + ": " +
                       (bracket == std::string::npos ? what : what.substr(bracket + 2));
        return false;
    }

private:
    // Where the next event belongs.
    enum class At : uint8_t {
        document,        // before the top-level value
        top,             // in the top-level object
        format_value,    // after "format":
        sensations_value,// after "sensations":
        sensations,      // in "sensations", between sensations
        sensation_value, // after a sensation's name
        sensation,       // in a sensation's object (sensation_tree_)
        effects_value,   // after a compound's "effects":
        effects,         // in a compound's "effects", between effects
        effect,          // in one effect of a compound (effect_tree_)
        done,            // after the top-level object
    };

    // --- the top level ---

    bool top_key(const std::string& k) {
        if (k == "format" || k == "sensations") {
            bool& seen = k == "format" ? seen_format_ : seen_sensations_;
            if (seen) fail_file(origin_, "duplicate key " + quote(k) + " in the object at the top level");
            seen = true;
            at_ = k == "format" ? At::format_value : At::sensations_value;
            return true;
        }
        fail_file(origin_, "unknown top-level field " + quote(k) + " (allowed: format, sensations)");
    }

    void check_format(const JsonValue& v) {
        if (!v.is_string() || v.text != kFormatVersion) {
            fail_file(origin_, "\"format\" must be \"" + std::string(kFormatVersion) + "\", found " + describe(v));
        }
    }

    [[noreturn]] void sensations_not_an_object(const JsonValue& v) {
        fail_file(origin_, "\"sensations\" must be an object of named sensations, found " + describe(v));
    }

    // --- sensations ---

    bool sensation_name(std::string& k) {
        if (!is_valid_sensation_name(k)) {
            fail_file(origin_, "sensation name " + quote(k) +
                                   " is not valid (use 1 to 64 letters, digits, '_', '-' or '.')");
        }
        if (!names_.insert(k).second) {
            fail_file(origin_, "duplicate key " + quote(k) + " in the object at /sensations");
        }
        name_ = std::move(k);
        at_ = At::sensation_value;
        return true;
    }

    [[noreturn]] void sensation_not_an_object(const JsonValue& v) {
        Where{origin_, name_, ""}.fail("", "expected an object (one effect, or {\"effects\": [...]} for a compound), found " +
                                               describe(v));
    }

    void begin_sensation() {
        sensation_tree_.begin("/sensations" + pointer_token(name_), 2);
        compound_ = false;
        compound_effects_.clear();
        at_ = At::sensation;
    }

    [[noreturn]] void unknown_in_compound(const std::string& k) const {
        Where{origin_, name_, ""}.fail("", "unknown field " + quote(k) +
                                               " in a compound sensation (allowed here: description, effects; each "
                                               "effect's fields go inside \"effects\")");
    }

    // A member of the sensation's own object. "effects" makes it a compound, whose
    // effects are read one by one instead of kept in the tree.
    bool sensation_key(std::string& k) {
        if (sensation_tree_.depth() != 1) return tree_ok(sensation_tree_.key(k), sensation_tree_, sensation_where());
        if (k == "effects") {
            for (const std::string& seen : sensation_tree_.top().keys) {
                if (seen != "description") unknown_in_compound(seen);
            }
            if (!tree_ok(sensation_tree_.key(k), sensation_tree_, sensation_where())) return false;
            compound_ = true;  // the first "effects" (a second is a duplicate key)
            at_ = At::effects_value;
            return true;
        }
        if (compound_ && k != "description") unknown_in_compound(k);
        return tree_ok(sensation_tree_.key(k), sensation_tree_, sensation_where());
    }

    void finish_sensation(JsonValue v) {
        Sensation s;
        s.name = name_;
        const Where where{origin_, name_, ""};
        if (JsonValue* d = v.find("description")) {
            if (!d->is_string()) where.fail("description", "expected a string, found " + describe(*d));
            s.description = std::move(d->text);  // a long one is not copied
        }
        if (compound_) {
            if (compound_effects_.empty()) where.fail("effects", "a compound sensation needs at least one effect");
            s.compound = true;
            s.effects = std::move(compound_effects_);
            compound_effects_.clear();
        } else {
            count_effect(where);
            s.effects.emplace_back();
            detail::read_effect(v, where, true, s.effects.back());
        }
        file.sensations.push_back(std::move(s));
        at_ = At::sensations;
    }

    // --- the effects of a compound ---

    void count_effect(const Where& where) {
        if (++effects_in_file_ > kMaxFileEffects) {
            where.fail("", "the file has more than " + std::to_string(kMaxFileEffects) +
                               " effects (allowed 1.." + std::to_string(kMaxFileEffects) +
                               " in one file, all sensations together)");
        }
    }

    Where effect_where() const {
        return Where{origin_, name_, "effects[" + std::to_string(compound_effects_.size()) + "]."};
    }
    Where sensation_where() const { return Where{origin_, name_, ""}; }

    void read_compound_effect(const JsonValue& v) {
        const Where where = effect_where();
        compound_effects_.emplace_back();
        detail::read_effect(v, where, false, compound_effects_.back());
        at_ = At::effects;
    }

    // --- events ---

    bool scalar(JsonValue v) {
        switch (at_) {
            case At::document:
                fail_file(origin_, "expected a JSON object at the top level, found " + describe(v));
            case At::format_value:
                check_format(v);
                at_ = At::top;
                return true;
            case At::sensations_value: sensations_not_an_object(v);
            case At::sensation_value: sensation_not_an_object(v);
            case At::sensation: return tree_ok(sensation_tree_.scalar(std::move(v)), sensation_tree_, sensation_where());
            case At::effects_value:
                sensation_where().fail("effects", "expected an array of effects, found " + describe(v));
            case At::effects:
                count_effect(effect_where());
                read_compound_effect(v);  // throws: an effect is an object
                return true;
            case At::effect: return tree_ok(effect_tree_.scalar(std::move(v)), effect_tree_, effect_where());
            case At::top:
            case At::sensations:
            case At::done: break;
        }
        return false;  // nlohmann sends no value where a key or the end must come
    }

    bool open(JsonValue::Kind kind) {
        JsonValue shape;  // for messages about a container found where another value belongs
        shape.kind = kind;
        const bool object = kind == JsonValue::Kind::object;
        switch (at_) {
            case At::document:
                if (!object) fail_file(origin_, "expected a JSON object at the top level, found an array");
                at_ = At::top;
                return true;
            case At::format_value: check_format(shape); return false;
            case At::sensations_value:
                if (!object) sensations_not_an_object(shape);
                at_ = At::sensations;
                return true;
            case At::sensation_value:
                if (!object) sensation_not_an_object(shape);
                begin_sensation();
                return tree_ok(sensation_tree_.open(kind), sensation_tree_, sensation_where());
            case At::sensation: return tree_ok(sensation_tree_.open(kind), sensation_tree_, sensation_where());
            case At::effects_value:
                if (object) sensation_where().fail("effects", "expected an array of effects, found an object");
                at_ = At::effects;
                return true;
            case At::effects:
                count_effect(effect_where());
                if (!object) read_compound_effect(shape);  // throws
                effect_tree_.begin("/sensations" + pointer_token(name_) + "/effects/" +
                                       std::to_string(compound_effects_.size()),
                                   4);
                at_ = At::effect;
                return tree_ok(effect_tree_.open(kind), effect_tree_, effect_where());
            case At::effect: return tree_ok(effect_tree_.open(kind), effect_tree_, effect_where());
            case At::top:
            case At::sensations:
            case At::done: break;
        }
        return false;
    }

    bool close() {
        switch (at_) {
            case At::top:
                at_ = At::done;  // finish_file() once nlohmann has seen the end
                return true;
            case At::sensations:
                at_ = At::top;
                return true;
            case At::sensation:
                sensation_tree_.close();
                if (!sensation_tree_.building()) finish_sensation(sensation_tree_.take());
                return true;
            case At::effects: {
                // The tree keeps "effects" as an empty array: the effects are in the model.
                JsonValue placeholder;
                placeholder.kind = JsonValue::Kind::array;
                at_ = At::sensation;
                return tree_ok(sensation_tree_.scalar(std::move(placeholder)), sensation_tree_, sensation_where());
            }
            case At::effect:
                effect_tree_.close();
                if (!effect_tree_.building()) read_compound_effect(effect_tree_.take());
                return true;
            default: return false;
        }
    }

    // A tree event's outcome: a broken rule becomes the FormatError.
    bool tree_ok(bool ok, const TreeBuilder& tree, const Where& where) const {
        if (ok) return true;
        const TreeBuilder::Error& e = tree.error();
        if (!e.field_path_valid) fail_file(origin_, e.problem);
        // The longest array of the format has its own words.
        const std::string_view samples = "custom.samples";
        if (e.path == samples && e.problem.find(" values in one array") != std::string::npos) {
            where.fail(e.path, "more than " + std::to_string(range::kSampleCount.max) + " samples (allowed " +
                                   detail::range_text(range::kSampleCount) + ")");
        }
        where.fail(e.path, e.problem);
    }

    // A number too large for a double (1e400, a 100 000-digit integer): nlohmann stops
    // there. It is refused like any value that does not fit, naming its field.
    bool number_overflow(const std::string& literal) {
        const JsonValue v = detail::number_literal(literal);
        const std::string problem =
            v.kind == JsonValue::Kind::big_integer
                ? describe(v) + " does not fit in a 64-bit integer"
                : describe(v) + " is beyond the range of every field (the format's numbers are 64-bit integers)";
        switch (at_) {
            case At::sensation: sensation_where().fail(sensation_tree_.next_path(), problem);
            case At::effect: effect_where().fail(effect_tree_.next_path(), problem);
            default: return scalar(v);  // where no number belongs: the usual message names what does
        }
    }

    std::string_view text_;  // for positions nlohmann does not give
    std::string_view origin_;
    At at_ = At::document;
    bool seen_format_ = false;
    bool seen_sensations_ = false;
    std::unordered_set<std::string> names_;  // at most kMaxFileEffects names of at most 64 bytes
    std::string name_;                       // the sensation being read
    size_t effects_in_file_ = 0;
    TreeBuilder sensation_tree_;
    bool compound_ = false;
    std::vector<EffectSpec> compound_effects_;
    TreeBuilder effect_tree_;
};

}  // namespace

bool is_valid_sensation_name(std::string_view name) noexcept {
    if (name.empty() || name.size() > kMaxSensationNameLength) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
               c == '-' || c == '.';
    });
}

const Sensation* SensationFile::find(std::string_view name) const noexcept {
    for (const Sensation& s : sensations) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

SensationFile parse_sensation_file(std::string_view text, std::string_view origin) {
    FileReader reader(text, origin);
    if (!Json::sax_parse(text.begin(), text.end(), &reader)) {
        fail_file(origin, reader.syntax_error.empty() ? std::string("invalid JSON") : reader.syntax_error);
    }
    reader.finish_file();
    return std::move(reader.file);
}

SensationFile load_sensation_file(const std::filesystem::path& path) {
    const std::string origin = path.string();
    std::FILE* f = std::fopen(origin.c_str(), "rb");
    if (f == nullptr) {
        fail_file(origin, "cannot open: " + std::generic_category().message(errno));
    }
    const std::string too_large = "file is larger than " + std::to_string(kMaxFileBytes) + " bytes";
    std::string text;
    // A regular file is refused before it is read, and read into a buffer of its size
    // (growing a string by doubling would take up to three times the file at a moment).
    struct stat st {};
    if (::fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode)) {
        if (static_cast<uint64_t>(st.st_size) > kMaxFileBytes) {
            std::fclose(f);
            fail_file(origin, too_large);
        }
        text.reserve(static_cast<size_t>(st.st_size) + 1);
    }
    char buf[1 << 16];
    size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
        text.append(buf, n);
        if (text.size() > kMaxFileBytes) {
            std::fclose(f);
            fail_file(origin, too_large);
        }
    }
    const bool failed = std::ferror(f) != 0;
    const int err = errno;
    std::fclose(f);
    if (failed) fail_file(origin, "cannot read: " + std::generic_category().message(err));
    return parse_sensation_file(text, origin);
}

}  // namespace feel::format
