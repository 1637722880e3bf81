// feel::format — sensation files ("feel/1" JSON, docs/sensation-format.md).
//
// A file holds named sensations. A sensation is one effect, or a compound whose effects
// play together, each with its own start delay. Reading validates everything: every
// error names the file, the sensation, the field path and the allowed range. Writing
// gives back the same file for a file in canonical form, and the same model for any file:
//
//   write(parse(text)) == text            for text in canonical form
//   parse(write(parse(f))) == parse(f)    for every valid file f
//
// The canonical form is the writer's output: keys in the documented order, optional
// fields only where the file spelled them out or they differ from their default,
// nlohmann::json's dump(2) layout, and a trailing newline.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "feel/effect.hpp"

namespace feel::format {

// One effect of a sensation: the engine's parameters plus its force-profile samples.
struct EffectSpec {
    EffectParams params{};
    std::vector<int16_t> samples;  // force_profile only, interleaved by channel
    // Optional fields that the file spelled out, as JSON pointers relative to the effect
    // (e.g. "/gain"), so that writing gives back what was read even where a value equals
    // its default.
    std::vector<std::string> explicit_fields;

    friend bool operator==(const EffectSpec&, const EffectSpec&) = default;
};

struct Sensation {
    std::string name;
    std::optional<std::string> description;
    bool compound = false;            // written as {"effects": [...]}
    std::vector<EffectSpec> effects;  // one for a single-effect sensation

    friend bool operator==(const Sensation&, const Sensation&) = default;
};

struct SensationFile {
    std::vector<Sensation> sensations;  // in file order
    [[nodiscard]] const Sensation* find(std::string_view name) const noexcept;

    friend bool operator==(const SensationFile&, const SensationFile&) = default;
};

// Thrown for any invalid file; what() is the full message, e.g.
//   examples/a.json: sensation "hum": periodic.phase = 36000 is out of range (allowed 0..35999)
class FormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The value of the "format" member of every file.
inline constexpr std::string_view kFormatVersion = "feel/1";
// Sensation names: 1 to 64 of the characters a-z A-Z 0-9 _ - . (they are typed on
// command lines and appear in messages).
inline constexpr size_t kMaxSensationNameLength = 64;
[[nodiscard]] bool is_valid_sensation_name(std::string_view name) noexcept;
// load_sensation_file() refuses larger files.
inline constexpr size_t kMaxFileBytes = 64u << 20;
// The most effects in one file, all sensations together (a single-effect sensation is
// one, a compound one per entry of "effects"). With it, reading any file takes at most
// about twice its size in memory (docs/sensation-format.md, "Limits").
inline constexpr size_t kMaxFileEffects = 4096;

// `origin` names the file in messages.
[[nodiscard]] SensationFile parse_sensation_file(std::string_view text, std::string_view origin);
// Reads and parses a file; an unreadable file is a FormatError naming the path.
[[nodiscard]] SensationFile load_sensation_file(const std::filesystem::path& path);
// The canonical text of `file`. Throws FormatError if the model is not valid (a bad
// name, a duplicate name, an effect validate_effect() rejects, a non-compound sensation
// without exactly one effect): a file that could not be read back is never written.
[[nodiscard]] std::string write_sensation_file(const SensationFile& file);

// The JSON Schema (draft 2020-12) of feel/1, generated from the format's field table:
// what docs/feel-1.schema.json holds (`feel schema` prints it) for editors to complete and
// check fields. Ranges are left to the reader.
[[nodiscard]] std::string json_schema();

}  // namespace feel::format
