// feel::studio — the one description of the format's fields that the Studio's forms are
// generated from.
//
// Nothing here is written per type. The fields of each type's block come from the
// format's own field table (src/format/effect_fields.hpp: the table the reader and the
// writer walk), and each field's range comes from the one validator: the describer sets
// the field of a valid effect of that type to a value far out of range, asks
// validate_effect() and reads the range out of its error. So a form can never show a
// range other than the one a file is checked against. Units follow the format's naming
// rules (docs/sensation-format.md, "Units"): *_us are microseconds, angles and
// directions hundredths of a degree, everything else ±10000 of the device's capability.
#pragma once

#include <nlohmann/json.hpp>

#include "feel/format/sensation_file.hpp"

namespace feel::studio {

// {"types": [{"type", "class", "block", "shape", "envelope", "fields": [...],
//             "control_law": [...]?}, ...],
//  "common": [...], "envelope": [...]}
// where each field is {"name", "kind" ("integer", "boolean", "choice"), "required",
// "choices"?, "min"?, "max"?, "infinite"?, "unit", "scale"?, "shown_unit"?} (an angle,
// kept in 0.01° in the file, is shown in degrees: shown = value × scale), and
// "direction": {"forms": [{"form", "axes", "exact_axes", "per_axis", "components": [fields],
// "default"}]}: the four forms of §6.5, the axes each fits (exactly, or any of them), and
// their components (one per axis of the effect for cartesian and moments). `starters`
// gives a valid effect of every type (the Studio's palette presets); a type it lacks is
// left out.
[[nodiscard]] nlohmann::json describe_fields(const format::SensationFile& starters);

}  // namespace feel::studio
