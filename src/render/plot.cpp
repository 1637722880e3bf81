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
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "feel/render/render.hpp"
#include "plot_scale.hpp"

namespace feel::render {
namespace {

using detail::Scale;

constexpr double kWidth = 1100;
constexpr double kHeight = 720;
constexpr double kLeft = 96;      // room for the y tick labels and the rotated axis label
constexpr double kRight = 28;
constexpr double kTop = 64;       // the title
constexpr double kBottom = 62;    // x tick labels and the time label
constexpr double kPanelGap = 34;
constexpr const char* kFont = "DejaVu Sans";

struct Rgb {
    double r, g, b;
};
// One color per axis (x, y, z, rx, ry, rz), distinct for the common color-vision types.
constexpr Rgb kAxisColors[kMaxAxes] = {
    {0.122, 0.467, 0.706}, {0.839, 0.373, 0.000}, {0.173, 0.627, 0.173},
    {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761},
};
constexpr Rgb kInk{0.15, 0.15, 0.17};
constexpr Rgb kMuted{0.38, 0.38, 0.42};
constexpr Rgb kGrid{0.90, 0.90, 0.92};

struct Rect {
    double x, y, w, h;
};

using Column = float (TraceRow::*)[kMaxAxes];

struct PanelSpec {
    Column column;
    const char* label;           // the y axis label, saying what ±10000 means on this axis
    Column overlay = nullptr;    // drawn dashed underneath when the trace has dynamics
};

void set_color(cairo_t* cr, Rgb c, double alpha = 1) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

enum class Align { start, center, end };

// Draws `text` with its horizontal anchor at x and its vertical center at y.
void draw_text(cairo_t* cr, const std::string& text, double x, double y, Align align) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text.c_str(), &ext);
    double left = x - ext.x_bearing;
    if (align == Align::center) left -= ext.width / 2;
    if (align == Align::end) left -= ext.width;
    cairo_move_to(cr, left, y - (ext.y_bearing + ext.height / 2));
    cairo_show_text(cr, text.c_str());
}

void set_font(cairo_t* cr, double size, bool bold = false) {
    cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

// The value range of one column over the device's axes, with 0 always in view. Data
// within the normalized limits is never padded past them, so a force that touches the
// motor limit gives an axis that ends at ±10000 rather than at the next step beyond.
Scale value_scale(const Trace& trace, Column column, Column overlay = nullptr) {
    double lo = 0, hi = 0;
    for (const TraceRow& row : trace.rows) {
        for (int a = 0; a < trace.axis_count; ++a) {
            lo = std::min<double>(lo, (row.*column)[a]);
            hi = std::max<double>(hi, (row.*column)[a]);
            if (overlay != nullptr && row.has_mass) {
                lo = std::min<double>(lo, (row.*overlay)[a]);
                hi = std::max<double>(hi, (row.*overlay)[a]);
            }
        }
    }
    if (hi - lo < 1e-3) {  // a flat zero line: show a small symmetric range around it
        lo = -1;
        hi = 1;
    }
    const double limit = kFullScale;
    const double pad = 0.04 * (hi - lo);
    if (lo < 0) lo = lo >= -limit ? std::max(lo - pad, -limit) : lo - pad;
    if (hi > 0) hi = hi <= limit ? std::min(hi + pad, limit) : hi + pad;
    return detail::nice_scale(lo, hi, 4, 7);
}

// Data to device coordinates. The value range sits a few units inside the frame, so a
// force held at the motor limit draws as a visible line, not as part of the frame.
constexpr double kValueInset = 7;

struct Mapping {
    Rect area;
    Scale xs, ys;
    double px(double x) const { return area.x + (x - xs.lo) / (xs.hi - xs.lo) * area.w; }
    double py(double y) const {
        const double h = area.h - 2 * kValueInset;
        return area.y + kValueInset + h - (y - ys.lo) / (ys.hi - ys.lo) * h;
    }
};

void draw_series(cairo_t* cr, const Trace& trace, const Mapping& m, Column column, int axis,
                 double time_scale) {
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
    cairo_set_line_width(cr, 1.6);
    cairo_stroke(cr);
}

void draw_legend(cairo_t* cr, const Rect& area, int axis_count) {
    set_font(cr, 13);
    constexpr double kSwatch = 22, kGap = 6, kSpacing = 16, kPad = 8, kRowH = 22;
    double width = kPad;
    for (int a = 0; a < axis_count; ++a) {
        cairo_text_extents_t ext;
        cairo_text_extents(cr, std::string(axis_name(static_cast<Axis>(a))).c_str(), &ext);
        width += kSwatch + kGap + ext.x_advance + (a + 1 < axis_count ? kSpacing : 0);
    }
    width += kPad;
    const double x0 = area.x + area.w - width - 10;
    const double y0 = area.y + 10;
    cairo_rectangle(cr, x0, y0, width, kRowH);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.88);
    cairo_fill_preserve(cr);
    set_color(cr, kGrid);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);

    double x = x0 + kPad;
    const double y = y0 + kRowH / 2;
    for (int a = 0; a < axis_count; ++a) {
        const std::string name(axis_name(static_cast<Axis>(a)));
        set_color(cr, kAxisColors[a]);
        cairo_set_line_width(cr, 2.5);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + kSwatch, y);
        cairo_stroke(cr);
        set_color(cr, kInk);
        cairo_text_extents_t ext;
        cairo_text_extents(cr, name.c_str(), &ext);
        draw_text(cr, name, x + kSwatch + kGap, y, Align::start);
        x += kSwatch + kGap + ext.x_advance + kSpacing;
    }
}

void draw_panel(cairo_t* cr, const Trace& trace, const Mapping& m, const PanelSpec& spec,
                double time_scale, bool x_labels) {
    const Rect& r = m.area;
    // Background and grid.
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

    // Zero line, and the ±10000 limits (dashed) when they are in view: the axis label says
    // what they mean.
    cairo_save(cr);
    cairo_rectangle(cr, r.x, r.y, r.w, r.h);
    cairo_clip(cr);
    set_color(cr, kMuted, 0.8);
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

    // The data, clipped to the panel. A dynamic's simulated mass draws dashed over the
    // handle's position, in the same axis colors, where the mass exists.
    if (spec.overlay != nullptr && trace.has_dynamics) {
        const double mass_dashes[] = {4, 3};
        cairo_set_dash(cr, mass_dashes, 2, 0);
        for (int a = trace.axis_count - 1; a >= 0; --a) {
            set_color(cr, kAxisColors[a], 0.75);
            draw_series(cr, trace, m, spec.overlay, a, time_scale);
        }
        cairo_set_dash(cr, nullptr, 0, 0);
    }
    for (int a = trace.axis_count - 1; a >= 0; --a) {  // x on top
        set_color(cr, kAxisColors[a]);
        draw_series(cr, trace, m, spec.column, a, time_scale);
    }
    cairo_restore(cr);

    // Frame.
    set_color(cr, kInk);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, std::round(r.x) + 0.5, std::round(r.y) + 0.5, std::round(r.w), std::round(r.h));
    cairo_stroke(cr);

    // Tick marks and labels.
    set_font(cr, 12.5);
    cairo_set_line_width(cr, 1);
    for (double v : m.ys.ticks()) {
        const double y = std::round(m.py(v)) + 0.5;
        cairo_move_to(cr, r.x - 5, y);
        cairo_line_to(cr, r.x, y);
        cairo_stroke(cr);
        draw_text(cr, detail::tick_label(v, m.ys.step), r.x - 9, y, Align::end);
    }
    for (double t : m.xs.ticks()) {
        const double x = std::round(m.px(t)) + 0.5;
        cairo_move_to(cr, x, r.y + r.h);
        cairo_line_to(cr, x, r.y + r.h + 5);
        cairo_stroke(cr);
        if (x_labels) draw_text(cr, detail::tick_label(t, m.xs.step), x, r.y + r.h + 17, Align::center);
    }

    // The y axis label, rotated, centered on the panel.
    set_font(cr, 14);
    set_color(cr, kInk);
    cairo_save(cr);
    cairo_translate(cr, 24, r.y + r.h / 2);
    cairo_rotate(cr, -std::numbers::pi / 2);
    draw_text(cr, spec.label, 0, 0, Align::center);
    cairo_restore(cr);

    draw_legend(cr, r, trace.axis_count);
}

void draw(cairo_t* cr, const Trace& trace, const std::string& title) {
    cairo_set_source_rgb(cr, 0.975, 0.975, 0.98);
    cairo_paint(cr);

    const double t_end_s = static_cast<double>(trace.rows.back().t_us) * 1e-6;
    const bool in_ms = t_end_s < 2.0;
    const double time_scale = in_ms ? 1e-3 : 1e-6;  // µs -> display unit
    const Scale xs = detail::exact_scale(static_cast<double>(trace.rows.front().t_us) * time_scale,
                                         static_cast<double>(trace.rows.back().t_us) * time_scale, 10);

    const double panel_h = (kHeight - kTop - kBottom - kPanelGap) / 2;
    const double panel_w = kWidth - kLeft - kRight;
    const PanelSpec force{&TraceRow::force, "force (\u00b110000 = motor limit)"};
    const PanelSpec position{&TraceRow::position,
                             trace.has_dynamics ? "position; dashed: the simulated mass"
                                                : "position (\u00b110000 = end of travel)",
                             &TraceRow::mass_absolute};
    const Mapping top{{kLeft, kTop, panel_w, panel_h}, xs, value_scale(trace, force.column)};
    const Mapping bottom{{kLeft, kTop + panel_h + kPanelGap, panel_w, panel_h}, xs,
                         value_scale(trace, position.column, position.overlay)};

    set_font(cr, 19, true);
    set_color(cr, kInk);
    draw_text(cr, title, kLeft, kTop / 2 - 2, Align::start);
    set_font(cr, 12.5);
    set_color(cr, kMuted);
    char rate[64];
    std::snprintf(rate, sizeof rate, "%zu ticks at %g Hz", trace.rows.size(), trace.rate_hz);
    draw_text(cr, rate, kWidth - kRight, kTop / 2 - 2, Align::end);

    draw_panel(cr, trace, top, force, time_scale, false);
    draw_panel(cr, trace, bottom, position, time_scale, true);

    set_font(cr, 14);
    set_color(cr, kInk);
    draw_text(cr, in_ms ? "time (ms)" : "time (s)", kLeft + panel_w / 2, kHeight - 18, Align::center);
}

std::string lowercase_extension(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const noexcept { cairo_surface_destroy(s); }
};
struct ContextDeleter {
    void operator()(cairo_t* c) const noexcept { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

void check(cairo_status_t status, const std::string& path) {
    if (status != CAIRO_STATUS_SUCCESS) {
        throw std::runtime_error("cannot write plot " + path + ": " + cairo_status_to_string(status));
    }
}

}  // namespace

void write_plot(const Trace& trace, const std::string& title, const std::string& path) {
    const std::string ext = lowercase_extension(path);
    if (ext != ".svg" && ext != ".png") {
        throw std::invalid_argument("--plot " + path +
                                    ": unknown plot format (allowed extensions .svg, .png)");
    }
    if (trace.rows.empty() || trace.axis_count < 1 || trace.axis_count > kMaxAxes) {
        throw std::invalid_argument("cannot plot " + path + ": the trace has no rows or no axes");
    }

    Surface surface(ext == ".svg"
                        ? cairo_svg_surface_create(path.c_str(), kWidth, kHeight)
                        : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(kWidth),
                                                     static_cast<int>(kHeight)));
    check(cairo_surface_status(surface.get()), path);
    {
        Context cr(cairo_create(surface.get()));
        draw(cr.get(), trace, title);
        check(cairo_status(cr.get()), path);
    }
    if (ext == ".png") check(cairo_surface_write_to_png(surface.get(), path.c_str()), path);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), path);
}

}  // namespace feel::render
