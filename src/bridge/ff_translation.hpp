// A Linux `struct ff_effect` as feel effects, and a feel device as evdev capabilities.
//
// Portable: it reads the kernel's structs (linux/input.h, from the C library's kernel
// headers) but calls no kernel, so the unit tests check every field without uinput.
//
// Design. One ff_effect becomes one feel effect, except FF_RUMBLE, which becomes two
// sines (a strong, slow one and a weak, fast one: the two motors of a rumble pad). Units go
// through evdev_units.hpp (hid-pidff's arithmetic: the same integers as feel's USB device
// gets). Where evdev allows something feel's validator does not, the translation either
// writes the same force in feel's terms (a negative periodic magnitude is the wave half a
// period on, or for a saw the other saw) or refuses with -EINVAL and a sentence naming the
// ff_effect field, its value and the range allowed; it never clamps.
#pragma once

#include <linux/input.h>

#include <cstdint>
#include <string>
#include <vector>

#include "feel/effect.hpp"
#include "feel/host/device.hpp"

namespace feel::bridge {

// FF_RUMBLE's two sines (docs/real-devices.md, "FF_RUMBLE"): the strong motor as a 20 Hz
// sine, the weak motor as a 100 Hz sine, each on the device's first axis.
inline constexpr int64_t kRumbleStrongPeriodUs = 50'000;
inline constexpr int64_t kRumbleWeakPeriodUs = 10'000;

// What one ff_effect becomes on a feel device.
struct Translation {
    int error = 0;                       // 0, or a negative errno for the upload's reply
    std::string message;                 // why, when error != 0
    std::vector<EffectParams> effects;   // 1 (2 for FF_RUMBLE) when error == 0
};

// Translates `effect` for a device with `caps` (its axes, buttons and effect types).
[[nodiscard]] Translation translate_effect(const ff_effect& effect, const host::DeviceCaps& caps);

// The feel button (1..32) an evdev key code names, or 0 when it names none: BTN_TRIGGER
// (0x120) .. BTN_DEAD (0x12F) are buttons 1..16, BTN_TRIGGER_HAPPY1.. (0x2C0..) 17..32.
[[nodiscard]] int32_t button_of_key(uint16_t code) noexcept;
// The key code of feel button 1..32 (the inverse of button_of_key).
[[nodiscard]] uint16_t key_of_button(int32_t button) noexcept;
// The evdev absolute axis of feel's axis index 0..5 (x, y, z, rx, ry, rz).
[[nodiscard]] uint16_t abs_of_axis(int32_t axis_index) noexcept;

// The EV_FF bits (FF_CONSTANT..FF_AUTOCENTER, and the waveforms) a device with `caps`
// supports, and in `missing` one line per bit it lacks, naming the feel type it needs.
struct FfCapabilities {
    std::vector<uint16_t> bits;
    std::vector<std::string> missing;
};
[[nodiscard]] FfCapabilities ff_capabilities(const host::DeviceCaps& caps);

// A play count from an EV_FF event as feel's iterations: 1..254 as given, and anything
// larger as infinite (SDL sends INT_MAX for SDL_HAPTIC_INFINITY). `value` > 0.
[[nodiscard]] int32_t iterations_of_count(int32_t value) noexcept;

// One line saying what a game asked, in evdev's own terms (`feel bridge --verbose`), e.g.
//   "FF_CONSTANT id 1: length 20000 ms, delay 0 ms, direction 0x6000, level 8192, envelope 1000 ms 4096 / 1000 ms 4096"
[[nodiscard]] std::string describe_ff_effect(const ff_effect& effect);

// The centring spring FF_AUTOCENTER asks for: strength 0..0xFFFF as both coefficients on
// each of the device's first two axes, full saturation, centre 0, endless.
[[nodiscard]] EffectParams autocenter_spring(uint16_t strength, const host::DeviceCaps& caps);

}  // namespace feel::bridge
