// feel::studio — the Studio's code export (issue 11 §2): the browser's `export_code` message
// (the current sensation, as set_sensation sends it, and a language) answered with
// `exported` (the code and a file name to download it as), made by src/codegen, the same
// generators as `feel export`.
#pragma once

#include <nlohmann/json.hpp>

namespace feel::studio {

// `m` has passed the protocol's schema. The sensation is read by the format's reader, as
// set_sensation reads it; a sensation it refuses gets an `error` reply with its sentence.
[[nodiscard]] nlohmann::json export_reply(const nlohmann::json& m);

}  // namespace feel::studio
