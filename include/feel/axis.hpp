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

// The most axes a device, and so an effect, may have: the size of every per-axis array in
// the API and in the engine's state. 6 (every Axis) unless the build sets FEEL_MAX_AXES, a
// capacity fixed at compile time: the Cortex-M4F firmware for a 2-axis device builds the
// engine with FEEL_MAX_AXES=2, which takes its RAM for effect slots and the velocity
// estimator's history down to what 2 axes need (docs/firmware.md). Such a build names only
// the first kMaxAxes axes (x, y, ...) and refuses a device or an effect with more; a program
// must be compiled with the value its feel library was built with. Only the engine
// (src/engine) is built with a value other than 6.
#ifndef FEEL_MAX_AXES
#define FEEL_MAX_AXES 6
#endif
inline constexpr int kMaxAxes = FEEL_MAX_AXES;
static_assert(kMaxAxes >= 1 && kMaxAxes <= 6, "FEEL_MAX_AXES must be 1..6 (x, y, z, rx, ry, rz)");

// The axes x, y, z, rx, ry, rz in order, the first n of them: the default of an
// axes[kMaxAxes] array, as FEEL_AXES_IN_ORDER(FEEL_MAX_AXES).
#define FEEL_AXES_IN_ORDER_1 ::feel::Axis::x
#define FEEL_AXES_IN_ORDER_2 FEEL_AXES_IN_ORDER_1, ::feel::Axis::y
#define FEEL_AXES_IN_ORDER_3 FEEL_AXES_IN_ORDER_2, ::feel::Axis::z
#define FEEL_AXES_IN_ORDER_4 FEEL_AXES_IN_ORDER_3, ::feel::Axis::rx
#define FEEL_AXES_IN_ORDER_5 FEEL_AXES_IN_ORDER_4, ::feel::Axis::ry
#define FEEL_AXES_IN_ORDER_6 FEEL_AXES_IN_ORDER_5, ::feel::Axis::rz
#define FEEL_AXES_IN_ORDER_EXPANDED(n) FEEL_AXES_IN_ORDER_##n
#define FEEL_AXES_IN_ORDER(n) FEEL_AXES_IN_ORDER_EXPANDED(n)

[[nodiscard]] constexpr std::string_view axis_name(Axis a) noexcept {
    constexpr std::string_view names[] = {"x", "y", "z", "rx", "ry", "rz"};
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
