// Joystick Input's report spec for a device's own inputs (codec.hpp: JoystickLayout),
// built without allocating so that decode() in a device's layout stays allocation-free.
// Private to the protocol library.
#pragma once

#include <cstdint>

#include "feel/protocol/codec.hpp"
#include "field_spec.hpp"
#include "hid_usages.hpp"

namespace feel::protocol::detail {

// Joystick Input's fields, shared by the full layout in the report table and by
// build_joystick_spec: `count` buttons of one bit (Button 1..count), `count` hats of four
// bits (Hat Switch, 0..7, null 15 = centred), and constant padding (no usage, 0).
inline constexpr Range kBinary{0, 1};
inline constexpr Range kHatDirection{0, 7};  // N, NE, E, SE, S, SW, W, NW; 15 (null) centred
inline constexpr int64_t kHatCentred = 15;

constexpr FieldSpec button_field(int count, std::span<const uint32_t> usages) noexcept {
    // In the struct the buttons are the bits of one word: this field has its own accessors.
    FieldSpec f = field(0, 1, kBinary).times(count).usages(usages.first(static_cast<std::size_t>(count)));
    f.path = "buttons[i]";
    f.get = [](const void* r, int i) noexcept -> int64_t {
        return (static_cast<const JoystickInputReport*>(r)->buttons >> i) & 1u;
    };
    f.set = [](void* r, int i, int64_t v) noexcept {
        uint32_t& word = static_cast<JoystickInputReport*>(r)->buttons;
        const uint32_t bit = 1u << i;
        word = v != 0 ? (word | bit) : (word & ~bit);
        return true;
    };
    return f;
}

constexpr FieldSpec hat_field(int count) noexcept {
    // A feel device's hats know pushed and centred: pushed is north (0), centred the null.
    FieldSpec f = field(usage::gd::kHatSwitch, 4, kHatDirection)
                      .times(count)
                      .or_infinite()
                      .only([](int64_t v) noexcept { return v == 0; },
                            "is not north (0) or centred (15): a feel device reports a pushed hat as north");
    f.path = "hats[i]";
    f.get = [](const void* r, int i) noexcept -> int64_t {
        return (static_cast<const JoystickInputReport*>(r)->hats >> i) & 1u ? 0 : kHatCentred;
    };
    f.set = [](void* r, int i, int64_t v) noexcept {
        uint8_t& bits = static_cast<JoystickInputReport*>(r)->hats;
        const auto bit = static_cast<uint8_t>(1u << i);
        bits = static_cast<uint8_t>(v != kHatCentred ? (bits | bit) : (bits & ~bit));
        return true;
    };
    return f;
}

constexpr FieldSpec padding_field(int bits) noexcept {
    FieldSpec f = field(0, static_cast<uint8_t>(bits), Range{0, 0});  // written 0, must read 0
    f.path = "padding";
    f.padding = true;
    f.get = [](const void*, int) noexcept -> int64_t { return 0; };
    f.set = [](void*, int, int64_t) noexcept { return true; };
    return f;
}


// Holds the usages and fields the spec's spans point into: build it in place, never copy.
struct JoystickSpec {
    uint32_t axis_usages[kMaxAxes] = {};
    uint32_t button_usages[32] = {};
    FieldSpec fields[5] = {};  // axes, buttons, button padding, hats, hat padding
    ReportSpec spec{};

    JoystickSpec() = default;
    JoystickSpec(const JoystickSpec&) = delete;
    JoystickSpec& operator=(const JoystickSpec&) = delete;
};

// Fills `out` for `layout` (which check_layout accepts).
void build_joystick_spec(const JoystickLayout& layout, JoystickSpec& out) noexcept;

// The walkers of encode() and decode(), for any spec.
[[nodiscard]] std::vector<uint8_t> encode_fields(const ReportSpec& spec, const void* fields);
[[nodiscard]] Error decode_fields(const ReportSpec& spec, std::span<const uint8_t> bytes,
                                  void* fields) noexcept;

}  // namespace feel::protocol::detail
