// feel::format — reading one effect object of a sensation file.
//
// The file-level reader (sensation_reader.cpp) finds the effects; this turns one
// effect's JSON into an EffectSpec and validates it with validate_effect().
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "feel/format/sensation_file.hpp"
#include "feel/units.hpp"
#include "json_document.hpp"

namespace feel::format::detail {

// Where a message comes from: "<origin>: sensation "<name>": <prefix><path>: <problem>".
struct Where {
    std::string_view origin;
    std::string_view sensation;  // empty for file-level errors
    std::string prefix;          // "effects[1]." inside a compound, else ""

    [[noreturn]] void fail(std::string_view path, std::string_view problem) const;
    // The validator's form: "<path> = <value> is out of range (allowed <min>..<max>)",
    // with ' or "infinite"' for the fields that may be infinite.
    [[noreturn]] void fail_range(std::string_view field, int64_t value, Range allowed) const;
};

// Reads `obj` into `out` and validates it. `allow_description`: the object is a whole
// single-effect sensation, which may also carry the sensation's description.
// Throws FormatError.
void read_effect(const JsonValue& obj, const Where& where, bool allow_description, EffectSpec& out);

// "1..65000000"
[[nodiscard]] std::string range_text(Range r);

}  // namespace feel::format::detail
