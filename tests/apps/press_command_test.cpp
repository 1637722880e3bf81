// feel render --press: buttons and hats pressed on a schedule start the file's reflexes
// (§1.2.c) as its trigger_button and trigger_repeat_interval_us say (§6.3); feel check
// lists them; render and play pick a file's only sensation by themselves.
#include <cmath>
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

constexpr int64_t kTapUs = 100'000;     // each tap's duration
constexpr int64_t kRepeatUs = 300'000;  // the gun's trigger repeat interval
constexpr int32_t kMagnitude = 4000;

// gun: a 100 ms constant on x, triggered by button 1, repeating every 300 ms while held.
// horn: a 100 ms constant on x, triggered by hat 2, no repeat.
format::SensationFile trigger_file() {
    EffectParams tap;
    tap.type = EffectType::constant;
    tap.duration_us = kTapUs;
    tap.axis_count = 1;
    tap.constant.magnitude = kMagnitude;
    EffectParams gun = tap;
    gun.trigger = Trigger{TriggerKind::button, 1};
    gun.trigger_repeat_interval_us = kRepeatUs;
    EffectParams horn = tap;
    horn.trigger = Trigger{TriggerKind::hat, 2};
    format::SensationFile file;
    file.sensations.push_back({"gun", std::nullopt, false, {{gun, {}, {}}}});
    file.sensations.push_back({"horn", std::nullopt, false, {{horn, {}, {}}}});
    return file;
}

// The times (µs) at which |fx| rises from 0: the starts of the taps, read from the CSV.
std::vector<long long> tap_starts(const std::string& csv) {
    std::vector<long long> starts;
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);  // the header names the columns
    size_t fx_column = 0;
    {
        std::istringstream header(line);
        size_t i = 0;
        for (std::string c; std::getline(header, c, ','); ++i) {
            if (c == "fx") fx_column = i;
        }
    }
    bool on = false;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::istringstream row(line);
        for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
        const double fx = std::strtod(cells.at(fx_column).c_str(), nullptr);
        const bool now = std::fabs(fx) > 0.5;
        if (now && !on) starts.push_back(std::stoll(cells[0]));
        on = now;
    }
    return starts;
}

class Press : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        file_ = path("triggers.feel.json");
        write(file_, format::write_sensation_file(trigger_file()));
    }
    std::string file_;
};

// Held for `hold`, the reflex starts at the press and every interval after it while held:
// floor(hold / interval) + 1 starts, at press + k·interval. Nothing plays before the press.
TEST_F(Press, AHeldButtonStartsItsReflexAtThePressAndEveryRepeatInterval) {
    const int64_t press_us = 200'000;
    for (const int64_t hold_us : {int64_t{950'000}, int64_t{250'000}, int64_t{650'000}}) {
        const std::string csv = path("gun.csv");
        const std::string spec = "1@0.2:" + std::to_string(static_cast<double>(press_us + hold_us) * 1e-6);
        const Result r = run_cli({"render", file_, "--sensation", "gun", "--device", "wheel", "--hand",
                                  "kinematic", "--duration", "1.5", "--press", spec, "-o", csv});
        ASSERT_EQ(r.code, kExitOk) << r.err;
        const std::vector<long long> starts = tap_starts(read(csv));
        const int64_t expected = hold_us / kRepeatUs + 1;
        ASSERT_EQ(static_cast<int64_t>(starts.size()), expected) << "hold " << hold_us << "\n" << r.out;
        for (int64_t k = 0; k < expected; ++k) EXPECT_EQ(starts[static_cast<size_t>(k)], press_us + k * kRepeatUs);
        EXPECT_NE(r.out.find("reflexes started effects " + std::to_string(expected)), std::string::npos) << r.out;
    }
}

// A hat switch pushed off center is a press of its trigger; without a repeat interval the
// reflex starts once per push, however long it is held.
TEST_F(Press, EachPushOfAHatStartsItsReflexOnce) {
    const std::string csv = path("horn.csv");
    const Result r = run_cli({"render", file_, "--sensation", "horn", "--device", "sim:joystick", "--hand",
                              "kinematic", "--duration", "1.2", "--press", "hat2:up@0.1:0.6,hat2:left@0.8:0.85",
                              "-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(tap_starts(read(csv)), (std::vector<long long>{100'000, 800'000}));
}

TEST_F(Press, APressAtTheStartIsAPress) {
    const std::string csv = path("start.csv");
    const Result r = run_cli({"render", file_, "--sensation", "gun", "--device", "wheel", "--hand", "kinematic",
                              "--duration", "0.5", "--press", "1@0:0.05", "-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(tap_starts(read(csv)), (std::vector<long long>{0}));
}

TEST_F(Press, WithoutPressesATriggeredEffectWaits) {
    const std::string csv = path("idle.csv");
    const Result r = run_cli({"render", file_, "--sensation", "gun", "--device", "wheel", "--duration", "0.5",
                              "-o", csv});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_TRUE(tap_starts(read(csv)).empty());
}

TEST_F(Press, BadTokensAreNamedWithTheAllowedForms) {
    struct Case {
        const char* spec;
        const char* named;
    };
    for (const Case c : {Case{"1@0.9:0.2", "\"1@0.9:0.2\""}, Case{"33@0:1", "\"33\""}, Case{"hat5:up@0:1", "\"hat5\""},
                         Case{"hat2:sideways@0:1", "\"sideways\""}, Case{"1", "no @"}, Case{"1@0.2", "no :"},
                         Case{"1@a:1", "\"a\""}, Case{"1@0:700", "700 s is out of range"},
                         Case{"1@0:1,,2@0:1", "empty entry"}, Case{"x@0:1", "\"x\""}}) {
        const Result r = run_cli({"render", file_, "--sensation", "gun", "--press", c.spec, "-o", path("x.csv")});
        EXPECT_EQ(r.code, kExitUsage) << c.spec;
        EXPECT_NE(r.err.find("--press"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.named), std::string::npos) << c.spec << ": " << r.err;
        EXPECT_NE(r.err.find("BUTTON 1..32"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(path("x.csv")));
    }
    // A button the device lacks: the joystick has fewer than 30 buttons.
    const Result r = run_cli({"render", file_, "--sensation", "gun", "--press", "30@0:1", "-o", path("x.csv")});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("--press"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("joystick"), std::string::npos) << r.err;
}

TEST_F(Press, CheckListsEachEffectsTriggerAndRepeat) {
    const Result r = run_cli({"check", file_});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 4u) << r.out;
    EXPECT_NE(lines[1].find("trigger"), std::string::npos) << lines[1];
    EXPECT_NE(lines[2].find("button 1 every 300 ms"), std::string::npos) << lines[2];
    EXPECT_NE(lines[3].find("hat 2"), std::string::npos) << lines[3];
    EXPECT_EQ(lines[3].find("every"), std::string::npos) << lines[3];
}

TEST_F(Press, RenderAndPlayPickAFilesOnlySensation) {
    format::SensationFile one = trigger_file();
    one.sensations.resize(1);
    one.sensations[0].effects[0].params.trigger = {};
    one.sensations[0].effects[0].params.trigger_repeat_interval_us = 0;
    const std::string single = path("single.feel.json");
    write(single, format::write_sensation_file(one));
    const Result rendered = run_cli({"render", single, "--duration", "0.2", "-o", path("one.csv")});
    ASSERT_EQ(rendered.code, kExitOk) << rendered.err;
    EXPECT_NE(rendered.out.find("gun"), std::string::npos) << rendered.out;
    const Result played = run_cli({"play", single, "--seconds", "0.5"});
    ASSERT_EQ(played.code, kExitOk) << played.err;
    EXPECT_NE(played.out.find("playing    gun"), std::string::npos) << played.out;

    // With several, the error lists them.
    for (const Result& r : {run_cli({"render", file_, "-o", "-"}), run_cli({"play", file_})}) {
        EXPECT_EQ(r.code, kExitUsage) << r.err;
        EXPECT_NE(r.err.find("--sensation"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("gun, horn"), std::string::npos) << r.err;
    }
}

TEST_F(Press, RenderNeedsNoOutputWhenOnlyAPlotIsWanted) {
    const std::string plot = path("gun.svg");
    const Result r = run_cli({"render", file_, "--sensation", "gun", "--press", "1@0.1:0.2", "--duration", "0.4",
                              "--plot", plot});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_TRUE(fs::exists(plot));
    EXPECT_NE(r.out.find("gun.svg"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("CSV"), std::string::npos) << r.out;
}

TEST_F(Press, RenderTakesSimProfileAsTheHostCommandsDo) {
    const Result r = run_cli({"render", file_, "--sensation", "gun", "--device", "sim:iforce2", "--duration", "0.1",
                              "-o", "-"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_NE(r.err.find("iforce2"), std::string::npos) << r.err;
    const Result bad = run_cli({"render", file_, "--sensation", "gun", "--device", "sim:pedals", "-o", "-"});
    EXPECT_EQ(bad.code, kExitUsage);
    EXPECT_NE(bad.err.find("sim:PROFILE"), std::string::npos) << bad.err;
}

// feel play --press on the in-process device: the simulated hand presses button 1 from
// 0.1 s to 0.75 s, so the gun's reflex starts at 0.1, 0.4 and 0.7 s, each tap 4000 on x.
TEST_F(Press, PlayPressesTheSimulatedHandsButtons) {
    const Result r = run_cli({"play", file_, "--sensation", "gun", "--device", "sim:wheel", "--press", "1@0.1:0.75",
                              "--seconds", "1.2"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    // The peak: a tap's magnitude on x (the wheel's only axis), at about a tap's start.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(\nx +([-+][0-9]+\.[0-9]) +([0-9.]+) s)"))) << r.out;
    EXPECT_NEAR(std::fabs(std::stod(m[1].str())), kMagnitude, 5) << r.out;
    // A device on a cable has its own hand.
    const Result remote = run_cli({"play", file_, "--sensation", "gun", "--device", "unix:/nonexistent.sock",
                                   "--press", "1@0.1:0.2"});
    EXPECT_EQ(remote.code, kExitUsage) << remote.err;
    EXPECT_NE(remote.err.find("--press needs a simulated device"), std::string::npos) << remote.err;
    const Result lacking = run_cli({"play", file_, "--sensation", "gun", "--device", "wheel", "--press",
                                    "hat1:up@0.1:0.2"});
    EXPECT_EQ(lacking.code, kExitUsage) << lacking.err;
    EXPECT_NE(lacking.err.find("wheel"), std::string::npos) << lacking.err;
}

// Without --seconds, play runs until the last reflex's effect has ended: button 1 held
// from 0.1 s to 0.75 s starts the gun at 0.1, 0.4 and 0.7 s (repeat 300 ms), and the last
// 100 ms tap ends at 0.8 s. Nothing plays before the first press (the reflex waits for it,
// as in render), so the peak is at a press.
TEST_F(Press, PlayWithoutSecondsEndsWhenTheLastReflexHasEnded) {
    const Result r = run_cli({"play", file_, "--sensation", "gun", "--device", "sim:wheel", "--press", "1@0.1:0.75"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    EXPECT_NE(r.out.find("until      every effect has stopped after the last release at 0.750 s"), std::string::npos)
        << r.out;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(ended      after ([0-9.]+) s)"))) << r.out;
    const double last_end_s = 0.7 + static_cast<double>(kTapUs) * 1e-6;
    EXPECT_GE(std::stod(m[1].str()), last_end_s - 0.01) << r.out;
    EXPECT_LT(std::stod(m[1].str()), last_end_s + 0.4) << r.out;  // the host's clock and queues, under load
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(\nx +[-+][0-9]+\.[0-9] +([0-9.]+) s)"))) << r.out;
    EXPECT_GE(std::stod(m[1].str()), 0.1 - 0.01) << r.out;
}

// A sensation that never ends is stopped 10 s (kPlayDefaultCapS) after the last release,
// not 10 s after the start: a schedule is never cut short.
TEST_F(Press, PlayStopsAnEndlessSensationTenSecondsAfterTheLastRelease) {
    format::SensationFile file = trigger_file();
    file.sensations.resize(1);
    file.sensations[0].effects[0].params.duration_us = kInfiniteUs;
    file.sensations[0].effects[0].params.trigger_repeat_interval_us = 0;
    const std::string endless = path("endless.feel.json");
    write(endless, format::write_sensation_file(file));
    const Result r = run_cli({"play", endless, "--device", "sim:wheel", "--press", "1@0.05:0.3"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    EXPECT_NE(r.out.find("limit      10.300 s"), std::string::npos) << r.out;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(stopped    after ([0-9.]+) s)"))) << r.out;
    EXPECT_GE(std::stod(m[1].str()), 0.3 + kPlayDefaultCapS) << r.out;
    EXPECT_LT(std::stod(m[1].str()), 0.3 + kPlayDefaultCapS + 0.4) << r.out;
}

// The summary's peak is at least every force a live line showed (the first report too).
TEST_F(Press, PlaysPeakIsAtLeastEveryForceTheLiveLinesShowed) {
    format::SensationFile one = trigger_file();
    one.sensations.resize(1);
    one.sensations[0].effects[0].params.trigger = {};
    one.sensations[0].effects[0].params.trigger_repeat_interval_us = 0;
    one.sensations[0].effects[0].params.duration_us = 400'000;
    const std::string single = path("single.feel.json");
    write(single, format::write_sensation_file(one));
    const Result r = run_cli({"play", single, "--device", "wheel"});
    ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
    double shown = 0;
    int lines = 0;
    for (const std::string& line : lines_of(r.out)) {
        std::smatch m;
        if (std::regex_search(line, m, std::regex(R"(^[0-9]+\.[0-9]{3} s   x +([-+][0-9]+\.[0-9]))"))) {
            shown = std::max(shown, std::fabs(std::stod(m[1].str())));
            ++lines;
        }
    }
    ASSERT_GE(lines, 2) << r.out;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(\nx +([-+][0-9]+\.[0-9]))"))) << r.out;
    EXPECT_GE(std::fabs(std::stod(m[1].str())), shown) << r.out;
    EXPECT_NEAR(std::fabs(std::stod(m[1].str())), kMagnitude, 5) << r.out;
}

}  // namespace
}  // namespace feel::cli::testing
