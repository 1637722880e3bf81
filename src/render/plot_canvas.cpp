// The drawing helpers both plots share, and the file each is written to.
#include "plot_canvas.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace feel::render::detail {
namespace {

constexpr const char* kFont = "DejaVu Sans";

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

// The legend's sample of one entry, kSample wide, centered vertically on y.
constexpr double kSample = 26;

void draw_sample(cairo_t* cr, const LegendEntry& e, double x, double y) {
    cairo_save(cr);
    set_color(cr, e.color, e.alpha);
    switch (e.mark) {
        case LegendEntry::Mark::band:
            cairo_rectangle(cr, x, y - 6, kSample, 12);
            cairo_fill(cr);
            break;
        case LegendEntry::Mark::arrow:
            cairo_set_line_width(cr, 1.6);
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + kSample - 2, y);
            cairo_stroke(cr);
            cairo_move_to(cr, x + kSample, y);
            cairo_line_to(cr, x + kSample - 8, y - 4);
            cairo_line_to(cr, x + kSample - 8, y + 4);
            cairo_close_path(cr);
            cairo_fill(cr);
            break;
        default:
            if (e.mark == LegendEntry::Mark::dashed) cairo_set_dash(cr, kTargetDash, 2, 0);
            if (e.mark == LegendEntry::Mark::dash_dot) cairo_set_dash(cr, kMassDash, 4, 0);
            if (e.mark == LegendEntry::Mark::dotted) {
                cairo_set_dash(cr, kReportedDash, 2, 0);
                cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            }
            cairo_set_line_width(cr, e.mark == LegendEntry::Mark::dotted ? 2.2 : 2.5);
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + kSample, y);
            cairo_stroke(cr);
    }
    cairo_restore(cr);
}

}  // namespace

void set_color(cairo_t* cr, Rgb c, double alpha) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

void set_font(cairo_t* cr, double size, bool bold) {
    cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

void draw_text(cairo_t* cr, const std::string& text, double x, double y, Align align) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text.c_str(), &ext);
    double left = x - ext.x_bearing;
    if (align == Align::center) left -= ext.width / 2;
    if (align == Align::end) left -= ext.width;
    cairo_move_to(cr, left, y - (ext.y_bearing + ext.height / 2));
    cairo_show_text(cr, text.c_str());
}

double text_width(cairo_t* cr, const std::string& text) {
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text.c_str(), &ext);
    return ext.x_advance;
}

double draw_legend(cairo_t* cr, double right, double top, double max_width, const std::vector<LegendEntry>& entries) {
    set_font(cr, 12.5);
    constexpr double kGap = 6, kSpacing = 16, kPad = 8, kRowH = 21;
    // Lay the entries out in rows first, to size the box.
    std::vector<std::vector<size_t>> rows(1);
    std::vector<double> widths(1, 0);
    for (size_t i = 0; i < entries.size(); ++i) {
        const double w = kSample + kGap + text_width(cr, entries[i].label);
        double& row_w = widths.back();
        if (row_w > 0 && row_w + kSpacing + w > max_width - 2 * kPad) {
            rows.emplace_back();
            widths.push_back(0);
        }
        widths.back() += (widths.back() > 0 ? kSpacing : 0) + w;
        rows.back().push_back(i);
    }
    const double width = *std::max_element(widths.begin(), widths.end()) + 2 * kPad;
    const double height = static_cast<double>(rows.size()) * kRowH + 2 * (kPad - 4);
    const double x0 = right - width;
    cairo_rectangle(cr, x0, top, width, height);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
    cairo_fill_preserve(cr);
    set_color(cr, kGrid);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    for (size_t r = 0; r < rows.size(); ++r) {
        double x = x0 + kPad;
        const double y = top + kPad - 4 + (static_cast<double>(r) + 0.5) * kRowH;
        for (size_t i : rows[r]) {
            draw_sample(cr, entries[i], x, y);
            set_color(cr, kInk);
            draw_text(cr, entries[i].label, x + kSample + kGap, y, Align::start);
            x += kSample + kGap + text_width(cr, entries[i].label) + kSpacing;
        }
    }
    return height;
}

void compass_direction(int32_t angle, double& ux, double& uy) noexcept {
    switch (angle) {  // exact at the axis angles, as the engine's walls are
        case 0: ux = 0, uy = 1; return;
        case 9000: ux = 1, uy = 0; return;
        case 18000: ux = 0, uy = -1; return;
        case 27000: ux = -1, uy = 0; return;
        default: break;
    }
    const double a = angle * std::numbers::pi / 18000.0;
    ux = std::sin(a);
    uy = std::cos(a);
}

std::string plot_extension(const std::string& path, const std::string& flag) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    std::string ext;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) ext = path.substr(dot);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".svg" && ext != ".png") {
        throw std::invalid_argument(flag + " " + path + ": unknown plot format (allowed extensions .svg, .png)");
    }
    return ext;
}

void write_plot_file(const std::string& path, const std::string& extension, double width, double height,
                     const std::function<void(cairo_t*)>& draw) {
    Surface surface(extension == ".svg"
                        ? cairo_svg_surface_create(path.c_str(), width, height)
                        : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(width),
                                                     static_cast<int>(height)));
    check(cairo_surface_status(surface.get()), path);
    {
        Context cr(cairo_create(surface.get()));
        draw(cr.get());
        check(cairo_status(cr.get()), path);
    }
    if (extension == ".png") check(cairo_surface_write_to_png(surface.get(), path.c_str()), path);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), path);
}

}  // namespace feel::render::detail
