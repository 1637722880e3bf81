// Helpers the importers share: range checks that name the source's field, and the last
// step, which checks the sensation with the format's own validator.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "feel/import/import.hpp"
#include "feel/units.hpp"

namespace feel::import::detail {

[[noreturn]] void fail(const std::string& message);

// "WHERE: FIELD = VALUE is out of range (allowed MIN..MAX)" unless r contains v.
void check_range(std::string_view where, std::string_view field, int64_t v, Range r);

// Throws ImportError naming `where` unless every effect of `s` passes validate_effect and
// the sensation can be written (name, compound shape).
void check_sensation(const format::Sensation& s, std::string_view where);

// The name options.name gives, else `fallback`; refuses an invalid name.
[[nodiscard]] std::string sensation_name(const ImportOptions& options, std::string_view fallback);

}  // namespace feel::import::detail
