// feel::protocol — a report as one line of text, for logs (`feel device --usb --log`).
#pragma once

#include <string>

#include "feel/protocol/reports.hpp"

namespace feel::protocol {

// "set_effect sequence=0 block=1 type=3 duration_us=2000000 ... axes[0]=0 ...": the report's
// key, then every field of the report table in wire order as path=value (wire values: enums
// as their number, text fields as their bytes). Allocates; not for the real-time path.
[[nodiscard]] std::string describe_report(const AnyReport& report);

}  // namespace feel::protocol
