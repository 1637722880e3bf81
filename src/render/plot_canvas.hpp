// What the two plots share (plot.cpp: force and position against time; plot_xy.cpp: the
// x-y plane): colors, text, legends, the data-to-page mapping and the output file.
//
// Internal to feel_render. Layout is in device units (px for PNG, pt for SVG).
#pragma once

#include <cairo.h>

#include <functional>
#include <string>
#include <vector>

#include "feel/axis.hpp"
#include "plot_scale.hpp"

namespace feel::render::detail {

struct Rgb {
    double r, g, b;
};
// One color per axis (x, y, z, rx, ry, rz), distinct for the common color-vision types.
inline constexpr Rgb kAxisColors[kMaxAxes] = {
    {0.122, 0.467, 0.706}, {0.839, 0.373, 0.000}, {0.173, 0.627, 0.173},
    {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761},
};
inline constexpr Rgb kInk{0.15, 0.15, 0.17};
inline constexpr Rgb kMuted{0.38, 0.38, 0.42};
inline constexpr Rgb kGrid{0.90, 0.90, 0.92};
inline constexpr Rgb kWallColor{0.70, 0.09, 0.12};     // walls: their surface line and solid side
inline constexpr Rgb kBarrierColor{0.45, 0.20, 0.62};  // barriers: their slab between the faces
inline constexpr Rgb kTargetColor{0.42, 0.42, 0.46};   // the hand's target (x-y plot)
inline constexpr Rgb kForceColor{0.10, 0.55, 0.25};    // force arrows (x-y plot)

// Line styles, the same in both plots and their legends.
inline constexpr double kTargetDash[] = {7, 4};    // the hand's target
inline constexpr double kReportedDash[] = {1.5, 3};  // the reported position (round caps)
inline constexpr double kMassDash[] = {9, 3, 2, 3};  // a dynamic's simulated mass (dash-dot)

void set_color(cairo_t* cr, Rgb c, double alpha = 1);
void set_font(cairo_t* cr, double size, bool bold = false);

enum class Align { start, center, end };
// Draws `text` with its horizontal anchor at x and its vertical center at y.
void draw_text(cairo_t* cr, const std::string& text, double x, double y, Align align);
// The advance width of `text` in the current font.
[[nodiscard]] double text_width(cairo_t* cr, const std::string& text);

struct Rect {
    double x, y, w, h;
};

// Data to page coordinates. `inset` keeps the value range a few units inside the frame.
struct Mapping {
    Rect area;
    Scale xs, ys;
    double inset = 0;
    [[nodiscard]] double px(double x) const { return area.x + (x - xs.lo) / (xs.hi - xs.lo) * area.w; }
    [[nodiscard]] double py(double y) const {
        const double h = area.h - 2 * inset;
        return area.y + inset + h - (y - ys.lo) / (ys.hi - ys.lo) * h;
    }
};

// One legend entry: a short sample of the line style (or a filled swatch) and a label.
struct LegendEntry {
    enum class Mark { line, dashed, dotted, dash_dot, band, arrow };
    std::string label;
    Rgb color;
    Mark mark = Mark::line;
    double alpha = 1;
};
// A legend box whose top right corner is at (right, top), entries in rows no wider than
// max_width. Returns the box's height.
double draw_legend(cairo_t* cr, double right, double top, double max_width, const std::vector<LegendEntry>& entries);

// The compass angle's direction on x, y, exact at the axis angles (0 -> +y, 9000 -> +x).
void compass_direction(int32_t angle, double& ux, double& uy) noexcept;

// ".svg" or ".png" (lower case) for a path with that extension; throws
// std::invalid_argument naming `flag` and the allowed extensions for another one.
std::string plot_extension(const std::string& path, const std::string& flag);

// Creates the surface for the file's format, calls draw, and writes the file; throws
// std::runtime_error when it cannot be written.
void write_plot_file(const std::string& path, const std::string& extension, double width, double height,
                     const std::function<void(cairo_t*)>& draw);

}  // namespace feel::render::detail
