// feel render: files in, CSV, plots and a summary out; every mistake a clear message.
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

class Render : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        file_ = path("effects.feel.json");
        write(file_, format::write_sensation_file(sample_file()));
    }
    std::string file_;
};

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    return cells;
}

// A kinematic hand at the center isolates the engine: fx = -M·G/10000 while the push
// lasts (polar 9000 comes from +x), then nothing.
TEST_F(Render, WritesTheTraceAsCsvWithTheForceOfTheDefinition) {
    const std::string csv = path("push.csv");
    const Result r = run_cli({"render", file_, "--sensation", "push_west", "--hand", "kinematic",
                              "--duration", "0.3", "-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    const auto lines = lines_of(read(csv));
    ASSERT_EQ(lines.size(), 1u + 300u);
    EXPECT_EQ(lines[0], "t_us,x,y,vx,vy,fx,fy,rx,ry");
    for (size_t i = 1; i < lines.size(); ++i) {
        const auto cells = split(lines[i]);
        ASSERT_EQ(cells.size(), 9u) << lines[i];
        const long long t = std::stoll(cells[0]);
        EXPECT_EQ(t, static_cast<long long>(i - 1) * 1000);
        const double fx = std::strtod(cells[5].c_str(), nullptr);
        if (t < 200'000) {
            EXPECT_NEAR(fx, -4321.0 * 5000 / 10000, 0.5) << lines[i];
        } else if (t > 200'000) {
            EXPECT_EQ(fx, 0.0) << lines[i];
        }
    }
    // The summary reports what was done and where it went.
    for (const char* word : {"push_west", "joystick", "kinematic", "300 ticks", "2160.5", "wrote",
                             "push.csv"}) {
        EXPECT_NE(r.out.find(word), std::string::npos) << word << " in\n" << r.out;
    }
}

TEST_F(Render, DefaultsToTheSensationsLengthOnAJoystickHeldFirmly) {
    const std::string csv = path("pair.csv");
    const Result r = run_cli({"render", file_, "--sensation", "pair", "-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    // 250 ms of sensation and a 100 ms tail, at 1 kHz.
    EXPECT_EQ(lines_of(read(csv)).size(), 1u + 350u);
    EXPECT_NE(r.out.find("firm"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("joystick"), std::string::npos) << r.out;
}

TEST_F(Render, TheHeaderFollowsTheDevice) {
    const std::string wheel = path("wheel.csv");
    ASSERT_EQ(run_cli({"render", file_, "--sensation", "hum", "--device", "wheel", "--duration",
                       "0.05", "-o", wheel})
                  .code,
              kExitOk);
    EXPECT_EQ(lines_of(read(wheel))[0], "t_us,x,vx,fx,rx");
    const std::string three = path("3axis.csv");
    ASSERT_EQ(run_cli({"render", file_, "--sensation", "hum", "--device", "3axis", "--duration",
                       "0.05", "-o", three})
                  .code,
              kExitOk);
    EXPECT_EQ(lines_of(read(three))[0], "t_us,x,y,z,vx,vy,vz,fx,fy,fz,rx,ry,rz");
}

TEST_F(Render, DashWritesTheCsvToStdoutAndTheSummaryToStderr) {
    const Result r = run_cli({"render", file_, "--sensation", "hum", "--duration", "0.01",
                              "--rate", "2000", "-o", "-"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 1u + 20u);
    EXPECT_EQ(lines[0], "t_us,x,y,vx,vy,fx,fy,rx,ry");
    EXPECT_EQ(split(lines.back())[0], "9500");
    EXPECT_NE(r.err.find("hum"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("wrote"), std::string::npos) << r.err;
}

TEST_F(Render, PlotsToSvgAndPngCreatingDirectories) {
    const std::string svg = path("plots/deep/hum.svg");
    const std::string png = path("plots/hum.png");
    const std::string csv = path("csv/hum.csv");
    ASSERT_EQ(run_cli({"render", file_, "--sensation", "hum", "--duration", "0.2", "-o", csv,
                       "--plot", svg})
                  .code,
              kExitOk);
    const Result r = run_cli({"render", file_, "--sensation", "hum", "--duration", "0.2", "-o",
                              csv, "--plot", png});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(read(svg).rfind("<?xml", 0), 0u);
    EXPECT_EQ(read(png).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_NE(r.out.find(png), std::string::npos) << r.out;
}

// --- mistakes on the command line: exit 2, the flag named -------------------------------

TEST_F(Render, AnUnknownFlagIsNamed) {
    const Result r = run_cli({"render", file_, "--sensation", "hum", "-o", "-", "--bogus", "3"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST_F(Render, MissingRequiredOptionsAreNamed) {
    const Result no_sensation = run_cli({"render", file_, "-o", "-"});
    EXPECT_EQ(no_sensation.code, kExitUsage);
    EXPECT_NE(no_sensation.err.find("--sensation"), std::string::npos) << no_sensation.err;
    const Result no_output = run_cli({"render", file_, "--sensation", "hum"});
    EXPECT_EQ(no_output.code, kExitUsage);
    EXPECT_NE(no_output.err.find("--output"), std::string::npos) << no_output.err;
}

TEST_F(Render, AnUnknownSensationListsTheAvailableOnes) {
    const Result r = run_cli({"render", file_, "--sensation", "hmm", "-o", path("x.csv")});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("\"hmm\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("push_west, hum, pair, kick"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("x.csv")));
}

TEST_F(Render, AnUnknownDeviceListsTheProfiles) {
    const Result r = run_cli({"render", file_, "--sensation", "hum", "--device", "pedals", "-o", "-"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("pedals"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("joystick, wheel, 3axis"), std::string::npos) << r.err;
}

TEST_F(Render, AnUnknownHandListsTheGrips) {
    const Result r = run_cli({"render", file_, "--sensation", "hum", "--hand", "tight", "-o", "-"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("none, loose, firm, stiff, kinematic"), std::string::npos) << r.err;
}

TEST_F(Render, OutOfRangeValuesNameTheFlagAndTheRange) {
    struct Case {
        std::vector<std::string> extra;
        const char* flag;
        const char* range;
    };
    const Case cases[] = {
        {{"--rate", "50"}, "--rate", "100..10000"},
        {{"--rate", "fast"}, "--rate", "fast"},
        {{"--duration", "0"}, "--duration", "600"},
        {{"--duration", "-2"}, "--duration", "600"},
        {{"--duration", "900"}, "--duration", "600"},
        {{"--motion", "wobble:1"}, "--motion", "hold:"},
        {{"--plot", "out.pdf"}, "--plot", ".svg, .png"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> argv{"feel", "render", file_, "--sensation", "hum", "-o", "-"};
        argv.insert(argv.end(), c.extra.begin(), c.extra.end());
        std::ostringstream out, err;
        const int code = run(argv, out, err);
        EXPECT_EQ(code, kExitUsage) << c.flag << ": " << err.str();
        EXPECT_NE(err.str().find(c.flag), std::string::npos) << err.str();
        EXPECT_NE(err.str().find(c.range), std::string::npos) << err.str();
        EXPECT_EQ(out.str(), "") << c.flag;
    }
}

// --- failures doing the work: exit 1 -----------------------------------------------------

TEST_F(Render, ASensationTheEngineRefusesNamesTheEffectAndType) {
    // The kick is a recoil on x and y; the wheel has only x.
    const Result r = run_cli({"render", file_, "--sensation", "kick", "--device", "wheel", "-o", path("kick.csv")});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_NE(r.err.find("\"kick\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("effect 0"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("dynamic_recoil"), std::string::npos) << r.err;
}

TEST_F(Render, AnAxisTheDeviceLacksIsAFailure) {
    const Result r = run_cli({"render", file_, "--sensation", "pair", "--device", "wheel", "-o",
                              path("pair.csv")});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_NE(r.err.find("effect 1"), std::string::npos) << r.err;
}

TEST_F(Render, AnUnreadableFileIsAFailureNamingIt) {
    const Result r = run_cli({"render", path("missing.json"), "--sensation", "hum", "-o", "-"});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
}

TEST_F(Render, AnUnwritableOutputIsAFailureNamingIt) {
    write(path("blocker"), "a file where a directory should be");
    const std::string csv = path("blocker/out.csv");
    const Result r = run_cli({"render", file_, "--sensation", "hum", "--duration", "0.01", "-o", csv});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_NE(r.err.find("blocker"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace feel::cli::testing

namespace feel::cli::testing {
namespace {

// A dynamic's render carries the simulated mass: CSV columns mx,my,mvx,mvy and a line
// about its reports in the summary (§5.2).
TEST_F(Render, ADynamicWritesTheMassAndSummarizesItsReports) {
    const std::string csv = path("kick_mass.csv");
    const Result r = run_cli({"render", file_, "--sensation", "kick", "-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(lines_of(read(csv))[0], "t_us,x,y,vx,vy,fx,fy,rx,ry,mx,my,mvx,mvy");
    EXPECT_NE(r.out.find("dynamics"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace feel::cli::testing
