// feel::codegen — source code that recreates a sensation (§1.4, §9.1: the Studio "automatically
// generates the DirectX code").
//
// Three languages:
//   cpp      a C++ program built from the §8 wrapper functions (feel::iforce, docs/wrappers.md)
//            and the host API (docs/host-api.md): one function per sensation that creates its
//            effects on a device, and a main that opens the device and plays one;
//   c        the same program in C on feel.h (docs/c-api.md): feel_effect_params filled field
//            by field and feel_create_effect;
//   library  the two calls of §9.5 (SensationLibrary::load, play) for the saved file.
//
// Every generated program creates exactly the EffectParams the file holds: the generator
// checks it itself (see effect_code.hpp), and tests/codegen compiles the programs of every
// example file and compares what the simulated device received with what the file gives it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "feel/format/sensation_file.hpp"

namespace feel::codegen {

enum class Language { cpp, c, library };

// "cpp", "c", "library"; nullopt for anything else.
[[nodiscard]] std::optional<Language> language_from_name(std::string_view name) noexcept;
[[nodiscard]] std::string_view language_name(Language language) noexcept;
// The file name extension of the generated code: ".cpp", ".c" (library: ".cpp").
[[nodiscard]] std::string_view language_extension(Language language) noexcept;

// The code for the named sensations of `file`, in file order (empty `names`: every
// sensation). `file_path` is how the code names the sensation file (the library snippet
// loads it; the programs mention it in their opening comment). Throws std::invalid_argument
// for a name the file lacks (the message lists the file's names) or a duplicate name.
[[nodiscard]] std::string export_code(Language language, const format::SensationFile& file,
                                      std::span<const std::string> names, std::string_view file_path);

}  // namespace feel::codegen
