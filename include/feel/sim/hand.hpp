// feel::sim — the simulated hand and the target motions it follows.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "feel/axis.hpp"

namespace feel::sim {

// none: a free handle. loose/firm/stiff: tethered to the target by the profile's grip.
// kinematic: the handle follows the target exactly (position prescribed).
enum class Grip : uint8_t { none, loose, firm, stiff, kinematic };

// "none", "loose", "firm", "stiff", "kinematic".
[[nodiscard]] std::optional<Grip> grip_from_name(std::string_view name) noexcept;
[[nodiscard]] std::string_view grip_name(Grip g) noexcept;

// The fastest sine or circle a hand can be asked to follow, Hz. Voluntary hand motion
// stays below about 10 Hz; the margin leaves room for tests of the grip's response.
inline constexpr double kMaxMotionHz = 50;

// A target motion, in normalized position units, as a function of time.
//   hold:X[,Y[,Z]]          constant positions (axes not given hold 0)
//   ramp:AXIS:FROM:TO       linear from FROM to TO over the motion's duration, then TO
//   sine:AXIS:AMPLITUDE:HZ  AMPLITUDE·sin(2π·HZ·t)
//   circle:RADIUS:HZ        x = R·cos(2π·HZ·t), y = R·sin(2π·HZ·t)
//   csv:PATH                rows "t_us,x[,y[,z...]]", linear interpolation, held at the ends
// AXIS is an axis name (x, y, z, rx, ry, rz) of the device. Every position the target can
// reach (X, FROM, TO, ±AMPLITUDE, ±RADIUS, csv positions) lies within the travel,
// -10000..10000: the target is where the hand wants the handle, and the handle cannot be
// anywhere else. HZ is in (0, kMaxMotionHz]. The csv file may start with a header line
// whose first field is "t_us"; blank lines and lines starting with '#' are skipped; t_us
// is >= 0 and strictly increasing; every row has the same number of positions, 1 to the
// device's axis count. Axes the motion does not name hold 0.
class TargetMotion {
public:
    // Parses a --motion SPEC; throws std::invalid_argument naming the bad part and the
    // allowed form or range. duration_s is the length of the render (used by ramp, which
    // needs it finite and > 0). axis_count is the device's, 1..kMaxAxes.
    static TargetMotion parse(std::string_view spec, double duration_s, int32_t axis_count);
    // A hold at these positions (x, y, ...); throws std::invalid_argument for more than
    // kMaxAxes positions or a position outside -10000..10000.
    static TargetMotion hold_at(std::initializer_list<double> positions);

    struct Sample {
        double position[kMaxAxes] = {};  // normalized
        double velocity[kMaxAxes] = {};  // normalized units / s
    };
    // Never allocates.
    [[nodiscard]] Sample at(double t_s) const noexcept;
    [[nodiscard]] const std::string& spec() const noexcept { return spec_; }
    // How many leading axes the motion names (hold:1,2 -> 2, sine:z:... -> 3, circle -> 2).
    [[nodiscard]] int32_t used_axes() const noexcept { return used_axes_; }

private:
    enum class Kind : uint8_t { hold, ramp, sine, circle, table };
    Kind kind_ = Kind::hold;
    std::string spec_ = "hold:0";
    int axis_ = 0;
    double a_ = 0, b_ = 0, c_ = 0;  // kind-specific parameters
    double hold_[kMaxAxes] = {};
    double duration_s_ = 1;
    std::vector<double> table_t_;                 // csv: times, s
    std::vector<double> table_x_;                 // csv: row-major positions
    int table_axes_ = 0;
    int32_t used_axes_ = 1;

    friend class MotionParser;
};

}  // namespace feel::sim
