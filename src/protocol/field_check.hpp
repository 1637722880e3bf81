// One field element's value against its logical range, with the error naming it the way
// the host sees it ("set_effect.gain", "custom_force_data.samples[3]"). Shared by encode()
// and decode(). Private to the protocol library.
#pragma once

#include <cstdint>

#include "feel/status.hpp"
#include "field_spec.hpp"

namespace feel::protocol::detail {

// Ok, or the error for element `index` of `field` in `report` holding `value`. Never
// allocates.
[[nodiscard]] Error check_field(const ReportSpec& report, const FieldSpec& field, int index,
                                int64_t value) noexcept;

// Writes "<report key>.<path>" with "[i]" replaced by "[index]" into `out` (NUL-terminated,
// cut to fit).
void field_name(const ReportSpec& report, const FieldSpec& field, int index, char (&out)[48]) noexcept;

}  // namespace feel::protocol::detail
