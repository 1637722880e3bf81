// feel::host — the device's DeviceInfo feature report as DeviceCaps.
#pragma once

#include "feel/host/device.hpp"
#include "feel/protocol/reports.hpp"

namespace feel::host {

// Copies every field (names NUL-padded on the wire become strings; µm, mN and hundredths
// of Hz become m, N and Hz). class_name is sim::device_class_name of the device class.
[[nodiscard]] DeviceCaps caps_from_info(const protocol::DeviceInfoReport& info);

// The DeviceInfo of an enumeration entry.
[[nodiscard]] DeviceInfo device_info_from(const protocol::DeviceInfoReport& info, std::string address);

}  // namespace feel::host
