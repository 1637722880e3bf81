// feel::host — the host's checks of an effect against a device, before any byte leaves.
//
// The same rules as the device (validate_effect, the engine's device checks), so that a
// game gets the error at once with the field and the range, plus what only the wire and
// the capabilities know: the axes, buttons and hats the device has, the types it plays,
// its sample memory. (Iterations 1..255 and infinite all travel: a feel device's loop count
// is 16 bits; descriptor_check.cpp refuses a standard PID device's 8-bit one.)
#pragma once

#include <span>
#include <string_view>

#include "feel/host/device.hpp"

namespace feel::host {

// ok, or invalid_parameter / not_supported whose message starts with `what`.
[[nodiscard]] Status check_effect(const EffectParams& params, std::span<const int16_t> samples,
                                  const DeviceCaps& caps, std::string_view what);

// Whether the device, or the host on its behalf, can play the type.
[[nodiscard]] bool can_create(const DeviceCaps& caps, EffectType type) noexcept;

// "spring" etc., for messages.
[[nodiscard]] std::string effect_label(EffectType type);

}  // namespace feel::host
