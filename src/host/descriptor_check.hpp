// feel::host — does the device's report descriptor describe the reports this host speaks?
//
// A device that declares its reports with other sizes speaks another version of the
// protocol: every report the host encodes would be misread. Device::open reads the
// descriptor (GET_DESCRIPTOR), parses it with protocol::hid::parse_report_descriptor and
// refuses such a device with ErrorKind::protocol.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "feel/protocol/codec.hpp"

namespace feel::host {

// Empty when every report of the codec (protocol::report_size, report_kind) is declared by
// the descriptor as a report of the same kind (Input, Output, Feature) and the same size,
// and the descriptor declares no report the codec does not know; otherwise a sentence
// naming the first report that differs. Joystick Input is the device's own: its axes
// (Generic Desktop X..Rz), buttons and Hat Switches are read from the descriptor into
// `joystick` (when given), and its size must be that layout's. A standard PID device,
// whose Loop Count is 8 bits, is named as such.
[[nodiscard]] std::string check_report_descriptor(std::span<const uint8_t> descriptor,
                                                  protocol::JoystickLayout* joystick = nullptr);

}  // namespace feel::host
