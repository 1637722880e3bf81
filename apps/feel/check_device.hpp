// feel check --device (check_device.cpp): a valid file judged by a device's capabilities.
#pragma once

#include <iosfwd>
#include <string>

#include "feel/format/sensation_file.hpp"

namespace feel::cli {

// Prints the device and, for each sensation of `file` (read from `path`), whether it plays
// on the device at `address` and why not. Returns whether every sensation plays. Throws as
// open_device() does for an address that is wrong (UsageError) or unreachable.
[[nodiscard]] bool check_on_device(const std::string& path, const format::SensationFile& file,
                                   const std::string& address, std::ostream& out);

}  // namespace feel::cli
