// The report printed after a render: what was rendered, and what the hand would feel.
#include "render_summary.hpp"

#include <cstdio>
#include <ostream>
#include <string>

#include "feel/effect_type.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"

namespace feel::cli {
namespace {

std::string printf_string(const char* fmt, auto... args) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}

std::string kind_of(const format::Sensation& s) {
    if (s.compound) return "compound of " + std::to_string(s.effects.size());
    if (s.effects.empty()) return "empty";
    return std::string(effect_type_name(s.effects.front().params.type));
}

// Forces below this print as 0.0, so their "time of peak" would only time rounding noise.
constexpr double kShownAsZero = 0.05;

}  // namespace

std::string format_seconds(double seconds) {
    if (seconds < 2.0) return printf_string("%.4g ms", seconds * 1e3);
    return printf_string("%.4g s", seconds);
}

std::string plot_title(const std::string& sensation, const render::RenderOptions& options) {
    return sensation + " \u2014 " + std::string(options.profile->name) + ", " +
           std::string(sim::grip_name(options.grip)) + " hand, motion " + options.motion;
}

// The dynamics' reports (§5.2): how many interim reports the host would have received, and
// the final position and velocity of every mass that ended by itself.
void write_dynamic_reports(const render::Trace& trace, std::ostream& out) {
    out << '\n' << "dynamics   " << trace.interim_reports << " interim reports, "
        << trace.final_reports.size() << (trace.final_reports.size() == 1 ? " final report\n" : " final reports\n");
    for (const DynamicReport& f : trace.final_reports) {
        out << "final      at " << format_seconds(static_cast<double>(f.t_us) * 1e-6) << ": mass - handle position (";
        for (int i = 0; i < f.axis_count; ++i) out << (i ? ", " : "") << printf_string("%.1f", f.position[i]);
        out << "), velocity (";
        for (int i = 0; i < f.axis_count; ++i) out << (i ? ", " : "") << printf_string("%.1f", f.velocity[i]);
        out << ") units/s\n";
    }
}

// The presses of --press and the starts the reflexes made (§1.2.c): the first dozen times.
void write_reflex_starts(const render::Trace& trace, const render::RenderOptions& o, std::ostream& out) {
    constexpr size_t kShown = 12;
    out << '\n' << "presses    " << o.presses.size() << "; reflexes started effects "
        << trace.reflex_starts_us.size() << (trace.reflex_starts_us.size() == 1 ? " time" : " times");
    for (size_t i = 0; i < trace.reflex_starts_us.size() && i < kShown; ++i) {
        out << (i == 0 ? ": at " : ", ") << format_seconds(static_cast<double>(trace.reflex_starts_us[i]) * 1e-6);
    }
    if (trace.reflex_starts_us.size() > kShown) out << ", ...";
    out << '\n';
}

void write_render_summary(const RenderReport& r, std::ostream& out) {
    const render::TraceStats& st = r.stats;
    const render::RenderOptions& o = *r.options;
    out << "sensation  " << r.sensation->name << "  (" << kind_of(*r.sensation) << ", from "
        << r.file << ")\n";
    out << "device     " << o.profile->name << " (" << o.profile->axis_count
        << (o.profile->axis_count == 1 ? " axis" : " axes") << "), " << sim::grip_name(o.grip)
        << " hand, motion " << o.motion << '\n';
    out << "rendered   " << st.ticks << " ticks at " << printf_string("%g", o.rate_hz) << " Hz = "
        << format_seconds(st.duration_s) << "; force saturated on " << st.saturated_ticks
        << (st.saturated_ticks == 1 ? " tick\n" : " ticks\n");
    out << '\n';
    out << "axis   peak |force|      at time    RMS force      position min .. max\n";
    for (int a = 0; a < st.axis_count; ++a) {
        const render::AxisStats& s = st.axes[a];
        out << printf_string("%-4s %14.1f %12s %12.1f   %12.1f .. %.1f\n",
                             std::string(axis_name(static_cast<Axis>(a))).c_str(),
                             s.peak_abs_force,
                             s.peak_abs_force >= kShownAsZero
                                 ? format_seconds(static_cast<double>(s.peak_t_us) * 1e-6).c_str()
                                 : "-",
                             s.rms_force, s.min_position, s.max_position);
    }
    out << "(force and position are normalized: \u00b110000 is the motor limit and the end of "
           "travel)\n";
    if (r.trace != nullptr && r.trace->has_dynamics) write_dynamic_reports(*r.trace, out);
    if (r.trace != nullptr && (!o.presses.empty() || !r.trace->reflex_starts_us.empty())) {
        write_reflex_starts(*r.trace, o, out);
    }
    if (!r.csv_path.empty() || !r.plot_path.empty() || !r.plot_xy_path.empty()) out << '\n';
    if (!r.csv_path.empty()) out << "wrote      " << r.csv_path << " (CSV, " << st.ticks << " rows)\n";
    if (!r.plot_path.empty()) out << "wrote      " << r.plot_path << " (plot)\n";
    if (!r.plot_xy_path.empty()) out << "wrote      " << r.plot_xy_path << " (x-y plot)\n";
}

}  // namespace feel::cli
