// Parsing --motion specs into TargetMotion.
//
// Every error names the part of the spec that is wrong, the value found and the form or
// range allowed, prefixed with the spec itself ("--motion \"sine:x:1\": ..."), so the CLI
// can pass the message through unchanged. Nothing is clamped: a target outside the
// travel, a non-positive frequency or a csv row out of order is an error, because the
// render it would produce is not the one that was asked for.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/sim/hand.hpp"
#include "feel/units.hpp"

namespace feel::sim {
namespace {

constexpr std::string_view kForms =
    "hold:X[,Y[,Z]], ramp:AXIS:FROM:TO, sine:AXIS:AMPLITUDE:HZ, circle:RADIUS:HZ or csv:PATH";

std::string motion_number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string_view trim(std::string_view s) {
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (;;) {
        const size_t end = s.find(sep, start);
        parts.push_back(s.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

// A finite decimal number filling the whole token, or nullopt.
std::optional<double> to_number(std::string_view token) {
    token = trim(token);
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    if (token.empty()) return std::nullopt;
    double v = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(v)) {
        return std::nullopt;
    }
    return v;
}

}  // namespace

// Builds TargetMotions; a friend of TargetMotion so that it can fill the private fields.
class MotionParser {
public:
    MotionParser(std::string_view spec, int32_t axis_count)
        : spec_(spec), axis_count_(axis_count) {}

    TargetMotion parse(double duration_s) const {
        const size_t colon = spec_.find(':');
        const std::string_view kind = trim(spec_.substr(0, colon));
        const std::string_view args =
            colon == std::string_view::npos ? std::string_view{} : spec_.substr(colon + 1);
        const bool known = kind == "hold" || kind == "ramp" || kind == "sine" ||
                           kind == "circle" || kind == "csv";
        if (!known) {
            fail(kind.empty() ? "empty motion kind (allowed " + std::string(kForms) + ")"
                              : "unknown motion kind \"" + std::string(kind) + "\" (allowed " +
                                    std::string(kForms) + ")");
        }
        if (colon == std::string_view::npos) {
            fail(std::string(kind) + " needs arguments after a ':' (allowed " +
                 std::string(kForms) + ")");
        }
        TargetMotion m;
        m.spec_ = std::string(spec_);
        if (kind == "hold") return parse_hold(std::move(m), args);
        if (kind == "ramp") return parse_ramp(std::move(m), args, duration_s);
        if (kind == "sine") return parse_sine(std::move(m), args);
        if (kind == "circle") return parse_circle(std::move(m), args);
        return parse_csv(std::move(m), args);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::invalid_argument("--motion \"" + std::string(spec_) + "\": " + what);
    }

    std::string axis_list() const {
        std::string s;
        for (int i = 0; i < axis_count_; ++i) {
            if (i > 0) s += ", ";
            s += axis_name(static_cast<Axis>(i));
        }
        return s;
    }

    std::vector<std::string_view> arguments(std::string_view args, std::string_view kind,
                                            std::string_view form, size_t count) const {
        std::vector<std::string_view> parts = split(args, ':');
        if (parts.size() != count) {
            fail(std::string(kind) + " takes " + std::to_string(count) + " arguments (" +
                 std::string(form) + "), got " + std::to_string(parts.size()));
        }
        return parts;
    }

    double number(std::string_view token, std::string_view name) const {
        const std::optional<double> v = to_number(token);
        if (!v) {
            const std::string_view t = trim(token);
            fail(t.empty() ? std::string(name) + " is empty (expected a number)"
                           : std::string(name) + " \"" + std::string(t) +
                                 "\" is not a finite number");
        }
        return *v;
    }

    // A number in lo..hi (normalized position units).
    double level(std::string_view token, std::string_view name, double lo, double hi,
                 std::string_view what) const {
        const double v = number(token, name);
        if (v < lo || v > hi) {
            fail(std::string(name) + " = " + motion_number(v) + " is outside " +
                 std::string(what) + " (allowed " + motion_number(lo) + ".." +
                 motion_number(hi) + ")");
        }
        return v;
    }

    double position(std::string_view token, std::string_view name) const {
        return level(token, name, -kFullScale, kFullScale, "the travel");
    }

    double hz(std::string_view token) const {
        const double v = number(token, "HZ");
        if (!(v > 0) || v > kMaxMotionHz) {
            fail("HZ = " + motion_number(v) + " is out of range (allowed 0 < HZ <= " +
                 motion_number(kMaxMotionHz) + ")");
        }
        return v;
    }

    int axis(std::string_view token) const {
        const std::string_view name = trim(token);
        const std::optional<Axis> a = axis_from_name(name);
        if (!a || axis_index(*a) >= axis_count_) {
            fail("AXIS \"" + std::string(name) + "\" is not an axis of this " +
                 std::to_string(axis_count_) + "-axis device (allowed " + axis_list() + ")");
        }
        return axis_index(*a);
    }

    TargetMotion parse_hold(TargetMotion m, std::string_view args) const {
        if (args.find(':') != std::string_view::npos) {
            fail("hold takes its positions separated by commas (hold:X[,Y[,Z]])");
        }
        const std::vector<std::string_view> parts = split(args, ',');
        if (parts.size() > static_cast<size_t>(axis_count_)) {
            fail("hold takes 1 to " + std::to_string(axis_count_) +
                 " positions (one per axis: " + axis_list() + "), got " +
                 std::to_string(parts.size()));
        }
        m.kind_ = TargetMotion::Kind::hold;
        for (size_t i = 0; i < parts.size(); ++i) {
            const std::string name =
                "position of " + std::string(axis_name(static_cast<Axis>(i)));
            m.hold_[i] = position(parts[i], name);
        }
        m.used_axes_ = static_cast<int32_t>(parts.size());
        return m;
    }

    TargetMotion parse_ramp(TargetMotion m, std::string_view args, double duration_s) const {
        const auto parts = arguments(args, "ramp", "ramp:AXIS:FROM:TO", 3);
        m.kind_ = TargetMotion::Kind::ramp;
        m.axis_ = axis(parts[0]);
        m.a_ = position(parts[1], "FROM");
        m.b_ = position(parts[2], "TO");
        if (!std::isfinite(duration_s) || !(duration_s > 0)) {
            fail("ramp runs over the render's duration, which must be finite and > 0 (got " +
                 motion_number(duration_s) + " s)");
        }
        m.duration_s_ = duration_s;
        m.used_axes_ = m.axis_ + 1;
        return m;
    }

    TargetMotion parse_sine(TargetMotion m, std::string_view args) const {
        const auto parts = arguments(args, "sine", "sine:AXIS:AMPLITUDE:HZ", 3);
        m.kind_ = TargetMotion::Kind::sine;
        m.axis_ = axis(parts[0]);
        m.a_ = position(parts[1], "AMPLITUDE");
        m.b_ = hz(parts[2]);
        m.used_axes_ = m.axis_ + 1;
        return m;
    }

    TargetMotion parse_circle(TargetMotion m, std::string_view args) const {
        const auto parts = arguments(args, "circle", "circle:RADIUS:HZ", 2);
        if (axis_count_ < 2) {
            fail("circle moves x and y, but this device has only axis x (use sine:x:...)");
        }
        m.kind_ = TargetMotion::Kind::circle;
        m.a_ = level(parts[0], "RADIUS", 0, kFullScale, "the travel");
        m.b_ = hz(parts[1]);
        m.used_axes_ = 2;
        return m;
    }

    TargetMotion parse_csv(TargetMotion m, std::string_view args) const {
        const std::string path(trim(args));
        if (path.empty()) fail("csv needs a file path (csv:PATH)");
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) {
            fail("csv file \"" + path + "\" is a directory (expected a file of rows " +
                 "\"t_us,x[,y[,z...]]\")");
        }
        std::ifstream in(path);
        if (!in) {
            fail("csv file \"" + path + "\" cannot be opened (" + std::strerror(errno) + ")");
        }
        m.kind_ = TargetMotion::Kind::table;
        const std::string form = "\"t_us,x[,y[,z...]]\"";
        std::string line;
        int line_no = 0;
        bool seen_first = false;
        while (std::getline(in, line)) {
            ++line_no;
            const std::string_view text = trim(line);
            if (text.empty() || text.front() == '#') continue;
            const std::string where = "csv file \"" + path + "\" line " + std::to_string(line_no);
            const std::vector<std::string_view> fields = split(text, ',');
            if (!seen_first && trim(fields[0]) == "t_us") {  // the header
                seen_first = true;
                continue;
            }
            seen_first = true;
            const size_t positions = fields.size() - 1;
            if (positions < 1 || positions > static_cast<size_t>(axis_count_)) {
                fail(where + ": " + std::to_string(positions) + " positions (expected " + form +
                     ": a time and 1 to " + std::to_string(axis_count_) + " positions, one per "
                     "axis: " + axis_list() + ")");
            }
            if (m.table_axes_ == 0) m.table_axes_ = static_cast<int>(positions);
            if (positions != static_cast<size_t>(m.table_axes_)) {
                fail(where + ": " + std::to_string(positions) + " positions, but the first row "
                     "has " + std::to_string(m.table_axes_) + " (every row needs the same columns)");
            }
            const double t_us = number(fields[0], where + ": t_us");
            if (t_us < 0) {
                fail(where + ": t_us = " + motion_number(t_us) + " is negative (allowed >= 0)");
            }
            const double t_s = t_us * 1e-6;
            if (!m.table_t_.empty() && !(t_s > m.table_t_.back())) {
                fail(where + ": t_us = " + motion_number(t_us) + " is not after the previous "
                     "row's " + motion_number(m.table_t_.back() * 1e6) +
                     " (times must strictly increase)");
            }
            m.table_t_.push_back(t_s);
            for (size_t a = 1; a < fields.size(); ++a) {
                m.table_x_.push_back(position(
                    fields[a], where + ": " + std::string(axis_name(static_cast<Axis>(a - 1)))));
            }
        }
        if (in.bad()) fail("csv file \"" + path + "\" cannot be read");
        if (m.table_t_.empty()) {
            fail("csv file \"" + path + "\" has no data rows (expected rows " + form + ")");
        }
        m.used_axes_ = m.table_axes_;
        return m;
    }

    std::string_view spec_;
    int32_t axis_count_;
};

TargetMotion TargetMotion::parse(std::string_view spec, double duration_s, int32_t axis_count) {
    if (axis_count < 1 || axis_count > kMaxAxes) {
        throw std::invalid_argument("--motion \"" + std::string(spec) + "\": axis_count = " +
                                    std::to_string(axis_count) + " is out of range (allowed 1.." +
                                    std::to_string(kMaxAxes) + ")");
    }
    return MotionParser(spec, axis_count).parse(duration_s);
}

}  // namespace feel::sim
