// write_csv(): the header names the device's axes; every number reads back exactly.
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "feel/render/render.hpp"
#include "sensation_builders.hpp"

namespace feel::render {
namespace {

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> out;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, sep)) out.push_back(cell);
    if (!line.empty() && line.back() == sep) out.emplace_back();
    return out;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

struct DeviceCase {
    const char* device;
    const char* header;
};

class CsvPerDevice : public ::testing::TestWithParam<DeviceCase> {};

TEST_P(CsvPerDevice, HeaderNamesEachAxisAndEveryRowHasOneCellPerColumn) {
    const DeviceCase c = GetParam();
    const format::Sensation s =
        testing::single("tap", testing::axis_constant(Axis::x, 4000, 50'000));
    RenderOptions o;
    o.profile = &testing::profile(c.device);
    o.grip = sim::Grip::kinematic;
    o.duration_s = 0.2;
    o.rate_hz = 1000;
    const Trace trace = render(s, o);

    std::ostringstream out;
    write_csv(trace, out);
    const std::vector<std::string> lines = lines_of(out.str());
    ASSERT_EQ(lines.size(), 1u + 200u);
    EXPECT_EQ(lines[0], c.header);
    const size_t columns = split(lines[0], ',').size();
    EXPECT_EQ(columns, 1u + 4u * static_cast<size_t>(o.profile->axis_count));
    for (size_t i = 1; i < lines.size(); ++i) {
        ASSERT_EQ(split(lines[i], ',').size(), columns) << "line " << i << ": " << lines[i];
    }
    EXPECT_EQ(split(lines[1], ',')[0], "0");
    EXPECT_EQ(split(lines.back(), ',')[0], "199000");
    // The force column of x during the tap: 4000, written as such.
    EXPECT_EQ(split(lines[1], ',')[1 + 2 * static_cast<size_t>(o.profile->axis_count)], "4000");
}

INSTANTIATE_TEST_SUITE_P(Devices, CsvPerDevice,
                         ::testing::Values(DeviceCase{"joystick", "t_us,x,y,vx,vy,fx,fy,rx,ry"},
                                           DeviceCase{"wheel", "t_us,x,vx,fx,rx"},
                                           DeviceCase{"3axis", "t_us,x,y,z,vx,vy,vz,fx,fy,fz,rx,ry,rz"}),
                         [](const auto& param_info) {
                             return std::string(param_info.param.device) == "3axis"
                                        ? std::string("three_axis")
                                        : std::string(param_info.param.device);
                         });

TEST(Csv, FloatsRoundTripExactly) {
    Trace trace;
    trace.axis_count = 2;
    trace.rate_hz = 1000;
    const float values[] = {0.1f, -3000.25f, 1e-7f, 9999.999f, -0.0f, 1.0e30f};
    for (size_t i = 0; i < std::size(values); ++i) {
        TraceRow row;
        row.t_us = static_cast<int64_t>(i) * 1000 + 123'456'789'012;
        row.position[0] = values[i];
        row.position[1] = -values[i];
        row.velocity[0] = values[i] * 3;
        row.velocity[1] = values[i] / 7;
        row.force[0] = values[(i + 1) % std::size(values)];
        row.force[1] = values[(i + 2) % std::size(values)];
        row.reported[0] = values[(i + 3) % std::size(values)];
        row.reported[1] = -values[(i + 4) % std::size(values)];
        trace.rows.push_back(row);
    }
    std::ostringstream out;
    write_csv(trace, out);
    const std::vector<std::string> lines = lines_of(out.str());
    ASSERT_EQ(lines.size(), 1 + trace.rows.size());
    for (size_t i = 0; i < trace.rows.size(); ++i) {
        const std::vector<std::string> cells = split(lines[i + 1], ',');
        ASSERT_EQ(cells.size(), 9u);
        const TraceRow& row = trace.rows[i];
        EXPECT_EQ(std::stoll(cells[0]), row.t_us);
        const float expected[] = {row.position[0], row.position[1], row.velocity[0],
                                  row.velocity[1], row.force[0],    row.force[1],
                                  row.reported[0], row.reported[1]};
        for (size_t c = 0; c < 8; ++c) {
            EXPECT_EQ(std::strtof(cells[c + 1].c_str(), nullptr), expected[c])
                << "row " << i << " column " << c + 1 << ": " << cells[c + 1];
        }
    }
}

TEST(Csv, AnEmptyTraceIsJustTheHeader) {
    Trace trace;
    trace.axis_count = 1;
    std::ostringstream out;
    write_csv(trace, out);
    EXPECT_EQ(out.str(), "t_us,x,vx,fx,rx\n");
}

}  // namespace
}  // namespace feel::render
