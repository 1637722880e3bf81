// evdev's force-feedback units and feel's: the one place the conversion is written.
//
// Linux describes an effect in `struct ff_effect` (linux/input.h) with 16-bit fields; feel
// in the primer's units (feel/units.hpp). A Linux game reaches a feel device two ways, and
// both must convert alike, so that a game feels the same device either way:
//   - feel's USB device (docs/usb-device.md): the kernel's hid-pidff rescales each field
//     onto the logical range feel's report descriptor declares;
//   - `feel bridge` (docs/real-devices.md): the bridge converts with the functions below.
// The functions are hid-pidff's arithmetic (drivers/hid/usbhid/hid-pidff.c, Linux 6.1) for
// feel's ranges, so the two paths give the same integers. The table is documented once, in
// docs/real-devices.md, "evdev units and feel units".
#pragma once

#include <cstdint>

#include "feel/units.hpp"

namespace feel::bridge {

// A signed level (constant level, ramp start and end, periodic magnitude and offset,
// condition coefficients and centre): -32768..32767 -> -10000..10000, toward zero.
// hid-pidff's pidff_set_signed on a field of logical range -10000..10000.
[[nodiscard]] constexpr int32_t evdev_signed_level(int16_t v) noexcept {
    if (v >= 0) return static_cast<int32_t>(int64_t{v} * kFullScale / 0x7fff);
    return static_cast<int32_t>(int64_t{v} * kFullScale / 0x8000);
}

// An unsigned level (gains, condition saturations and deadband): 0..0xFFFF -> 0..10000,
// toward zero. hid-pidff's pidff_set.
[[nodiscard]] constexpr int32_t evdev_unsigned_level(uint16_t v) noexcept {
    return static_cast<int32_t>(int64_t{v} * kFullScale / 0xffff);
}

// The largest envelope level evdev defines (the envelope's levels are 15-bit).
inline constexpr uint16_t kEvdevMaxEnvelopeLevel = 0x7fff;

// An envelope level: 0..0x7FFF -> 0..10000, toward zero (the caller refuses larger ones).
[[nodiscard]] constexpr int32_t evdev_envelope_level(uint16_t v) noexcept {
    return static_cast<int32_t>(int64_t{v} * kFullScale / kEvdevMaxEnvelopeLevel);
}

// An angle (the direction, a periodic's phase): 0..0xFFFF of a turn -> hundredths of a
// degree, 0..35999. hid-pidff rescales onto 0..36000, where 36000 (only 0xFFFF gives it) is
// the same angle as 0; feel's range is 0..35999, so it is written 0.
[[nodiscard]] constexpr int32_t evdev_angle(uint16_t v) noexcept {
    const auto centidegrees = static_cast<int32_t>(int64_t{v} * 36000 / 0xffff);
    return centidegrees == 36000 ? 0 : centidegrees;
}

// A time (replay length and delay, envelope times, period, trigger interval): milliseconds
// -> microseconds.
[[nodiscard]] constexpr int64_t evdev_ms_to_us(uint16_t ms) noexcept { return int64_t{ms} * 1000; }

}  // namespace feel::bridge
