// Reading sensation files: the file, its sensations and their names. Each effect is
// read and validated by effect_reader.cpp.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>

#include "effect_reader.hpp"
#include "feel/format/sensation_file.hpp"
#include "json_document.hpp"

namespace feel::format {
namespace {

using detail::describe;
using detail::JsonValue;
using detail::quote;
using detail::Where;

[[noreturn]] void fail_file(std::string_view origin, const std::string& problem) {
    throw FormatError(std::string(origin) + ": " + problem);
}

Sensation read_sensation(std::string_view origin, const std::string& name, const JsonValue& v) {
    if (!is_valid_sensation_name(name)) {
        fail_file(origin, "sensation name " + quote(name) +
                              " is not valid (use 1 to 64 letters, digits, '_', '-' or '.')");
    }
    Sensation s;
    s.name = name;
    Where where{origin, name, ""};
    if (!v.is_object()) {
        where.fail("", "expected an object (one effect, or {\"effects\": [...]} for a compound), found " +
                           describe(v));
    }
    if (const JsonValue* d = v.find("description")) {
        if (!d->is_string()) where.fail("description", "expected a string, found " + describe(*d));
        s.description = d->text;
    }
    const JsonValue* effects = v.find("effects");
    if (effects == nullptr) {
        s.effects.emplace_back();
        detail::read_effect(v, where, true, s.effects.back());
        return s;
    }
    s.compound = true;
    for (const std::string& key : v.keys) {
        if (key != "description" && key != "effects") {
            where.fail("", "unknown field " + quote(key) +
                               " in a compound sensation (allowed here: description, effects; each effect's "
                               "fields go inside \"effects\")");
        }
    }
    if (!effects->is_array()) where.fail("effects", "expected an array of effects, found " + describe(*effects));
    if (effects->items.empty()) where.fail("effects", "a compound sensation needs at least one effect");
    s.effects.resize(effects->items.size());
    for (size_t i = 0; i < effects->items.size(); ++i) {
        Where inner{origin, name, "effects[" + std::to_string(i) + "]."};
        detail::read_effect(effects->items[i], inner, false, s.effects[i]);
    }
    return s;
}

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
    const JsonValue root = detail::parse_json(text, origin);
    if (!root.is_object()) fail_file(origin, "expected a JSON object at the top level, found " + describe(root));
    for (const std::string& key : root.keys) {
        if (key != "format" && key != "sensations") {
            fail_file(origin, "unknown top-level field " + quote(key) + " (allowed: format, sensations)");
        }
    }
    const JsonValue* format = root.find("format");
    if (format == nullptr) fail_file(origin, "missing \"format\": \"" + std::string(kFormatVersion) + "\"");
    if (!format->is_string() || format->text != kFormatVersion) {
        fail_file(origin, "\"format\" must be \"" + std::string(kFormatVersion) + "\", found " + describe(*format));
    }
    const JsonValue* sensations = root.find("sensations");
    if (sensations == nullptr) fail_file(origin, "missing \"sensations\" (an object of named sensations)");
    if (!sensations->is_object()) {
        fail_file(origin, "\"sensations\" must be an object of named sensations, found " + describe(*sensations));
    }
    if (sensations->keys.empty()) fail_file(origin, "\"sensations\" is empty: a file defines at least one sensation");
    SensationFile file;
    file.sensations.reserve(sensations->keys.size());
    for (size_t i = 0; i < sensations->keys.size(); ++i) {
        file.sensations.push_back(read_sensation(origin, sensations->keys[i], sensations->items[i]));
    }
    return file;
}

SensationFile load_sensation_file(const std::filesystem::path& path) {
    const std::string origin = path.string();
    std::FILE* f = std::fopen(origin.c_str(), "rb");
    if (f == nullptr) {
        fail_file(origin, "cannot open: " + std::generic_category().message(errno));
    }
    std::string text;
    char buf[1 << 16];
    size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
        text.append(buf, n);
        if (text.size() > kMaxFileBytes) {
            std::fclose(f);
            fail_file(origin, "file is larger than " + std::to_string(kMaxFileBytes) + " bytes");
        }
    }
    const bool failed = std::ferror(f) != 0;
    const int err = errno;
    std::fclose(f);
    if (failed) fail_file(origin, "cannot read: " + std::generic_category().message(err));
    return parse_sensation_file(text, origin);
}

}  // namespace feel::format
