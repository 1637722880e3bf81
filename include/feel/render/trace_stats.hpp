// feel::render — summary statistics of a rendered trace, for the CLI's report.
#pragma once

#include <cstdint>

#include "feel/render/render.hpp"

namespace feel::render {

struct AxisStats {
    double peak_abs_force = 0;  // largest |force|, normalized 0..10000
    int64_t peak_t_us = 0;      // time of the first row reaching the peak, µs
    double rms_force = 0;       // sqrt(mean(force²)) over all rows, normalized
    double min_position = 0;    // normalized, ±10000 of travel (beyond in an end stop)
    double max_position = 0;
};

struct TraceStats {
    int32_t axis_count = 0;
    int64_t ticks = 0;
    int64_t saturated_ticks = 0;  // rows where the engine clamped the summed force
    double duration_s = 0;        // ticks / rate: the time the trace covers
    AxisStats axes[kMaxAxes] = {};
};

// An empty trace gives zero statistics.
[[nodiscard]] TraceStats summarize(const Trace& trace) noexcept;

}  // namespace feel::render
