// --motion specs: every form evaluates to its formula, and every malformed spec is
// refused with a message that names the bad part and the allowed form or range.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/sim/hand.hpp"

namespace feel::sim {
namespace {


std::string write_file(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / name;
    std::ofstream(path) << text;
    return path.string();
}

TEST(TargetMotion, HoldKeepsEveryAxisStill) {
    const TargetMotion m = TargetMotion::parse("hold:1000,-2000", 1, 3);
    for (double t : {0.0, 0.5, 100.0}) {
        const TargetMotion::Sample s = m.at(t);
        EXPECT_EQ(s.position[0], 1000);
        EXPECT_EQ(s.position[1], -2000);
        EXPECT_EQ(s.position[2], 0);
        for (double v : s.velocity) EXPECT_EQ(v, 0);
    }
    EXPECT_EQ(m.used_axes(), 2);
    EXPECT_EQ(m.spec(), "hold:1000,-2000");
    EXPECT_EQ(TargetMotion::parse(" hold: +250 ", 1, 1).at(0).position[0], 250);
}

TEST(TargetMotion, HoldAtBuildsAHold) {
    const TargetMotion m = TargetMotion::hold_at({-10000, 2.5, 10000});
    EXPECT_EQ(m.at(3).position[0], -10000);
    EXPECT_EQ(m.at(3).position[1], 2.5);
    EXPECT_EQ(m.at(3).position[2], 10000);
    EXPECT_EQ(m.used_axes(), 3);
    EXPECT_EQ(TargetMotion::parse(m.spec(), 1, 3).at(0).position[1], 2.5);
}

TEST(TargetMotion, RampGoesFromFromToToOverTheDuration) {
    const TargetMotion m = TargetMotion::parse("ramp:y:-5000:5000", 2.0, 2);
    EXPECT_EQ(m.at(0).position[1], -5000);
    EXPECT_DOUBLE_EQ(m.at(0.5).position[1], -2500);
    EXPECT_DOUBLE_EQ(m.at(1.0).position[1], 0);
    EXPECT_DOUBLE_EQ(m.at(1.0).velocity[1], 5000);  // 10000 units over 2 s
    EXPECT_EQ(m.at(2.0).position[1], 5000);
    EXPECT_EQ(m.at(7.0).position[1], 5000);
    EXPECT_EQ(m.at(7.0).velocity[1], 0);
    EXPECT_EQ(m.at(1.0).position[0], 0);
    EXPECT_EQ(m.used_axes(), 2);
}

TEST(TargetMotion, SineIsAmplitudeTimesSin2PiFt) {
    const TargetMotion m = TargetMotion::parse("sine:x:3000:2", 1, 2);
    for (double t = 0; t < 2; t += 0.013) {
        const TargetMotion::Sample s = m.at(t);
        EXPECT_NEAR(s.position[0], 3000 * std::sin(4 * std::numbers::pi * t), 1e-9);
        EXPECT_NEAR(s.velocity[0], 3000 * 4 * std::numbers::pi * std::cos(4 * std::numbers::pi * t), 1e-7);
        EXPECT_EQ(s.position[1], 0);
    }
    EXPECT_EQ(TargetMotion::parse("sine:z:-100:0.5", 1, 3).used_axes(), 3);
}

TEST(TargetMotion, CircleKeepsItsRadiusAndMovesTangentially) {
    const TargetMotion m = TargetMotion::parse("circle:4000:0.5", 1, 2);
    EXPECT_NEAR(m.at(0).position[0], 4000, 1e-12);
    EXPECT_NEAR(m.at(0.5).position[0], 0, 1e-9);  // a quarter turn at 0.5 Hz
    EXPECT_NEAR(m.at(0.5).position[1], 4000, 1e-9);
    EXPECT_NEAR(m.at(1.0).position[0], -4000, 1e-9);  // half a turn
    EXPECT_NEAR(m.at(1.0).position[1], 0, 1e-9);
    for (double t = 0; t < 3; t += 0.07) {
        const TargetMotion::Sample s = m.at(t);
        EXPECT_NEAR(std::hypot(s.position[0], s.position[1]), 4000, 1e-9);
        EXPECT_NEAR(std::hypot(s.velocity[0], s.velocity[1]), 4000 * std::numbers::pi, 1e-9);
        EXPECT_NEAR(s.position[0] * s.velocity[0] + s.position[1] * s.velocity[1], 0, 1e-6);
    }
}

TEST(TargetMotion, CsvInterpolatesLinearlyAndHoldsAtTheEnds) {
    const std::string path = write_file("motion_ok.csv",
                                        "# a test motion\r\n"
                                        "t_us,x,y\r\n"
                                        "\r\n"
                                        "100000, 0, 1000\r\n"
                                        "200000, 2000, 1000\r\n"
                                        "400000, -2000, -1000\r\n");
    const TargetMotion m = TargetMotion::parse("csv:" + path, 1, 2);
    EXPECT_EQ(m.used_axes(), 2);
    EXPECT_EQ(m.at(0).position[0], 0);  // before the first row: its values, still
    EXPECT_EQ(m.at(0).position[1], 1000);
    EXPECT_EQ(m.at(0).velocity[0], 0);
    EXPECT_DOUBLE_EQ(m.at(0.15).position[0], 1000);
    EXPECT_DOUBLE_EQ(m.at(0.15).velocity[0], 2000 / 0.1);
    EXPECT_NEAR(m.at(0.3).position[0], 0, 1e-9);
    EXPECT_NEAR(m.at(0.3).position[1], 0, 1e-9);
    EXPECT_DOUBLE_EQ(m.at(0.3).velocity[1], -2000 / 0.2);
    EXPECT_EQ(m.at(0.4).position[0], -2000);
    EXPECT_EQ(m.at(9).position[1], -1000);  // after the last row: held
    EXPECT_EQ(m.at(9).velocity[1], 0);

    const std::string one = write_file("motion_one.csv", "0,500\n1000000,-500\n");
    const TargetMotion m1 = TargetMotion::parse("csv:" + one, 1, 3);
    EXPECT_EQ(m1.used_axes(), 1);
    EXPECT_DOUBLE_EQ(m1.at(0.25).position[0], 250);
    EXPECT_EQ(m1.at(0.25).position[1], 0);
}

struct BadSpec {
    std::string spec;
    int32_t axis_count;
    std::vector<std::string> must_mention;
    double duration_s = 1;
};

void expect_refused(const BadSpec& bad) {
    try {
        (void)TargetMotion::parse(bad.spec, bad.duration_s, bad.axis_count);
        ADD_FAILURE() << "accepted \"" << bad.spec << "\"";
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("--motion \"" + bad.spec + "\": ", 0), 0u) << message;
        for (const std::string& word : bad.must_mention) {
            EXPECT_NE(message.find(word), std::string::npos)
                << "\"" << bad.spec << "\": \"" << message << "\" does not mention \"" << word
                << "\"";
        }
    }
}

TEST(TargetMotion, EveryMalformedSpecIsRefusedWithAClearMessage) {
    const std::vector<BadSpec> bad = {
        {"", 2, {"empty motion kind", "hold:X[,Y[,Z]]", "csv:PATH"}},
        {"wobble:1", 2, {"unknown motion kind \"wobble\"", "sine:AXIS:AMPLITUDE:HZ"}},
        {"hold", 2, {"hold needs arguments", "hold:X[,Y[,Z]]"}},
        {"hold:", 2, {"position of x is empty"}},
        {"hold:1,", 2, {"position of y is empty"}},
        {"hold:1,2,3", 2, {"hold takes 1 to 2 positions", "x, y", "got 3"}},
        {"hold:abc", 2, {"position of x \"abc\" is not a finite number"}},
        {"hold:nan", 2, {"\"nan\" is not a finite number"}},
        {"hold:0,inf", 2, {"position of y \"inf\" is not a finite number"}},
        {"hold:1e3x", 2, {"\"1e3x\" is not a finite number"}},
        {"hold:10000.5", 2, {"position of x = 10000.5 is outside the travel", "-10000..10000"}},
        {"hold:1:2", 2, {"separated by commas"}},
        {"ramp:x:0", 2, {"ramp takes 3 arguments (ramp:AXIS:FROM:TO), got 2"}},
        {"ramp:x:0:1:2", 2, {"got 4"}},
        {"ramp:z:0:1", 2, {"AXIS \"z\" is not an axis of this 2-axis device (allowed x, y)"}},
        {"ramp:X:0:1", 2, {"AXIS \"X\""}},
        {"ramp:x:-20000:0", 2, {"FROM = -20000 is outside the travel (allowed -10000..10000)"}},
        {"ramp:x:0:10001", 2, {"TO = 10001"}},
        {"ramp:x:0:1", 2, {"duration", "> 0", "got 0 s"}, 0.0},
        {"ramp:x:0:1", 2, {"duration", "got nan s"}, std::nan("")},
        {"sine:x:100", 2, {"sine takes 3 arguments (sine:AXIS:AMPLITUDE:HZ), got 2"}},
        {"sine:x:100:0", 2, {"HZ = 0 is out of range (allowed 0 < HZ <= 50)"}},
        {"sine:x:100:-2", 2, {"HZ = -2 is out of range"}},
        {"sine:x:100:51", 2, {"HZ = 51 is out of range"}},
        {"sine:x:100:fast", 2, {"HZ \"fast\" is not a finite number"}},
        {"sine:x:12000:1", 2, {"AMPLITUDE = 12000 is outside the travel"}},
        {"sine:y:100:1", 1, {"AXIS \"y\" is not an axis of this 1-axis device (allowed x)"}},
        {"sine:x::1", 2, {"AMPLITUDE is empty"}},
        {"circle:100", 2, {"circle takes 2 arguments (circle:RADIUS:HZ), got 1"}},
        {"circle:100:1", 1, {"circle moves x and y", "only axis x"}},
        {"circle:-5:1", 2, {"RADIUS = -5 is outside the travel (allowed 0..10000)"}},
        {"circle:100:0", 2, {"HZ = 0"}},
        {"csv:", 2, {"csv needs a file path (csv:PATH)"}},
        {"csv:/nonexistent/feel/motion.csv", 2, {"cannot be opened", "/nonexistent/feel/motion.csv"}},
        {"csv:" + ::testing::TempDir(), 2, {"is a directory"}},
        {"hold:0", 0, {"axis_count = 0 is out of range (allowed 1..6)"}},
    };
    for (const BadSpec& b : bad) expect_refused(b);
}

TEST(TargetMotion, EveryMalformedCsvNamesTheFileAndLine) {
    struct BadCsv {
        std::string name, text;
        std::vector<std::string> must_mention;
    };
    const std::vector<BadCsv> bad = {
        {"empty.csv", "", {"has no data rows"}},
        {"header_only.csv", "t_us,x\n# nothing\n", {"has no data rows"}},
        {"bad_number.csv", "t_us,x,y\n0,1,2\n1000,1,oops\n", {"line 3", "y \"oops\" is not a finite number"}},
        {"bad_time.csv", "0,1\nsoon,2\n", {"line 2", "t_us \"soon\" is not a finite number"}},
        {"no_positions.csv", "0,1\n1000\n", {"line 2", "0 positions", "1 to 2 positions"}},
        {"too_many.csv", "0,1,2,3\n", {"line 1", "3 positions", "x, y"}},
        {"ragged.csv", "0,1\n1000,1,2\n", {"line 2", "2 positions, but the first row has 1"}},
        {"backwards.csv", "0,1\n2000,1\n1000,1\n", {"line 3", "t_us = 1000 is not after", "2000", "strictly increase"}},
        {"repeat.csv", "0,1\n0,2\n", {"line 2", "not after"}},
        {"negative.csv", "-5,1\n", {"line 1", "t_us = -5 is negative"}},
        {"outside.csv", "\n\n0,1\n10,-10001\n", {"line 4", "x = -10001 is outside the travel", "-10000..10000"}},
    };
    for (const BadCsv& b : bad) {
        const std::string path = write_file(b.name, b.text);
        std::vector<std::string> mention = b.must_mention;
        mention.push_back("csv file \"" + path + "\"");
        expect_refused({"csv:" + path, 2, mention});
    }
}

TEST(TargetMotion, HoldAtRefusesWhatParseRefuses) {
    EXPECT_THROW((void)TargetMotion::hold_at({1, 2, 3, 4, 5, 6, 7}), std::invalid_argument);
    EXPECT_THROW((void)TargetMotion::hold_at({}), std::invalid_argument);
    EXPECT_THROW((void)TargetMotion::hold_at({0, 10000.1}), std::invalid_argument);
    EXPECT_THROW((void)TargetMotion::hold_at({std::nan("")}), std::invalid_argument);
}

TEST(GripNames, RoundTrip) {
    for (Grip g : {Grip::none, Grip::loose, Grip::firm, Grip::stiff, Grip::kinematic}) {
        EXPECT_EQ(grip_from_name(grip_name(g)), g);
    }
    EXPECT_EQ(grip_name(Grip::firm), "firm");
    EXPECT_FALSE(grip_from_name("Firm").has_value());
    EXPECT_FALSE(grip_from_name("").has_value());
}

}  // namespace
}  // namespace feel::sim
