// Which sensation of a file a command works on: the one --sensation names, or, without
// --sensation, the file's only one. Shared by render and play so both say the same thing.
#pragma once

#include <string>

#include "feel/format/sensation_file.hpp"

namespace feel::cli {

// Throws UsageError listing the file's sensations when `name` is not among them, or when
// `name` is empty and the file holds none or several.
[[nodiscard]] const format::Sensation& choose_sensation(const format::SensationFile& file,
                                                        const std::string& name, const std::string& path);

}  // namespace feel::cli
