// feel devices, play, stream and monitor on the in-process simulated device (no --device):
// the commands a fresh machine can run. Expected values come from the effects' definitions
// (magnitude × gain, polar directions, durations, delays), not from the commands' output.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

class HostCommands : public CliTest {
protected:
    std::string sample_path() {
        const std::string file = path("effects.feel.json");
        write(file, format::write_sensation_file(sample_file()));
        return file;
    }
};

// The first number after `prefix` at the start of a line; NaN when no line has it.
double number_after(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(prefix, 0) != 0) continue;
        const std::string rest = line.substr(prefix.size());
        std::smatch m;
        if (std::regex_search(rest, m, std::regex(R"([-+]?[0-9]+(\.[0-9]+)?)"))) return std::stod(m.str());
    }
    return std::nan("");
}

// The peak force of `axis` in feel play's summary table ("x      -2160.5     0.012 s").
double peak_of(const std::string& text, const std::string& axis) { return number_after(text, axis + " "); }

void expect_usage_error(const Result& r, const std::string& who, const std::vector<std::string>& words) {
    EXPECT_EQ(r.code, kExitUsage) << r.err;
    EXPECT_NE(r.err.find(who + ": error: "), std::string::npos) << r.err;
    for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << w << " in\n" << r.err;
}

// ---------------------------------------------------------------------------------------
// feel devices

TEST_F(HostCommands, DevicesListsOneInProcessDevicePerProfile) {
    const Result r = run_cli({"devices", "--socket-dir", path("no-sockets")});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    // The in-process table comes first; the USB HID PID section after its blank line
    // depends on what this machine has plugged in, so only its presence is checked.
    auto lines = lines_of(r.out);
    const auto blank = std::find(lines.begin(), lines.end(), std::string());
    ASSERT_NE(blank, lines.end()) << r.out;
    lines.erase(blank, lines.end());
    ASSERT_EQ(lines.size(), 6u) << r.out;
    EXPECT_TRUE(r.out.find("USB HID force-feedback device") != std::string::npos) << r.out;
    EXPECT_EQ(lines[0].rfind("address", 0), 0u) << lines[0];
    for (const char* name : {"joystick", "wheel", "3axis", "iforce1", "iforce2"}) {
        bool found = false;
        for (const std::string& line : lines) {
            if (line.rfind(std::string("sim:") + name + " ", 0) != 0) continue;
            found = true;
            const bool one = std::string(name) == "iforce1";
            EXPECT_NE(line.find(one ? "I-FORCE 1.x" : "I-FORCE 2.0"), std::string::npos) << line;
        }
        EXPECT_TRUE(found) << name << " in\n" << r.out;
    }
}

// ---------------------------------------------------------------------------------------
// feel play

TEST_F(HostCommands, PlayShowsTheVectorForceOfASingleEffectAndEnds) {
    const Result r = run_cli({"play", sample_path(), "--sensation", "push_west"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    // 4321 at gain 5000 from polar 9000 (from +x): 2160.5 toward -x, nothing on y.
    EXPECT_NEAR(peak_of(r.out, "x"), -2160.5, 5) << r.out;
    EXPECT_NEAR(peak_of(r.out, "y"), 0, 5) << r.out;
    EXPECT_NE(r.out.find("on         sim:iforce2"), std::string::npos) << r.out;
    // A 200 ms effect: it ends by itself, after 200 ms and a few reports more.
    const double ended = number_after(r.out, "ended      after ");
    EXPECT_GE(ended, 0.19) << r.out;
    EXPECT_LT(ended, 0.6) << r.out;
    // Live progress: plain lines when the output is not a terminal, "0.100 s   x ...".
    int progress = 0;
    for (const std::string& line : lines_of(r.out)) {
        if (std::regex_search(line, std::regex(R"(^[0-9]+\.[0-9]{3} s   x +[-+][0-9]+\.[0-9])"))) ++progress;
    }
    EXPECT_GE(progress, 2) << r.out;
    EXPECT_EQ(r.out.find('\r'), std::string::npos);
}

TEST_F(HostCommands, PlayWaitsForACompoundsDelayedEffect) {
    // a: 2000 on x for 100 ms; b: 2000 on y, starting at 150 ms for 100 ms.
    const Result r = run_cli({"play", sample_path(), "--sensation", "pair"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    EXPECT_NEAR(std::fabs(peak_of(r.out, "x")), 2000, 5) << r.out;
    EXPECT_NEAR(std::fabs(peak_of(r.out, "y")), 2000, 5) << r.out;
    const double ended = number_after(r.out, "ended      after ");
    EXPECT_GE(ended, 0.24) << r.out;
    EXPECT_LT(ended, 0.7) << r.out;
    EXPECT_NE(r.out.find("delayed"), std::string::npos) << r.out;  // b, while a plays
}

TEST_F(HostCommands, PlayRepeatsWithIterations) {
    const Result r = run_cli({"play", sample_path(), "--sensation", "push_west", "--iterations", "2"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    const double ended = number_after(r.out, "ended      after ");
    EXPECT_GE(ended, 0.39) << r.out;
    EXPECT_LT(ended, 0.8) << r.out;
}

TEST_F(HostCommands, PlayStopsAnEndlessSensationAfterSeconds) {
    const Result r = run_cli({"play", sample_path(), "--sensation", "hum", "--seconds", "0.3"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    EXPECT_NE(r.out.find("(--seconds)"), std::string::npos) << r.out;
    const double stopped = number_after(r.out, "stopped    after ");
    EXPECT_GE(stopped, 0.3) << r.out;
    EXPECT_LT(stopped, 0.6) << r.out;
    // A 3000 sine of 23 ms (cli_fixture.hpp) sampled every 1 ms tick: the tick nearest the peak
    // is within half a tick, π/23 of phase, so the largest sample is within cos(π/23) of it.
    EXPECT_GE(std::fabs(peak_of(r.out, "x")), 3000 * std::cos(3.14159265 / 23) - 1) << r.out;
    EXPECT_LE(std::fabs(peak_of(r.out, "x")), 3000.5) << r.out;
}

TEST_F(HostCommands, PlayErrorsNameTheProblem) {
    const std::string file = sample_path();
    expect_usage_error(run_cli({"play", file, "--sensation", "nope"}), "feel play",
                       {"--sensation \"nope\"", "push_west, hum, pair, kick"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--seconds", "0"}), "feel play",
                       {"--seconds", "0 < value <= 3600"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--seconds", "nan"}), "feel play", {"--seconds"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--iterations", "0"}), "feel play",
                       {"--iterations", "1..255"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--iterations", "256"}), "feel play",
                       {"--iterations", "1..255"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--iterations", "lots"}), "feel play",
                       {"--iterations", "infinite"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--device", "tcp:localhost"}), "feel play",
                       {"--device", "tcp:localhost"});
    expect_usage_error(run_cli({"play", file, "--sensation", "hum", "--device", "sim:iforce3"}), "feel play",
                       {"--device", "iforce3", "joystick, wheel, 3axis, iforce1, iforce2"});
    expect_usage_error(run_cli({"play", file}), "feel play", {"--sensation"});

    const Result missing = run_cli({"play", path("missing.feel.json"), "--sensation", "hum"});
    EXPECT_EQ(missing.code, kExitFailure);
    EXPECT_NE(missing.err.find("missing.feel.json"), std::string::npos) << missing.err;

    const Result nobody = run_cli({"play", file, "--sensation", "hum", "--device", "unix:" + path("nobody.sock")});
    EXPECT_EQ(nobody.code, kExitFailure);
    EXPECT_NE(nobody.err.find("nobody.sock"), std::string::npos) << nobody.err;
}

TEST_F(HostCommands, PlayOnADeviceWithoutDynamicsIsRenderedByTheHost) {
    // iforce1 plays no Dynamics; the host renders the recoil (host emulation, §1.2.c).
    const Result r = run_cli({"play", sample_path(), "--sensation", "kick", "--device", "iforce1"});
    EXPECT_EQ(r.code, kExitOk) << r.out << r.err;
}

TEST_F(HostCommands, PlayReportsAFileErrorWithTheField) {
    const std::string bad = path("bad.feel.json");
    std::string text = format::write_sensation_file(sample_file());
    const std::string from = "\"magnitude\": 3000";
    ASSERT_NE(text.find(from), std::string::npos) << text;
    text.replace(text.find(from), from.size(), "\"magnitude\": 12000");
    write(bad, text);
    const Result r = run_cli({"play", bad, "--sensation", "hum"});
    EXPECT_EQ(r.code, kExitFailure);
    for (const char* word : {"bad.feel.json", "hum", "magnitude", "12000"}) {
        EXPECT_NE(r.err.find(word), std::string::npos) << word << " in\n" << r.err;
    }
}

// ---------------------------------------------------------------------------------------
// feel stream

TEST_F(HostCommands, StreamAt60HzIsReconstructedWithoutOvershootOneIntervalLate) {
    const Result r = run_cli({"stream", "--seconds", "1", "--rate", "60", "--amplitude", "5000", "--frequency", "2"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    EXPECT_NEAR(number_after(r.out, "sent       "), 60, 2) << r.out;
    // The device ramps to each sample over one interval: never beyond the samples.
    EXPECT_LE(number_after(r.out, "overshoot  "), 0.5) << r.out;
    // ... and so lags the waveform by about one interval, 1/60 s, plus the trip.
    const double delay_ms = number_after(r.out, "delay      ");
    EXPECT_GE(delay_ms, 8) << r.out;
    EXPECT_LE(delay_ms, 40) << r.out;
    EXPECT_GE(number_after(r.out, "reports    "), 500) << r.out;  // 1 kHz reports for 1 s
}

TEST_F(HostCommands, StreamAt1kHzPassesThroughAndAStepIsHeld) {
    const Result r = run_cli({"stream", "--seconds", "0.6", "--rate", "1000", "--shape", "step", "--amplitude",
                              "4000"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    EXPECT_LE(number_after(r.out, "overshoot  "), 0.5) << r.out;
    // Every 1 ms slot is sent, or skipped when a loaded machine wakes the host too late.
    const double sent = number_after(r.out, "sent       ");
    std::smatch m;
    const double skipped = std::regex_search(r.out, m, std::regex(R"(\(([0-9]+) skipped)")) ? std::stod(m[1]) : 0;
    EXPECT_NEAR(sent + skipped, 600, 2) << r.out;
    // The last sample was 4000; the device holds it after the stream stops (§2.4).
    EXPECT_NEAR(number_after(r.out, "held       x "), 4000, 0.5) << r.out;
}

TEST_F(HostCommands, StreamFlagsAreChecked) {
    expect_usage_error(run_cli({"stream", "--rate", "0"}), "feel stream", {"--rate", "1..1000"});
    expect_usage_error(run_cli({"stream", "--rate", "1001"}), "feel stream", {"--rate", "1..1000"});
    expect_usage_error(run_cli({"stream", "--rate", "60.5"}), "feel stream", {"--rate", "whole number"});
    expect_usage_error(run_cli({"stream", "--shape", "triangle"}), "feel stream", {"--shape", "sine, square, step"});
    expect_usage_error(run_cli({"stream", "--amplitude", "10001"}), "feel stream", {"--amplitude", "0..10000"});
    expect_usage_error(run_cli({"stream", "--amplitude", "-1"}), "feel stream", {"--amplitude", "0..10000"});
    expect_usage_error(run_cli({"stream", "--rate", "60", "--frequency", "31"}), "feel stream",
                       {"--frequency", "0 < value <= 30 Hz"});
    expect_usage_error(run_cli({"stream", "--seconds", "0"}), "feel stream", {"--seconds", "600"});
    expect_usage_error(run_cli({"stream", "--device", "unix:"}), "feel stream", {"--device"});
}

// ---------------------------------------------------------------------------------------
// feel monitor

TEST_F(HostCommands, MonitorShowsTheLoopForcesAndSafetyFiveTimesASecond) {
    const Result r = run_cli({"monitor", "--seconds", "1.3"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    int blocks = 0;
    double measured = std::nan("");
    for (const std::string& line : lines_of(r.out)) {
        blocks += line.rfind("device   ", 0) == 0 ? 1 : 0;
        if (line.find(" Hz measured (nominal 1000 Hz)") != std::string::npos) measured = number_after(line, "loop ");
    }
    EXPECT_GE(blocks, 6) << r.out;  // 5 per second, and the last at the end
    EXPECT_LE(blocks, 8) << r.out;
    EXPECT_NE(r.out.find("(nominal 1000 Hz), overruns "), std::string::npos) << r.out;
    // After its first second the device has measured its loop: 1000 ticks a second, less
    // what a loaded machine made it skip.
    EXPECT_GE(measured, 800) << r.out;
    EXPECT_LE(measured, 1010) << r.out;
    EXPECT_NE(r.out.find("force    x "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("safety   "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("effects  0 resident, 0 playing"), std::string::npos) << r.out;
}

TEST_F(HostCommands, MonitorPlaysASensationAndListsItsEffects) {
    const Result r = run_cli({"monitor", "--seconds", "0.9", "--sensation", sample_path() + ":hum"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    // Only the chosen sensation is downloaded (its one effect), and it plays.
    EXPECT_NE(r.out.find("effects  1 resident, 1 playing"), std::string::npos) << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(\n +[0-9]+  sine +playing)"))) << r.out;
    // The sine's force shows on x (within its amplitude of 3000).
    bool pushed = false;
    for (const std::string& line : lines_of(r.out)) {
        if (line.rfind("force    x ", 0) != 0) continue;
        const double x = number_after(line, "force    x ");
        EXPECT_LE(std::fabs(x), 3000.5) << line;
        pushed = pushed || std::fabs(x) > 1;
    }
    EXPECT_TRUE(pushed) << r.out;
}

TEST_F(HostCommands, MonitorFlagsAreChecked) {
    const std::string file = sample_path();
    expect_usage_error(run_cli({"monitor", "--seconds", "-1"}), "feel monitor", {"--seconds", "86400"});
    expect_usage_error(run_cli({"monitor", "--seconds", "1", "--sensation", file}), "feel monitor",
                       {"--sensation", "FILE:NAME"});
    expect_usage_error(run_cli({"monitor", "--seconds", "1", "--sensation", file + ":nope"}), "feel monitor",
                       {"nope", "push_west, hum, pair, kick"});
}

TEST_F(HostCommands, HelpListsTheHostCommands) {
    const Result help = run_cli({"--help"});
    for (const char* cmd : {"devices", "caps", "play", "stream", "monitor", "device"}) {
        EXPECT_NE(help.out.find(cmd), std::string::npos) << cmd;
    }
    for (const char* cmd : {"play", "stream", "monitor"}) {
        const Result r = run_cli({cmd, "--help"});
        EXPECT_EQ(r.code, kExitOk) << cmd;
        EXPECT_NE(r.out.find("--device"), std::string::npos) << cmd << r.out;
    }
}

}  // namespace
}  // namespace feel::cli::testing
