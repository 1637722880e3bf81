// feel — device axes.
//
//            +y (forward, away from the user)
//             ^
//             |
//   -x <------+------> +x (right)        +z is up, out of the page.
//             |                          rx, ry, rz are rotations about x, y, z
//             v                          (right-hand rule), used by nD devices (§6.5.d).
//            -y (toward the user)
//
// A force's sign is physical: a positive force on an axis pushes the handle toward +axis.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace feel {

enum class Axis : uint8_t { x, y, z, rx, ry, rz };
inline constexpr int kMaxAxes = 6;

[[nodiscard]] constexpr std::string_view axis_name(Axis a) noexcept {
    constexpr std::string_view names[kMaxAxes] = {"x", "y", "z", "rx", "ry", "rz"};
    return names[static_cast<int>(a)];
}

[[nodiscard]] constexpr std::optional<Axis> axis_from_name(std::string_view s) noexcept {
    for (int i = 0; i < kMaxAxes; ++i) {
        if (axis_name(static_cast<Axis>(i)) == s) return static_cast<Axis>(i);
    }
    return std::nullopt;
}

[[nodiscard]] constexpr int axis_index(Axis a) noexcept { return static_cast<int>(a); }

}  // namespace feel
