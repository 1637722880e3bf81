// The human-readable report of `feel render`.
#pragma once

#include <iosfwd>
#include <string>

#include "feel/format/sensation_file.hpp"
#include "feel/render/render.hpp"
#include "feel/render/trace_stats.hpp"

namespace feel::cli {

struct RenderReport {
    std::string file;                                // the sensation file
    const format::Sensation* sensation = nullptr;
    const render::RenderOptions* options = nullptr;
    render::TraceStats stats{};
    std::string csv_path;                            // empty: the CSV went to stdout
    std::string plot_path;                           // empty: no plot
    std::string plot_xy_path;                        // empty: no x-y plot
    const render::Trace* trace = nullptr;            // for the dynamics' reports
};

void write_render_summary(const RenderReport& report, std::ostream& out);

// "railing_impact — joystick, firm hand, motion hold:0"
[[nodiscard]] std::string plot_title(const std::string& sensation,
                                     const render::RenderOptions& options);

// 0.35 -> "350 ms", 2.5 -> "2.5 s": ms below 2 s, where ms read more naturally.
[[nodiscard]] std::string format_seconds(double seconds);

}  // namespace feel::cli
