// Plots of a trace with cairo: force on top, position below, sharing the time axis.
//
// The same drawing code renders to an SVG surface (vector, for docs and the web) or to an
// image surface written as PNG. Layout is in device units (px for PNG, pt for SVG), fixed
// so that plots of different sensations line up when placed side by side.
//
// A long trace has far more ticks than the plot has pixel columns; drawing every point
// would make big files and a smeared line. When there are more than a few points per
// column, each column is drawn as the vertical span from its lowest to its highest
// value (in the order they occurred), which keeps every peak visible, exactly where it is.
//
// The position panel shows what a designer checks a wall or a barrier against: the handle
// (solid), where the hand wanted it (dashed), the position the device reports (dotted,
// when a clipping wall can make it differ from the handle's), a dynamic's mass
// (dash-dot), and each wall as a line at its surface with its solid side shaded, each
// barrier as the band between its faces. Elements at an angle other than an axis angle
// have no single coordinate to draw against time; the x-y plot (plot_xy.cpp) shows them.
#include <cairo.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "feel/render/render.hpp"
#include "plot_canvas.hpp"
#include "plot_scale.hpp"

namespace feel::render {
namespace {

using namespace detail;

constexpr double kWidth = 1100;
constexpr double kHeight = 720;
constexpr double kLeft = 96;      // room for the y tick labels and the rotated axis label
constexpr double kRight = 28;
constexpr double kTop = 64;       // the title
constexpr double kBottom = 62;    // x tick labels and the time label
constexpr double kPanelGap = 34;
// Data to device coordinates: the value range sits a few units inside the frame, so a
// force held at the motor limit draws as a visible line, not as part of the frame.
constexpr double kValueInset = 7;

using Column = float (TraceRow::*)[kMaxAxes];

// A wall or barrier as a value on one device axis: an axis element, or an angle element
// at an axis angle (u = ±x or ±y).
struct AxisSurface {
    int axis = -1;            // -1: at another angle, not drawn against time
    double at = 0;            // the wall's surface or the barrier's center, on that axis
    bool solid_above = true;  // a wall's solid side is at larger values of the axis
};

AxisSurface axis_surface(const SurfaceMark& m, int32_t axis_count) {
    if (m.axis >= 0) return m.axis < axis_count ? AxisSurface{m.axis, m.at, m.solid_above} : AxisSurface{};
    if (m.angle % 9000 != 0 || axis_count < 2) return {};
    double ux = 0, uy = 0;
    compass_direction(m.angle, ux, uy);
    const double sign = ux + uy;  // ±1: u is ±x or ±y
    return {ux != 0 ? 0 : 1, sign * m.at, sign > 0 ? m.solid_above : !m.solid_above};
}

std::string position_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return v < 0 ? "\u2212" + std::string(buf + 1) : std::string(buf);
}

bool has_clipping_wall(const Trace& trace) {
    for (const SurfaceMark& m : trace.surfaces) {
        if (!m.barrier && m.clipping) return true;
    }
    return false;
}

// The value range of some columns over the device's axes (and of `extra` values), with 0
// always in view. Data within the normalized limits is never padded past them, so a
// force that touches the motor limit gives an axis that ends at ±10000 rather than at the
// next step beyond.
Scale value_scale(const Trace& trace, const std::vector<Column>& columns, bool with_mass,
                  const std::vector<double>& extra = {}) {
    double lo = 0, hi = 0;
    for (const TraceRow& row : trace.rows) {
        for (int a = 0; a < trace.axis_count; ++a) {
            for (Column c : columns) {
                lo = std::min<double>(lo, (row.*c)[a]);
                hi = std::max<double>(hi, (row.*c)[a]);
            }
            if (with_mass && row.has_mass) {
                lo = std::min<double>(lo, row.mass_absolute[a]);
                hi = std::max<double>(hi, row.mass_absolute[a]);
            }
        }
    }
    for (double v : extra) lo = std::min(lo, v), hi = std::max(hi, v);
    if (hi - lo < 1e-3) {  // a flat zero line: show a small symmetric range around it
        lo = -1;
        hi = 1;
    }
    const double limit = kFullScale;
    const double pad = 0.04 * (hi - lo);
    if (lo < 0) lo = lo >= -limit ? std::max(lo - pad, -limit) : lo - pad;
    if (hi > 0) hi = hi <= limit ? std::min(hi + pad, limit) : hi + pad;
    return nice_scale(lo, hi, 4, 7);
}

void draw_series(cairo_t* cr, const Trace& trace, const Mapping& m, Column column, int axis,
                 double time_scale, double width = 1.6) {
    const size_t n = trace.rows.size();
    const auto t_of = [&](size_t i) { return static_cast<double>(trace.rows[i].t_us) * time_scale; };
    const auto v_of = [&](size_t i) { return static_cast<double>((trace.rows[i].*column)[axis]); };

    cairo_new_path(cr);
    if (n == 1) {  // a single tick: a dot
        cairo_arc(cr, m.px(t_of(0)), m.py(v_of(0)), 2.5, 0, 2 * std::numbers::pi);
        cairo_fill(cr);
        return;
    }
    if (static_cast<double>(n) <= 3 * m.area.w) {
        cairo_move_to(cr, m.px(t_of(0)), m.py(v_of(0)));
        for (size_t i = 1; i < n; ++i) cairo_line_to(cr, m.px(t_of(i)), m.py(v_of(i)));
    } else {
        bool started = false;
        size_t i = 0;
        while (i < n) {
            const double column_x = std::floor(m.px(t_of(i)));
            double lo = v_of(i), hi = lo;
            size_t lo_i = i, hi_i = i;
            size_t j = i + 1;
            for (; j < n && std::floor(m.px(t_of(j))) == column_x; ++j) {
                if (v_of(j) < lo) lo = v_of(j), lo_i = j;
                if (v_of(j) > hi) hi = v_of(j), hi_i = j;
            }
            const double first = lo_i <= hi_i ? lo : hi;
            const double second = lo_i <= hi_i ? hi : lo;
            if (started) cairo_line_to(cr, column_x + 0.5, m.py(first));
            else cairo_move_to(cr, column_x + 0.5, m.py(first)), started = true;
            cairo_line_to(cr, column_x + 0.5, m.py(second));
            i = j;
        }
    }
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_width(cr, width);
    cairo_stroke(cr);
}

// Each wall as a line at its surface with the solid side shaded, each barrier as a band
// between its faces, labelled with its axis and place. Clipped to the panel by the caller.
void draw_surfaces(cairo_t* cr, const Trace& trace, const Mapping& m) {
    const Rect& r = m.area;
    set_font(cr, 12);
    for (const SurfaceMark& mark : trace.surfaces) {
        const AxisSurface s = axis_surface(mark, trace.axis_count);
        if (s.axis < 0) continue;
        const std::string axis(axis_name(static_cast<Axis>(s.axis)));
        std::string label;
        double label_y = 0;
        if (mark.barrier) {
            const double top = m.py(s.at + mark.thickness / 2), bottom = m.py(s.at - mark.thickness / 2);
            set_color(cr, kBarrierColor, 0.16);
            cairo_rectangle(cr, r.x, top, r.w, std::max(bottom - top, 1.0));
            cairo_fill(cr);
            set_color(cr, kBarrierColor, 0.9);
            cairo_set_line_width(cr, 1.2);
            for (double y : {top, bottom}) {
                cairo_move_to(cr, r.x, y);
                cairo_line_to(cr, r.x + r.w, y);
            }
            cairo_stroke(cr);
            label = axis + " barrier " + position_text(s.at) + " \u00b1 " + position_text(mark.thickness / 2);
            label_y = top - 9;
        } else {
            const double y = m.py(s.at);
            set_color(cr, kWallColor, 0.07);  // the solid side
            cairo_rectangle(cr, r.x, s.solid_above ? r.y : y, r.w, s.solid_above ? y - r.y : r.y + r.h - y);
            cairo_fill(cr);
            set_color(cr, kWallColor);
            cairo_set_line_width(cr, 2);
            cairo_move_to(cr, r.x, y);
            cairo_line_to(cr, r.x + r.w, y);
            cairo_stroke(cr);
            label = axis + " wall " + position_text(s.at) + (s.solid_above ? ", solid above" : ", solid below") +
                    (mark.clipping ? ", clipping" : "") + (mark.relative ? " (relative)" : "");
            label_y = s.solid_above ? y - 10 : y + 10;
        }
        set_color(cr, mark.barrier ? kBarrierColor : kWallColor);
        draw_text(cr, label, r.x + 8, label_y, Align::start);
    }
}

void draw_frame_and_grid(cairo_t* cr, const Mapping& m) {
    const Rect& r = m.area;
    cairo_rectangle(cr, r.x, r.y, r.w, r.h);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill(cr);
    cairo_set_line_width(cr, 1);
    set_color(cr, kGrid);
    for (double t : m.xs.ticks()) {
        const double x = std::round(m.px(t)) + 0.5;
        cairo_move_to(cr, x, r.y);
        cairo_line_to(cr, x, r.y + r.h);
    }
    for (double v : m.ys.ticks()) {
        const double y = std::round(m.py(v)) + 0.5;
        cairo_move_to(cr, r.x, y);
        cairo_line_to(cr, r.x + r.w, y);
    }
    cairo_stroke(cr);
}

void draw_ticks(cairo_t* cr, const Mapping& m, bool x_labels, const std::string& y_label) {
    const Rect& r = m.area;
    set_color(cr, kInk);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, std::round(r.x) + 0.5, std::round(r.y) + 0.5, std::round(r.w), std::round(r.h));
    cairo_stroke(cr);
    set_font(cr, 12.5);
    cairo_set_line_width(cr, 1);
    for (double v : m.ys.ticks()) {
        const double y = std::round(m.py(v)) + 0.5;
        cairo_move_to(cr, r.x - 5, y);
        cairo_line_to(cr, r.x, y);
        cairo_stroke(cr);
        draw_text(cr, tick_label(v, m.ys.step), r.x - 9, y, Align::end);
    }
    for (double t : m.xs.ticks()) {
        const double x = std::round(m.px(t)) + 0.5;
        cairo_move_to(cr, x, r.y + r.h);
        cairo_line_to(cr, x, r.y + r.h + 5);
        cairo_stroke(cr);
        if (x_labels) draw_text(cr, tick_label(t, m.xs.step), x, r.y + r.h + 17, Align::center);
    }
    // The y axis label, rotated, centered on the panel.
    set_font(cr, 14);
    cairo_save(cr);
    cairo_translate(cr, 24, r.y + r.h / 2);
    cairo_rotate(cr, -std::numbers::pi / 2);
    draw_text(cr, y_label, 0, 0, Align::center);
    cairo_restore(cr);
}

std::vector<LegendEntry> axis_entries(int32_t axis_count) {
    std::vector<LegendEntry> entries;
    for (int a = 0; a < axis_count; ++a) {
        entries.push_back({std::string(axis_name(static_cast<Axis>(a))), kAxisColors[a]});
    }
    return entries;
}

// The zero line, and the ±10000 limits (dashed) when they are in view: the axis label
// says what they mean.
void draw_reference_lines(cairo_t* cr, const Mapping& m) {
    const Rect& r = m.area;
    set_color(cr, kMuted, 0.8);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, r.x, std::round(m.py(0)) + 0.5);
    cairo_line_to(cr, r.x + r.w, std::round(m.py(0)) + 0.5);
    cairo_stroke(cr);
    const double dashes[] = {6, 4};
    cairo_set_dash(cr, dashes, 2, 0);
    set_color(cr, kMuted, 0.9);
    for (double limit : {double{kFullScale}, -double{kFullScale}}) {
        if (limit < m.ys.lo || limit > m.ys.hi) continue;
        const double y = std::round(m.py(limit)) + 0.5;
        cairo_move_to(cr, r.x, y);
        cairo_line_to(cr, r.x + r.w, y);
        cairo_stroke(cr);
    }
    cairo_set_dash(cr, nullptr, 0, 0);
}

void draw_force_panel(cairo_t* cr, const Trace& trace, const Mapping& m, double time_scale) {
    draw_frame_and_grid(cr, m);
    cairo_save(cr);
    cairo_rectangle(cr, m.area.x, m.area.y, m.area.w, m.area.h);
    cairo_clip(cr);
    draw_reference_lines(cr, m);
    for (int a = trace.axis_count - 1; a >= 0; --a) {  // x on top
        set_color(cr, kAxisColors[a]);
        draw_series(cr, trace, m, &TraceRow::force, a, time_scale);
    }
    cairo_restore(cr);
    draw_ticks(cr, m, false, "force (\u00b110000 = motor limit)");
    draw_legend(cr, m.area.x + m.area.w - 10, m.area.y + 10, m.area.w * 0.7, axis_entries(trace.axis_count));
}

void draw_position_panel(cairo_t* cr, const Trace& trace, const Mapping& m, double time_scale) {
    const bool reported = has_clipping_wall(trace);
    draw_frame_and_grid(cr, m);
    cairo_save(cr);
    cairo_rectangle(cr, m.area.x, m.area.y, m.area.w, m.area.h);
    cairo_clip(cr);
    draw_surfaces(cr, trace, m);
    draw_reference_lines(cr, m);
    const auto dashed = [&](Column column, const double* dashes, int count, double alpha, double width) {
        cairo_set_dash(cr, dashes, count, 0);
        for (int a = trace.axis_count - 1; a >= 0; --a) {
            set_color(cr, kAxisColors[a], alpha);
            draw_series(cr, trace, m, column, a, time_scale, width);
        }
        cairo_set_dash(cr, nullptr, 0, 0);
    };
    if (trace.has_hand) dashed(&TraceRow::target, kTargetDash, 2, 0.6, 1.3);
    if (trace.has_dynamics) dashed(&TraceRow::mass_absolute, kMassDash, 4, 0.75, 1.6);
    for (int a = trace.axis_count - 1; a >= 0; --a) {  // x on top
        set_color(cr, kAxisColors[a]);
        draw_series(cr, trace, m, &TraceRow::position, a, time_scale);
    }
    if (reported) {
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        for (int a = trace.axis_count - 1; a >= 0; --a) {
            set_color(cr, {kAxisColors[a].r * 0.45, kAxisColors[a].g * 0.45, kAxisColors[a].b * 0.45});
            cairo_set_dash(cr, kReportedDash, 2, 0);
            draw_series(cr, trace, m, &TraceRow::reported, a, time_scale, 2.2);
        }
        cairo_set_dash(cr, nullptr, 0, 0);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    }
    cairo_restore(cr);
    draw_ticks(cr, m, true, "position (\u00b110000 = end of travel)");

    std::vector<LegendEntry> entries = axis_entries(trace.axis_count);
    entries.push_back({"handle", kInk});
    if (trace.has_hand) entries.push_back({"hand target", kInk, LegendEntry::Mark::dashed, 0.6});
    if (reported) entries.push_back({"reported", kInk, LegendEntry::Mark::dotted});
    if (trace.has_dynamics) entries.push_back({"simulated mass", kInk, LegendEntry::Mark::dash_dot, 0.75});
    bool walls = false, barriers = false;
    for (const SurfaceMark& s : trace.surfaces) {
        if (axis_surface(s, trace.axis_count).axis < 0) continue;
        (s.barrier ? barriers : walls) = true;
    }
    if (walls) entries.push_back({"wall (solid side shaded)", kWallColor});
    if (barriers) entries.push_back({"barrier", kBarrierColor, LegendEntry::Mark::band, 0.35});
    draw_legend(cr, m.area.x + m.area.w - 10, m.area.y + 10, m.area.w * 0.7, entries);
}

void draw(cairo_t* cr, const Trace& trace, const std::string& title) {
    cairo_set_source_rgb(cr, 0.975, 0.975, 0.98);
    cairo_paint(cr);

    const double t_end_s = static_cast<double>(trace.rows.back().t_us) * 1e-6;
    const bool in_ms = t_end_s < 2.0;
    const double time_scale = in_ms ? 1e-3 : 1e-6;  // µs -> display unit
    const Scale xs = exact_scale(static_cast<double>(trace.rows.front().t_us) * time_scale,
                                 static_cast<double>(trace.rows.back().t_us) * time_scale, 10);

    const double panel_h = (kHeight - kTop - kBottom - kPanelGap) / 2;
    const double panel_w = kWidth - kLeft - kRight;
    std::vector<double> surfaces;  // the walls and barriers drawn stay in view
    for (const SurfaceMark& s : trace.surfaces) {
        const AxisSurface a = axis_surface(s, trace.axis_count);
        if (a.axis < 0) continue;
        surfaces.push_back(a.at - s.thickness / 2);
        surfaces.push_back(a.at + s.thickness / 2);
    }
    std::vector<Column> positions{&TraceRow::position};
    if (trace.has_hand) positions.push_back(&TraceRow::target);
    const Mapping top{{kLeft, kTop, panel_w, panel_h}, xs, value_scale(trace, {&TraceRow::force}, false), kValueInset};
    const Mapping bottom{{kLeft, kTop + panel_h + kPanelGap, panel_w, panel_h}, xs,
                         value_scale(trace, positions, trace.has_dynamics, surfaces), kValueInset};

    set_font(cr, 19, true);
    set_color(cr, kInk);
    draw_text(cr, title, kLeft, kTop / 2 - 2, Align::start);
    set_font(cr, 12.5);
    set_color(cr, kMuted);
    char rate[64];
    std::snprintf(rate, sizeof rate, "%zu ticks at %g Hz", trace.rows.size(), trace.rate_hz);
    draw_text(cr, rate, kWidth - kRight, kTop / 2 - 2, Align::end);

    draw_force_panel(cr, trace, top, time_scale);
    draw_position_panel(cr, trace, bottom, time_scale);

    set_font(cr, 14);
    set_color(cr, kInk);
    draw_text(cr, in_ms ? "time (ms)" : "time (s)", kLeft + panel_w / 2, kHeight - 18, Align::center);
}

}  // namespace

void write_plot(const Trace& trace, const std::string& title, const std::string& path) {
    const std::string ext = plot_extension(path, "--plot");
    if (trace.rows.empty() || trace.axis_count < 1 || trace.axis_count > kMaxAxes) {
        throw std::invalid_argument("cannot plot " + path + ": the trace has no rows or no axes");
    }
    write_plot_file(path, ext, kWidth, kHeight, [&](cairo_t* cr) { draw(cr, trace, title); });
}

}  // namespace feel::render
