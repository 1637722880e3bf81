// feel::codegen — one effect as statements: the fields of an EffectParams that differ from a
// starting value, each as an assignment in C++ or C.
//
// The field list is the format's own (src/format/effect_fields.hpp, the table the reader and
// the writer walk) plus the Effect Structure's common fields, so that a field added to the
// format is exported without touching the generators. Each generator starts from a value
// (a §8 wrapper's result in C++, feel_effect_params_init's defaults in C) and assigns what
// differs. assignments() applies the assignments to a copy of the start and checks that the
// copy equals the effect: a field the walk missed can never be silently dropped.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "feel/effect.hpp"

namespace feel::codegen {

enum class Dialect { cpp, c };

// One statement's parts: `<object>.<path> = <value>;`.
struct Assignment {
    std::string path;   // e.g. "conditions[1].deadband", in C "constant_magnitude"
    std::string value;  // a literal: 2500, feel::kInfiniteUs, FEEL_WALL_SENSE_NEGATIVE, true
};

// The assignments that turn `start` into `effect`, in the format's canonical field order.
// Throws std::logic_error if they would not (a field missing from the walk: a bug here).
[[nodiscard]] std::vector<Assignment> assignments(const EffectParams& start, const EffectParams& effect,
                                                  Dialect dialect);

// The type's constant: feel::EffectType::sine, FEEL_TYPE_SINE.
[[nodiscard]] std::string type_literal(EffectType type, Dialect dialect);

// A C or C++ identifier made of a sensation name (letters, digits, '_', '-', '.'): '-' and
// '.' become '_', a leading digit gets a "s_" before it.
[[nodiscard]] std::string identifier(std::string_view name);

// Text for a // or /* */ comment: one line, no comment terminators.
[[nodiscard]] std::string comment_text(std::string_view text);

// comment_text(text) in lines of at most `width` characters (a longer word stays whole), each
// starting with `lead` ("// ", " * ") and ending with a newline.
[[nodiscard]] std::string comment_lines(std::string_view text, std::string_view lead, size_t width = 100);

// A string literal for C and C++ (sensation names and paths: escapes quotes and backslashes).
[[nodiscard]] std::string string_literal(std::string_view text);

}  // namespace feel::codegen
