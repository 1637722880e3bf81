// The bytes FunctionFS wants on ep0 before the function can be bound: the interface's
// descriptors for full and high speed, and its strings (linux/usb/functionfs.h, format V2).
//
// The function is one HID interface (class 3, no boot subclass: a joystick is not a boot
// device) with its HID class descriptor (0x21, 9 bytes, straight after the interface, as
// HID 1.11 §7.1 orders it and FunctionFS accepts) and two interrupt endpoints, IN first
// (ep1, address 0x81) then OUT (ep2, address 0x02). Both speeds poll every 1 ms:
//
//   full speed   wMaxPacketSize 64    bInterval 1 (frames of 1 ms)
//   high speed   wMaxPacketSize 1024  bInterval 4 (2^(4-1) microframes of 125 us = 1 ms)
//
// A report larger than a packet travels as several packets of one transfer; the device
// side reassembles output reports by their size (report_assembler.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace feel::usb::detail {

inline constexpr uint16_t kFullSpeedPacketBytes = 64;
inline constexpr uint16_t kHighSpeedPacketBytes = 1024;
inline constexpr uint8_t kFullSpeedInterval = 1;   // frames (1 ms)
inline constexpr uint8_t kHighSpeedInterval = 4;   // 2^(n-1) microframes: 1 ms
inline constexpr uint8_t kEndpointInAddress = 0x81;
inline constexpr uint8_t kEndpointOutAddress = 0x02;
inline constexpr uint16_t kBcdHid = 0x0111;        // HID 1.11

// The HID class descriptor of the interface: 9 bytes, one report descriptor of this length.
[[nodiscard]] std::array<uint8_t, 9> hid_class_descriptor(uint16_t report_descriptor_bytes);

// The V2 descriptors blob (FS and HS sets). Throws std::invalid_argument for a report
// descriptor longer than 0xFFFF bytes.
[[nodiscard]] std::vector<uint8_t> function_descriptors(std::size_t report_descriptor_bytes);

// The strings blob: one language (en-US, 0x0409), one string, the interface's name.
[[nodiscard]] std::vector<uint8_t> function_strings(const std::string& interface_name);

}  // namespace feel::usb::detail
