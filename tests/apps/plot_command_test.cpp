// feel render --plot and --plot-xy with walls and barriers: the lines lie where the file
// puts them, read back from the SVG the command writes; the CSV's reported position stops
// at a clipping wall as §3.7 says; a 1-axis device is refused for --plot-xy.
//
// The SVG is cairo's: each stroked line is a <path style="...stroke:rgb(R%,G%,B%)..."
// d="M x y L x y ..."/> in page units. The tests find the hand's target path (a circle of
// the --motion, so its extremes are ±RADIUS exactly: the independent ruler) and derive the
// page mapping from it; every other line is then checked in data units against the file.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "cli_fixture.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli::testing {
namespace {

constexpr double kRadius = 6000;  // --motion circle:6000:0.5, two seconds: one whole turn
constexpr int32_t kFloorAt = 4000;

// The plots' line colors, as cairo writes them (identification only).
constexpr const char* kWallStroke = "stroke:rgb(70%,9%,12%)";
constexpr const char* kBarrierStroke = "stroke:rgb(45%,20%,62%)";
constexpr const char* kTargetXyStroke = "stroke:rgb(42%,42%,46%)";
constexpr const char* kHandleXyStroke = "stroke:rgb(12.2%,46.7%,70.6%)";
constexpr const char* kReportedXyStroke = "stroke:rgb(83.9%,37.3%,0%)";
constexpr const char* kYAxisStroke = "stroke:rgb(83.9%,37.3%,0%)";
constexpr const char* kTargetDash = "stroke-dasharray:7,4";

struct Point {
    double x, y;
};
struct SvgPath {
    std::string style;
    std::vector<Point> points;  // the M and L points, in page units
};

// The value of attribute `name` in the element text, "" without it.
std::string attribute(const std::string& element, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const size_t start = element.find(key);
    if (start == std::string::npos) return "";
    const size_t from = start + key.size();
    return element.substr(from, element.find('"', from) - from);
}

std::vector<SvgPath> stroked_paths(const std::string& svg) {
    std::vector<SvgPath> out;
    for (size_t at = svg.find("<path "); at != std::string::npos; at = svg.find("<path ", at + 1)) {
        const std::string element = svg.substr(at, svg.find("/>", at) - at);
        SvgPath p;
        p.style = attribute(element, "style");
        if (p.style.empty() || p.style.find("stroke:none") != std::string::npos) continue;
        std::istringstream d(attribute(element, "d"));
        std::string op;
        while (d >> op) {
            if (op == "M" || op == "L") {
                Point pt{};
                d >> pt.x >> pt.y;
                p.points.push_back(pt);
            }
        }
        out.push_back(std::move(p));
    }
    return out;
}

std::vector<SvgPath> with_style(const std::vector<SvgPath>& paths, std::initializer_list<const char*> parts) {
    std::vector<SvgPath> out;
    for (const SvgPath& p : paths) {
        bool all = true;
        for (const char* part : parts) all = all && p.style.find(part) != std::string::npos;
        if (all) out.push_back(p);
    }
    return out;
}

struct Box {
    double x0 = std::numeric_limits<double>::max(), x1 = -x0, y0 = x0, y1 = -x0;
};
Box box_of(const std::vector<Point>& points) {
    Box b;
    for (const Point& p : points) {
        b.x0 = std::min(b.x0, p.x), b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y), b.y1 = std::max(b.y1, p.y);
    }
    return b;
}

// Page to data units, from a path known to span -r..r on both axes (y up the page).
struct Ruler {
    double cx, cy, per_unit_x, per_unit_y;
    [[nodiscard]] double x(double page_x) const { return (page_x - cx) / per_unit_x; }
    [[nodiscard]] double y(double page_y) const { return (cy - page_y) / per_unit_y; }
};
Ruler ruler_from_circle(const std::vector<Point>& circle, double r) {
    const Box b = box_of(circle);
    return {(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2, (b.x1 - b.x0) / (2 * r), (b.y1 - b.y0) / (2 * r)};
}

EffectParams endless(EffectType type, std::initializer_list<Axis> axes) {
    EffectParams p;
    p.type = type;
    p.duration_us = kInfiniteUs;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) p.axes[i++] = a;
    return p;
}

// floor: §8.2's HorizontalWall(10000, positive, 4000, clipping on), hard at y = 4000.
// far_corner: an angle_wall at compass 4500, 8000 out (beyond the circle) and a barrier
// across x at -2000, 600 thick, in one compound.
format::SensationFile wall_file() {
    EffectParams floor = endless(EffectType::axis_wall, {Axis::y});
    floor.wall.hardness = 10000;
    floor.wall.sense = WallSense::positive;
    floor.wall.offset = kFloorAt;
    floor.wall.clipping = true;
    EffectParams diagonal = endless(EffectType::angle_wall, {Axis::x, Axis::y});
    diagonal.wall.hardness = 5000;
    diagonal.wall.offset = 8000;
    diagonal.wall.angle = 4500;
    EffectParams slab = endless(EffectType::axis_barrier, {Axis::x});
    slab.barrier.pos_hardness = 3000;
    slab.barrier.neg_hardness = 3000;
    slab.barrier.thickness = 600;
    slab.barrier.offset = -2000;
    format::SensationFile file;
    file.sensations.push_back({"floor", std::nullopt, false, {{floor, {}, {}}}});
    file.sensations.push_back({"far_corner", std::nullopt, true, {{diagonal, {}, {}}, {slab, {}, {}}}});
    return file;
}

class Plots : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        file_ = path("walls.feel.json");
        write(file_, format::write_sensation_file(wall_file()));
    }
    Result render(const std::string& sensation, std::initializer_list<std::string> more) {
        std::vector<std::string> args{"render", file_, "--sensation", sensation, "--device", "joystick",
                                      "--hand",  "firm", "--motion",    "circle:6000:0.5", "--duration", "2"};
        args.insert(args.end(), more.begin(), more.end());
        std::vector<std::string> argv{"feel"};
        argv.insert(argv.end(), args.begin(), args.end());
        std::ostringstream out, err;
        Result r;
        r.code = run(argv, out, err);
        r.out = out.str();
        r.err = err.str();
        return r;
    }
    std::string file_;
};

// The x-y view: one scale on both axes (the target circle is round), the wall's line at
// y = 4000, the reported position up to the wall and no further, the handle a little in.
TEST_F(Plots, TheXyWallLineLiesWhereTheFileSaysAndTheReportedPathStopsThere) {
    const std::string svg = path("floor_xy.svg");
    const Result r = render("floor", {"--plot-xy", svg});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_NE(r.out.find("floor_xy.svg (x-y plot)"), std::string::npos) << r.out;
    const std::vector<SvgPath> paths = stroked_paths(read(svg));

    const auto target = with_style(paths, {kTargetXyStroke, "stroke-width:1.4;"});
    ASSERT_EQ(target.size(), 1u);
    const Ruler ruler = ruler_from_circle(target[0].points, kRadius);
    EXPECT_NEAR(ruler.per_unit_x, ruler.per_unit_y, 1e-4 * ruler.per_unit_x) << "one scale on both axes";

    const auto wall = with_style(paths, {kWallStroke, "stroke-width:2;"});
    ASSERT_EQ(wall.size(), 1u);
    ASSERT_EQ(wall[0].points.size(), 2u);
    for (const Point& p : wall[0].points) EXPECT_NEAR(ruler.y(p.y), kFloorAt, 1.0);
    const Box across = box_of(wall[0].points);
    EXPECT_LT(ruler.x(across.x0), -kRadius);  // across the whole view
    EXPECT_GT(ruler.x(across.x1), kRadius);

    const auto reported = with_style(paths, {kReportedXyStroke, "stroke-width:2.4;"});
    ASSERT_EQ(reported.size(), 1u);
    EXPECT_NEAR(ruler.y(box_of(reported[0].points).y0), kFloorAt, 1.0);  // at the wall, never past it
    const auto handle = with_style(paths, {kHandleXyStroke, "stroke-width:1.8;"});
    ASSERT_EQ(handle.size(), 1u);
    EXPECT_GT(ruler.y(box_of(handle[0].points).y0), kFloorAt + 20);  // a finite stiffness gives way a little
}

// An angle wall is the line x·sin a + y·cos a = offset (docs/conditions.md), a barrier's
// faces are at offset ± thickness/2.
TEST_F(Plots, AnAngleWallAndABarrierLieOnTheirLinesInTheXyView) {
    const std::string svg = path("far_xy.svg");
    const Result r = render("far_corner", {"--plot-xy", svg});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    const std::vector<SvgPath> paths = stroked_paths(read(svg));
    const auto target = with_style(paths, {kTargetXyStroke, "stroke-width:1.4;"});
    ASSERT_EQ(target.size(), 1u);
    const Ruler ruler = ruler_from_circle(target[0].points, kRadius);

    const auto wall = with_style(paths, {kWallStroke, "stroke-width:2;"});
    ASSERT_EQ(wall.size(), 1u);
    ASSERT_EQ(wall[0].points.size(), 2u);
    const double s45 = std::sqrt(0.5);
    for (const Point& p : wall[0].points) EXPECT_NEAR(s45 * ruler.x(p.x) + s45 * ruler.y(p.y), 8000, 2.0);

    const auto faces = with_style(paths, {kBarrierStroke});
    ASSERT_EQ(faces.size(), 1u);
    ASSERT_EQ(faces[0].points.size(), 4u);  // two lines
    std::vector<double> xs;
    for (const Point& p : faces[0].points) xs.push_back(ruler.x(p.x));
    std::sort(xs.begin(), xs.end());
    EXPECT_NEAR(xs[0], -2300, 1.0);
    EXPECT_NEAR(xs[1], -2300, 1.0);
    EXPECT_NEAR(xs[2], -1700, 1.0);
    EXPECT_NEAR(xs[3], -1700, 1.0);
    // The view is made wide enough to show the diagonal wall the hand never reaches.
    const Box frame = box_of(target[0].points);
    EXPECT_GT(8000 * ruler.per_unit_x, (frame.x1 - frame.x0) / 2);
}

// The time plot's position panel: the wall's line at y = 4000 against the y target's
// sine, which spans ±6000 over the whole render.
TEST_F(Plots, TheTimePlotsWallLineLiesAtTheWallsPlace) {
    const std::string svg = path("floor.svg");
    const Result r = render("floor", {"--plot", svg});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    const std::vector<SvgPath> paths = stroked_paths(read(svg));
    const auto target_y = with_style(paths, {kYAxisStroke, kTargetDash});
    ASSERT_EQ(target_y.size(), 1u);
    const Box b = box_of(target_y[0].points);
    const auto value_of = [&](double page_y) { return kRadius - (page_y - b.y0) / (b.y1 - b.y0) * 2 * kRadius; };
    const auto wall = with_style(paths, {kWallStroke, "stroke-width:2;"});
    ASSERT_EQ(wall.size(), 1u);
    ASSERT_EQ(wall[0].points.size(), 2u);
    for (const Point& p : wall[0].points) EXPECT_NEAR(value_of(p.y), kFloorAt, 1.0);
    EXPECT_LE(box_of(wall[0].points).x0, b.x0 + 0.01);  // over the whole time axis
    EXPECT_GE(box_of(wall[0].points).x1, b.x1 - 0.01);
}

// §3.7 clipping: the reported y never passes the wall and sits on it while the handle is
// in; the wall pushes only from inside, out along -y; at the deepest point (the handle at
// rest across the wall) Hooke's law holds, |fy| = K·depth, K = hardness/10000 of the
// device's wall stiffness (docs/conditions.md), within the sensor's resolution.
TEST_F(Plots, TheReportedPositionStopsAtTheWallAndTheWallPushesByItsStiffness) {
    const std::string csv = path("floor.csv");
    const Result r = render("floor", {"-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const double k = static_cast<double>(sim::engine_config_for(joystick).wall_stiffness);  // hardness 10000
    const double q = 20000.0 / joystick.axes[0].sensor_counts;                           // one sensor step
    const auto lines = lines_of(read(csv));
    ASSERT_EQ(lines[0], "t_us,x,y,vx,vy,fx,fy,rx,ry");
    double deepest = -1, force_there = 0;
    int inside = 0;
    for (size_t i = 1; i < lines.size(); ++i) {
        std::vector<double> v;
        std::istringstream row(lines[i]);
        for (std::string c; std::getline(row, c, ',');) v.push_back(std::strtod(c.c_str(), nullptr));
        const double y = v[2], fy = v[6], ry = v[8];
        ASSERT_LE(ry, kFloorAt) << lines[i];
        if (y > kFloorAt + q) {
            ++inside;
            EXPECT_EQ(ry, kFloorAt) << lines[i];
            EXPECT_LT(fy, 0) << lines[i];
            if (y - kFloorAt > deepest) deepest = y - kFloorAt, force_there = -fy;
        } else if (y < kFloorAt - q) {
            EXPECT_EQ(fy, 0) << lines[i];
        }
    }
    ASSERT_GT(inside, 100);  // the circle presses into the wall for a good part of a turn
    EXPECT_GE(force_there, k * (deepest - q)) << "depth " << deepest;
    EXPECT_LE(force_there, k * (deepest + q)) << "depth " << deepest;
}

TEST_F(Plots, TheXyViewNeedsTwoAxes) {
    const std::string png = path("wheel_xy.png");
    const Result r = run_cli({"render", file_, "--sensation", "floor", "--device", "wheel", "--plot-xy", png});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("--plot-xy needs a 2-axis device; wheel has 1 axis"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(png));
    const Result bad = run_cli({"render", file_, "--sensation", "floor", "--plot-xy", path("xy.pdf")});
    EXPECT_EQ(bad.code, kExitUsage);
    EXPECT_NE(bad.err.find("--plot-xy"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find(".svg, .png"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace feel::cli::testing
