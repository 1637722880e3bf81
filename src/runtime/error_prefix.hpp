// Names a nested field in an Error: "safety." + "fade_in_us", so the host can tell which
// block of a configuration was wrong. Private to the runtime.
#pragma once

#include <algorithm>
#include <iterator>
#include <string_view>

#include "feel/status.hpp"

namespace feel::runtime::detail {

// The error with `prefix` in front of its field; unchanged when the two do not fit.
[[nodiscard]] inline Error prefixed(std::string_view prefix, Error e) noexcept {
    const std::string_view field(e.field);
    if (prefix.size() + field.size() + 1 > sizeof e.field) return e;
    char joined[sizeof e.field] = {};
    std::copy(prefix.begin(), prefix.end(), joined);
    std::copy(field.begin(), field.end(), joined + prefix.size());
    std::copy(std::begin(joined), std::end(joined), e.field);
    return e;
}

}  // namespace feel::runtime::detail
