// feel render: one sensation, one device, one hand, in closed loop.
//
// Everything that can be checked without doing the work is checked first (names, the plot
// format), so that a typo never costs a long render. Output directories are created as
// needed, so `-o out/x.csv` works in a fresh checkout.
#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/render/render.hpp"
#include "feel/render/trace_stats.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "render_summary.hpp"
#include "sensation_choice.hpp"

namespace feel::cli {
namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// A profile name, or sim:PROFILE as the host commands spell a simulated device.
const sim::DeviceProfile& device_by_name(const std::string& name) {
    const std::string profile = name.rfind("sim:", 0) == 0 ? name.substr(4) : name;
    if (const sim::DeviceProfile* p = sim::find_device_profile(profile)) return *p;
    std::string names;
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        names += names.empty() ? "" : ", ";
        names += p.name;
    }
    throw UsageError("--device " + quoted(name) + " is not a simulated device render can run (available: " +
                     names + ", each also as sim:PROFILE)");
}

sim::Grip grip_by_name(const std::string& name) {
    if (const auto g = sim::grip_from_name(name)) return *g;
    std::string names;
    for (sim::Grip g : {sim::Grip::none, sim::Grip::loose, sim::Grip::firm, sim::Grip::stiff,
                        sim::Grip::kinematic}) {
        names += names.empty() ? "" : ", ";
        names += sim::grip_name(g);
    }
    throw UsageError("--hand " + quoted(name) + " is not a hand (allowed: " + names + ")");
}

void check_plot_path(const std::string& flag, const std::string& path) {
    if (path.empty()) return;
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".svg" && ext != ".png") {
        throw UsageError(flag + " " + quoted(path) + " has an unknown format (allowed extensions .svg, .png)");
    }
}

void make_parent_directory(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (parent.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec) throw std::runtime_error("cannot create directory " + parent.string() + ": " + ec.message());
}

void write_csv_file(const render::Trace& trace, const std::string& path) {
    make_parent_directory(path);
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    render::write_csv(trace, file);
    file.close();
    if (!file) throw std::runtime_error("error while writing " + path);
}

}  // namespace

void run_render(const RenderArgs& args, std::ostream& out, std::ostream& err) {
    render::RenderOptions options;
    options.profile = &device_by_name(args.device);
    options.grip = grip_by_name(args.hand);
    options.motion = args.motion;
    options.rate_hz = args.rate_hz;
    if (args.duration_s) {
        // 0 means "the sensation's length" to the library; on the command line that is
        // spelled by leaving the flag out, so an explicit value must be positive.
        if (!(*args.duration_s > 0)) {
            throw UsageError("--duration " + number(*args.duration_s) +
                             " s is out of range (allowed 0 < duration <= 600 s; leave it out "
                             "for the sensation's own length)");
        }
        options.duration_s = *args.duration_s;
    }
    check_plot_path("--plot", args.plot);
    check_plot_path("--plot-xy", args.plot_xy);
    if (!args.plot_xy.empty() && options.profile->axis_count < 2) {
        throw UsageError("--plot-xy needs a 2-axis device; " + std::string(options.profile->name) + " has " +
                         std::to_string(options.profile->axis_count) + " axis (--plot draws it against time)");
    }
    if (args.output.empty() && args.plot.empty() && args.plot_xy.empty()) {
        throw UsageError("--output: an output path is required (or - for stdout), unless --plot or --plot-xy is given");
    }
    try {
        options.presses = render::parse_presses(args.press);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }

    const format::SensationFile file = format::load_sensation_file(args.file);
    const format::Sensation& sensation = choose_sensation(file, args.sensation, args.file);

    const render::Trace trace = render::render(sensation, options);

    const bool csv_to_stdout = args.output == "-";
    std::ostream& report = csv_to_stdout ? err : out;
    if (csv_to_stdout) {
        render::write_csv(trace, out);
        if (!out) throw std::runtime_error("error while writing the CSV to standard output");
    } else if (!args.output.empty()) {
        write_csv_file(trace, args.output);
    }
    if (!args.plot.empty()) {
        make_parent_directory(args.plot);
        render::write_plot(trace, plot_title(sensation.name, options), args.plot);
    }
    if (!args.plot_xy.empty()) {
        make_parent_directory(args.plot_xy);
        render::write_xy_plot(trace, plot_title(sensation.name, options), args.plot_xy);
    }

    RenderReport r;
    r.file = args.file;
    r.sensation = &sensation;
    r.options = &options;
    r.stats = render::summarize(trace);
    r.csv_path = csv_to_stdout ? "" : args.output;
    r.plot_path = args.plot;
    r.plot_xy_path = args.plot_xy;
    r.trace = &trace;
    write_render_summary(r, report);
}

}  // namespace feel::cli
