// Peak, time of peak and RMS of the force on each axis, plus the handle's excursion.
#include "feel/render/trace_stats.hpp"

#include <algorithm>
#include <cmath>

namespace feel::render {

TraceStats summarize(const Trace& trace) noexcept {
    TraceStats stats;
    stats.axis_count = trace.axis_count;
    stats.ticks = static_cast<int64_t>(trace.rows.size());
    if (trace.rows.empty() || trace.rate_hz <= 0) return stats;
    stats.duration_s = static_cast<double>(stats.ticks) / trace.rate_hz;

    double sum_sq[kMaxAxes] = {};
    for (int a = 0; a < trace.axis_count; ++a) {
        stats.axes[a].min_position = trace.rows.front().position[a];
        stats.axes[a].max_position = trace.rows.front().position[a];
        stats.axes[a].peak_t_us = trace.rows.front().t_us;
    }
    for (const TraceRow& row : trace.rows) {
        if (row.saturated) ++stats.saturated_ticks;
        for (int a = 0; a < trace.axis_count; ++a) {
            AxisStats& s = stats.axes[a];
            const double f = row.force[a];
            if (std::fabs(f) > s.peak_abs_force) {
                s.peak_abs_force = std::fabs(f);
                s.peak_t_us = row.t_us;
            }
            sum_sq[a] += f * f;
            s.min_position = std::min<double>(s.min_position, row.position[a]);
            s.max_position = std::max<double>(s.max_position, row.position[a]);
        }
    }
    for (int a = 0; a < trace.axis_count; ++a) {
        stats.axes[a].rms_force = std::sqrt(sum_sq[a] / static_cast<double>(stats.ticks));
    }
    return stats;
}

}  // namespace feel::render
