// The x-y plot (`feel render --plot-xy`): the plane of a 2-axis sensation seen from above,
// +y forward (away from the user) up the page, +x to the right (docs/conventions.md).
//
// Both axes share one scale, so that a circle of the hand draws as a circle and an angle
// wall at compass 4500 lies at 45°. The range is symmetric about the center and covers
// the handle, the hand's target, the reported position and every wall and barrier, so
// that a wall the hand never reaches still shows where it is.
//
// What is drawn, bottom to top: each wall's solid half-plane (shaded) and its surface line,
// each barrier's slab between its faces; the hand's target path (grey); the handle's
// path (solid); the reported position (dotted, when a clipping wall can make it differ);
// the force on the handle as arrows at evenly spaced ticks, their length proportional
// to the force; and the start of the path. A wall line is the set p·u = at across the whole
// plane (clipped to the plot), so its place can be read against the axes.
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/render/render.hpp"
#include "plot_canvas.hpp"
#include "plot_scale.hpp"

namespace feel::render {
namespace {

using namespace detail;

constexpr double kWidth = 1100;
constexpr double kHeight = 820;
constexpr double kLeft = 96;    // the y tick labels and the rotated axis label
constexpr double kTop = 76;     // the title and the subtitle
constexpr double kSide = 680;   // the square plot area
constexpr double kGutter = 24;  // between the plot and the legend column
constexpr double kArrowCount = 48;          // force arrows over the whole trace, at most
constexpr double kArrowFullScale = 0.16;    // a 10000 force: this fraction of the plotted span
constexpr double kArrowThreshold = 100;     // smaller forces (normalized) draw no arrow

// The half-width of the square view: the largest |coordinate| of anything drawn, padded.
double view_half_width(const Trace& trace) {
    double m = 0;
    for (const TraceRow& row : trace.rows) {
        for (int a = 0; a < 2; ++a) {
            m = std::max({m, std::fabs(static_cast<double>(row.position[a])),
                          std::fabs(static_cast<double>(row.reported[a])),
                          trace.has_hand ? std::fabs(static_cast<double>(row.target[a])) : 0.0});
        }
    }
    for (const SurfaceMark& s : trace.surfaces) {
        if (s.axis < 2) m = std::max(m, std::fabs(s.at) + s.thickness / 2);
    }
    return std::max(m * 1.06, 1.0);
}

// The direction across an element, on x, y; false for an element on another axis (z, rx, ...).
bool plane_direction(const SurfaceMark& s, double& ux, double& uy) {
    if (s.axis >= 2) return false;
    if (s.axis == 0) ux = 1, uy = 0;
    else if (s.axis == 1) ux = 0, uy = 1;
    else compass_direction(s.angle, ux, uy);
    return true;
}

// The half-plane (or slab) p·u in [lo, hi] of the view, as a path; `far` is beyond the view.
void band_path(cairo_t* cr, const Mapping& m, double ux, double uy, double lo, double hi, double far) {
    const double tx = uy, ty = -ux;  // along the surface
    const auto corner = [&](double s, double t) {
        return std::pair{m.px(s * ux + t * tx), m.py(s * uy + t * ty)};
    };
    const auto [x0, y0] = corner(lo, -far);
    const auto [x1, y1] = corner(lo, far);
    const auto [x2, y2] = corner(hi, far);
    const auto [x3, y3] = corner(hi, -far);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_line_to(cr, x2, y2);
    cairo_line_to(cr, x3, y3);
    cairo_close_path(cr);
}

void line_path(cairo_t* cr, const Mapping& m, double ux, double uy, double at, double far) {
    const double tx = uy, ty = -ux;
    cairo_move_to(cr, m.px(at * ux - far * tx), m.py(at * uy - far * ty));
    cairo_line_to(cr, m.px(at * ux + far * tx), m.py(at * uy + far * ty));
}

void draw_surfaces(cairo_t* cr, const Trace& trace, const Mapping& m, double far) {
    for (const SurfaceMark& s : trace.surfaces) {
        double ux = 0, uy = 0;
        if (!plane_direction(s, ux, uy)) continue;
        if (s.barrier) {
            band_path(cr, m, ux, uy, s.at - s.thickness / 2, s.at + s.thickness / 2, far);
            set_color(cr, kBarrierColor, 0.18);
            cairo_fill(cr);
            set_color(cr, kBarrierColor, 0.9);
            cairo_set_line_width(cr, 1.2);
            line_path(cr, m, ux, uy, s.at - s.thickness / 2, far);
            line_path(cr, m, ux, uy, s.at + s.thickness / 2, far);
            cairo_stroke(cr);
        } else {
            band_path(cr, m, ux, uy, s.at, s.solid_above ? s.at + far : s.at - far, far);
            set_color(cr, kWallColor, 0.07);
            cairo_fill(cr);
            set_color(cr, kWallColor);
            cairo_set_line_width(cr, 2);
            line_path(cr, m, ux, uy, s.at, far);
            cairo_stroke(cr);
        }
    }
}

void draw_path(cairo_t* cr, const Trace& trace, const Mapping& m, float (TraceRow::*column)[kMaxAxes], double width) {
    cairo_new_path(cr);
    bool first = true;
    double last_x = 0, last_y = 0;
    for (const TraceRow& row : trace.rows) {
        const double x = m.px((row.*column)[0]), y = m.py((row.*column)[1]);
        // Points closer than a fifth of a unit of the page add nothing to the line.
        if (!first && std::hypot(x - last_x, y - last_y) < 0.2) continue;
        if (first) cairo_move_to(cr, x, y);
        else cairo_line_to(cr, x, y);
        first = false;
        last_x = x, last_y = y;
    }
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_width(cr, width);
    cairo_stroke(cr);
}

void draw_arrow(cairo_t* cr, double x0, double y0, double x1, double y1) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    if (len < 1) return;
    const double dx = (x1 - x0) / len, dy = (y1 - y0) / len;
    const double head = std::min(9.0, 0.45 * len);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1 - dx * head * 0.8, y1 - dy * head * 0.8);
    cairo_stroke(cr);
    cairo_move_to(cr, x1, y1);
    cairo_line_to(cr, x1 - dx * head - dy * head * 0.45, y1 - dy * head + dx * head * 0.45);
    cairo_line_to(cr, x1 - dx * head + dy * head * 0.45, y1 - dy * head - dx * head * 0.45);
    cairo_close_path(cr);
    cairo_fill(cr);
}

// The force at evenly spaced ticks, from the handle, 10000 = kArrowFullScale of the span.
void draw_forces(cairo_t* cr, const Trace& trace, const Mapping& m, double span) {
    const size_t n = trace.rows.size();
    const size_t step = std::max<size_t>(1, static_cast<size_t>(std::ceil(static_cast<double>(n) / kArrowCount)));
    const double per_unit = kArrowFullScale * span / kFullScale;  // position units per force unit
    set_color(cr, kForceColor, 0.9);
    cairo_set_line_width(cr, 1.6);
    for (size_t i = 0; i < n; i += step) {
        const TraceRow& row = trace.rows[i];
        const double fx = row.force[0], fy = row.force[1];
        if (std::hypot(fx, fy) < kArrowThreshold) continue;
        const double x = row.position[0], y = row.position[1];
        draw_arrow(cr, m.px(x), m.py(y), m.px(x + fx * per_unit), m.py(y + fy * per_unit));
    }
}

void draw_axes(cairo_t* cr, const Mapping& m) {
    const Rect& r = m.area;
    cairo_rectangle(cr, r.x, r.y, r.w, r.h);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill(cr);
    set_color(cr, kGrid);
    cairo_set_line_width(cr, 1);
    for (double v : m.xs.ticks()) {
        cairo_move_to(cr, std::round(m.px(v)) + 0.5, r.y);
        cairo_line_to(cr, std::round(m.px(v)) + 0.5, r.y + r.h);
    }
    for (double v : m.ys.ticks()) {
        cairo_move_to(cr, r.x, std::round(m.py(v)) + 0.5);
        cairo_line_to(cr, r.x + r.w, std::round(m.py(v)) + 0.5);
    }
    cairo_stroke(cr);
    set_color(cr, kMuted, 0.8);  // the center of travel
    cairo_move_to(cr, std::round(m.px(0)) + 0.5, r.y);
    cairo_line_to(cr, std::round(m.px(0)) + 0.5, r.y + r.h);
    cairo_move_to(cr, r.x, std::round(m.py(0)) + 0.5);
    cairo_line_to(cr, r.x + r.w, std::round(m.py(0)) + 0.5);
    cairo_stroke(cr);
}

void draw_ticks(cairo_t* cr, const Mapping& m) {
    const Rect& r = m.area;
    set_color(cr, kInk);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, std::round(r.x) + 0.5, std::round(r.y) + 0.5, std::round(r.w), std::round(r.h));
    cairo_stroke(cr);
    set_font(cr, 12.5);
    cairo_set_line_width(cr, 1);
    for (double v : m.xs.ticks()) {
        const double x = std::round(m.px(v)) + 0.5;
        cairo_move_to(cr, x, r.y + r.h);
        cairo_line_to(cr, x, r.y + r.h + 5);
        cairo_stroke(cr);
        draw_text(cr, tick_label(v, m.xs.step), x, r.y + r.h + 17, Align::center);
    }
    for (double v : m.ys.ticks()) {
        const double y = std::round(m.py(v)) + 0.5;
        cairo_move_to(cr, r.x - 5, y);
        cairo_line_to(cr, r.x, y);
        cairo_stroke(cr);
        draw_text(cr, tick_label(v, m.ys.step), r.x - 9, y, Align::end);
    }
    set_font(cr, 14);
    draw_text(cr, "x position (\u00b110000 = end of travel; + right)", r.x + r.w / 2, r.y + r.h + 44, Align::center);
    cairo_save(cr);
    cairo_translate(cr, 24, r.y + r.h / 2);
    cairo_rotate(cr, -std::numbers::pi / 2);
    draw_text(cr, "y position (\u00b110000 = end of travel; + forward)", 0, 0, Align::center);
    cairo_restore(cr);
}

// A number as the notes show it: whole units, or as given when it is short.
std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, std::fabs(v) >= 100 ? "%.0f" : "%g", v);
    return buf;
}

// " (y = −3000)" for an angle element at an axis angle, else "".
std::string axis_angle_place(const SurfaceMark& s) {
    if (s.angle % 9000 != 0) return "";
    double ux = 0, uy = 0;
    compass_direction(s.angle, ux, uy);
    return std::string(ux != 0 ? " (x = " : " (y = ") + number((ux + uy) * s.at) + ")";
}

void draw(cairo_t* cr, const Trace& trace, const std::string& title) {
    cairo_set_source_rgb(cr, 0.975, 0.975, 0.98);
    cairo_paint(cr);

    const Scale scale = nice_scale(-view_half_width(trace), view_half_width(trace), 6, 10);
    const Mapping m{{kLeft, kTop, kSide, kSide}, scale, scale};
    const double span = scale.hi - scale.lo;
    const double far = 4 * span;  // surface lines reach well beyond the view, then are clipped

    set_font(cr, 19, true);
    set_color(cr, kInk);
    draw_text(cr, title, kLeft, 26, Align::start);
    set_font(cr, 13);
    set_color(cr, kMuted);
    const std::string seen = trace.axis_count > 2 ? "the x-y plane seen from above (other axes not shown)"
                                                  : "the x-y plane seen from above";
    draw_text(cr, seen + ", " + std::to_string(trace.rows.size()) + " ticks at " + number(trace.rate_hz) + " Hz",
              kLeft, 52, Align::start);

    draw_axes(cr, m);
    const bool reported = std::any_of(trace.surfaces.begin(), trace.surfaces.end(),
                                      [](const SurfaceMark& s) { return !s.barrier && s.clipping; });
    cairo_save(cr);
    cairo_rectangle(cr, m.area.x, m.area.y, m.area.w, m.area.h);
    cairo_clip(cr);
    draw_surfaces(cr, trace, m, far);
    if (trace.has_hand) {  // solid: the dashes of a path the hand goes round twice would fill each other's gaps
        set_color(cr, kTargetColor, 0.8);
        draw_path(cr, trace, m, &TraceRow::target, 1.4);
    }
    set_color(cr, kAxisColors[0]);
    draw_path(cr, trace, m, &TraceRow::position, 1.8);
    if (reported) {  // sparse dots over the handle, which shows between them
        set_color(cr, kAxisColors[1]);
        const double sparse_dots[] = {kReportedDash[0], 3 * kReportedDash[1]};
        cairo_set_dash(cr, sparse_dots, 2, 0);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        draw_path(cr, trace, m, &TraceRow::reported, 2.4);
        cairo_set_dash(cr, nullptr, 0, 0);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    }
    draw_forces(cr, trace, m, span);
    const TraceRow& start = trace.rows.front();
    set_color(cr, kInk);
    cairo_arc(cr, m.px(start.position[0]), m.py(start.position[1]), 4.5, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
    cairo_restore(cr);
    draw_ticks(cr, m);

    // The legend, and what the surfaces are, in the column right of the plot.
    std::vector<LegendEntry> entries{{"handle", kAxisColors[0]}};
    if (trace.has_hand) entries.push_back({"hand target", kTargetColor, LegendEntry::Mark::line, 0.8});
    if (reported) entries.push_back({"reported position", kAxisColors[1], LegendEntry::Mark::dotted});
    entries.push_back({"force (10000 = " + number(kArrowFullScale * span) + " units long)", kForceColor,
                       LegendEntry::Mark::arrow});
    std::vector<std::string> notes;
    for (const SurfaceMark& s : trace.surfaces) {
        double ux = 0, uy = 0;
        if (!plane_direction(s, ux, uy)) continue;
        const std::string where = s.axis == 0   ? "x = " + number(s.at)
                                  : s.axis == 1 ? "y = " + number(s.at)
                                                : "at " + number(s.at) + " along compass " + number(s.angle / 100.0) + "\u00b0" +
                                                      axis_angle_place(s);
        if (s.barrier) {
            notes.push_back("barrier " + where);
            notes.push_back("    faces \u00b1" + number(s.thickness / 2) + " from its center");
        } else {
            const std::string axis = s.axis == 0 ? "x" : "y";
            const std::string solid =
                s.axis >= 0 ? "solid where " + axis + (s.solid_above ? " > " : " < ") + number(s.at)
                            : "solid toward compass " + number(((s.angle + (s.solid_above ? 0 : 18000)) % 36000) / 100.0) + "\u00b0";
            notes.push_back("wall " + where);
            notes.push_back("    " + solid + (s.clipping ? ", clipping" : "") + (s.relative ? ", relative" : ""));
        }
    }
    if (std::any_of(trace.surfaces.begin(), trace.surfaces.end(), [](const SurfaceMark& s) { return !s.barrier; })) {
        entries.push_back({"wall (solid side shaded)", kWallColor});
    }
    if (std::any_of(trace.surfaces.begin(), trace.surfaces.end(), [](const SurfaceMark& s) { return s.barrier; })) {
        entries.push_back({"barrier", kBarrierColor, LegendEntry::Mark::band, 0.35});
    }
    const double column_x = kLeft + kSide + kGutter;
    const double column_w = kWidth - column_x - 16;
    const double legend_h = draw_legend(cr, column_x + column_w, kTop, column_w, entries);
    set_font(cr, 12.5);
    double y = kTop + legend_h + 22;
    set_color(cr, kInk);
    draw_text(cr, "\u25cf start of the path", column_x + 4, y, Align::start);
    for (const std::string& note : notes) {
        y += note.rfind("    ", 0) == 0 ? 17 : 23;
        draw_text(cr, note, column_x + 4, y, Align::start);
    }
}

}  // namespace

void write_xy_plot(const Trace& trace, const std::string& title, const std::string& path) {
    const std::string ext = plot_extension(path, "--plot-xy");
    if (trace.rows.empty() || trace.axis_count > kMaxAxes) {
        throw std::invalid_argument("cannot plot " + path + ": the trace has no rows");
    }
    if (trace.axis_count < 2) {
        throw std::invalid_argument("--plot-xy needs a 2-axis device; the trace has " +
                                    std::to_string(trace.axis_count) + " axis");
    }
    write_plot_file(path, ext, kWidth, kHeight, [&](cairo_t* cr) { draw(cr, trace, title); });
}

}  // namespace feel::render
