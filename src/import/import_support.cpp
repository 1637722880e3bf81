// Shared importer helpers (import_support.hpp) and the format dispatch (import.hpp).
#include "import_support.hpp"

#include <algorithm>
#include <cctype>

#include "feel/effect_validation.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::import {
namespace detail {

void fail(const std::string& message) { throw ImportError(message); }

void check_range(std::string_view where, std::string_view field, int64_t v, Range r) {
    if (r.contains(v)) return;
    fail(std::string(where) + ": " + std::string(field) + " = " + std::to_string(v) +
         " is out of range (allowed " + std::to_string(r.min) + ".." + std::to_string(r.max) + ")");
}

void check_sensation(const format::Sensation& s, std::string_view where) {
    for (size_t i = 0; i < s.effects.size(); ++i) {
        const format::EffectSpec& e = s.effects[i];
        if (const Error err = validate_effect(e.params, e.samples)) {
            fail(std::string(where) + (s.effects.size() > 1 ? " (effect " + std::to_string(i + 1) + ")" : "") +
                 ": the imported effect is not valid in feel: " + err.message());
        }
    }
    format::SensationFile file;
    file.sensations.push_back(s);
    try {
        (void)format::write_sensation_file(file);
    } catch (const format::FormatError& e) {
        fail(std::string(where) + ": " + e.what());
    }
}

std::string sensation_name(const ImportOptions& options, std::string_view fallback) {
    if (options.name.empty()) return std::string(fallback);
    if (!format::is_valid_sensation_name(options.name)) {
        fail("--name \"" + options.name + "\" is not a sensation name (1.." +
             std::to_string(format::kMaxSensationNameLength) + " of a-z A-Z 0-9 _ - .)");
    }
    return options.name;
}

}  // namespace detail

namespace {

bool ends_with_ci(std::string_view s, std::string_view suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                      [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

}  // namespace

std::string_view format_name(SourceFormat f) noexcept {
    switch (f) {
        case SourceFormat::ffe: return "DirectInput effect file (.ffe)";
        case SourceFormat::ahap: return "Apple AHAP";
        case SourceFormat::wav: return "WAV";
    }
    return "?";
}

std::optional<SourceFormat> detect_format(std::string_view bytes, std::string_view file_name) {
    if (bytes.size() >= 12 && bytes.substr(0, 4) == "RIFF") {
        if (bytes.substr(8, 4) == "FORC") return SourceFormat::ffe;
        if (bytes.substr(8, 4) == "WAVE") return SourceFormat::wav;
    }
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && bytes[first] == '{' &&
        bytes.substr(0, 4096).find("\"Pattern\"") != std::string_view::npos) {
        return SourceFormat::ahap;
    }
    if (ends_with_ci(file_name, ".ffe")) return SourceFormat::ffe;
    if (ends_with_ci(file_name, ".ahap")) return SourceFormat::ahap;
    if (ends_with_ci(file_name, ".wav")) return SourceFormat::wav;
    return std::nullopt;
}

std::string sensation_name_from_file(std::string_view file_name) {
    const size_t slash = file_name.find_last_of("/\\");
    std::string_view stem = slash == std::string_view::npos ? file_name : file_name.substr(slash + 1);
    const size_t dot = stem.find_last_of('.');
    if (dot != std::string_view::npos && dot > 0) stem = stem.substr(0, dot);
    std::string name;
    for (char c : stem.substr(0, format::kMaxSensationNameLength)) {
        const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
        name += ok ? c : '_';
    }
    return name.empty() ? "imported" : name;
}

ImportResult import_sensation(std::string_view bytes, std::string_view file_name, const ImportOptions& options) {
    if (bytes.size() > kMaxImportBytes) {
        detail::fail(std::string(file_name) + ": the file has " + std::to_string(bytes.size()) +
                     " bytes; imports read at most " + std::to_string(kMaxImportBytes) + " bytes (16 MiB)");
    }
    const std::optional<SourceFormat> f = detect_format(bytes, file_name);
    if (!f) {
        detail::fail(std::string(file_name) +
                     ": unknown format: expected a DirectInput effect file (RIFF FORC, .ffe), an Apple AHAP "
                     "file (JSON with a \"Pattern\", .ahap) or a WAV file (RIFF WAVE, .wav)");
    }
    ImportOptions named = options;
    if (named.name.empty()) named.name = sensation_name_from_file(file_name);
    try {
        switch (*f) {
            case SourceFormat::ffe: return import_ffe(bytes, named);
            case SourceFormat::ahap: return import_ahap(bytes, named);
            case SourceFormat::wav: return import_wav(bytes, named);
        }
    } catch (const ImportError& e) {
        throw ImportError(std::string(file_name) + ": " + e.what());
    }
    detail::fail("unreachable format");
}

}  // namespace feel::import
