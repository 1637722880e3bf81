// The trace as CSV: one header line, then one line per tick.
//
// Floats are written with std::to_chars in their shortest round-trip form, so reading
// the CSV back gives the exact floats the engine produced (and "0" stays "0", which keeps
// the files small).
#include <charconv>
#include <ostream>
#include <string>

#include "feel/render/render.hpp"

namespace feel::render {
namespace {

void append(std::string& line, float v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    line.append(buf, ec == std::errc{} ? end : buf);
}

void append(std::string& line, int64_t v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    line.append(buf, ec == std::errc{} ? end : buf);
}

void append_columns(std::string& line, const char* prefix, int32_t axis_count) {
    for (int a = 0; a < axis_count; ++a) {
        line += ',';
        line += prefix;
        line += axis_name(static_cast<Axis>(a));
    }
}

}  // namespace

void write_csv(const Trace& trace, std::ostream& out) {
    const int32_t axes = trace.axis_count;
    std::string line = "t_us";
    append_columns(line, "", axes);
    append_columns(line, "v", axes);
    append_columns(line, "f", axes);
    append_columns(line, "r", axes);
    if (trace.has_dynamics) {  // the simulated mass, relative to the handle (§5.2)
        append_columns(line, "m", axes);
        append_columns(line, "mv", axes);
    }
    line += '\n';
    out << line;

    for (const TraceRow& row : trace.rows) {
        line.clear();
        append(line, row.t_us);
        for (const float* column : {row.position, row.velocity, row.force, row.reported, row.mass_relative,
                                    row.mass_velocity}) {
            if (!trace.has_dynamics && column == row.mass_relative) break;
            for (int a = 0; a < axes; ++a) {
                line += ',';
                append(line, column[a]);
            }
        }
        line += '\n';
        out << line;
    }
    out.flush();
}

}  // namespace feel::render
