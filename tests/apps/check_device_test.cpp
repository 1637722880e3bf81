// feel check --device: a file valid by the format is also judged by a device's limits,
// given by the profiles' documented capabilities (docs/simulated-device.md): the wheel has
// no hat, an I-FORCE 1.x-class device plays no dynamics and holds 16 effects (§1.3).
#include <string>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

EffectParams tap() {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = 100'000;
    p.axis_count = 1;
    p.constant.magnitude = 3000;
    return p;
}

// tap: plays anywhere. horn: triggered by hat 2. seventeen: a compound of 17 taps.
format::SensationFile device_file() {
    format::SensationFile file;
    file.sensations.push_back({"tap", std::nullopt, false, {{tap(), {}, {}}}});
    EffectParams horn = tap();
    horn.trigger = Trigger{TriggerKind::hat, 2};
    file.sensations.push_back({"horn", std::nullopt, false, {{horn, {}, {}}}});
    format::Sensation many{"seventeen", std::nullopt, true, {}};
    for (int i = 0; i < 17; ++i) many.effects.push_back({tap(), {}, {}});
    file.sensations.push_back(many);
    return file;
}

// The last line starting with `prefix` (a sensation's verdict comes after its table row).
std::string line_starting(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    std::string found;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(prefix, 0) == 0) found = line;
    }
    return found;
}

class CheckDevice : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        file_ = path("device.feel.json");
        write(file_, format::write_sensation_file(device_file()));
    }
    std::string file_;
};

TEST_F(CheckDevice, EverySensationPlaysOnAnIforce2) {
    const Result r = run_cli({"check", file_, "--device", "sim:iforce2"});
    EXPECT_EQ(r.code, kExitOk) << r.err << r.out;
    for (const char* name : {"tap ", "horn ", "seventeen "}) {
        EXPECT_NE(line_starting(r.out, name).find("plays"), std::string::npos) << name << r.out;
    }
}

TEST_F(CheckDevice, AHatTheWheelLacksIsNamed) {
    const Result r = run_cli({"check", file_, "--device", "wheel"});
    EXPECT_EQ(r.code, kExitFailure) << r.out;
    EXPECT_NE(line_starting(r.out, "tap ").find("plays"), std::string::npos) << r.out;
    const std::string horn = line_starting(r.out, "horn ");
    EXPECT_NE(horn.find("does not play"), std::string::npos) << r.out;
    EXPECT_NE(horn.find("hat"), std::string::npos) << horn;
    EXPECT_NE(r.err.find("do not play on wheel"), std::string::npos) << r.err;
}

TEST_F(CheckDevice, SeventeenEffectsDoNotFitAnIforce1sSixteenSlots) {
    const Result r = run_cli({"check", file_, "--device", "iforce1"});
    EXPECT_EQ(r.code, kExitFailure) << r.out;
    EXPECT_NE(line_starting(r.out, "on sim:iforce1").find("16 effect slots"), std::string::npos) << r.out;
    EXPECT_NE(line_starting(r.out, "tap ").find("plays"), std::string::npos) << r.out;
    EXPECT_NE(line_starting(r.out, "seventeen ").find("does not play"), std::string::npos) << r.out;
}

TEST_F(CheckDevice, AnUnknownDeviceIsAUsageError) {
    const Result r = run_cli({"check", file_, "--device", "pedals"});
    EXPECT_EQ(r.code, kExitUsage) << r.out;
    EXPECT_NE(r.err.find("pedals"), std::string::npos) << r.err;
}

// Help footers list the codes each command can return: `devices` cannot fail once its
// command line is right (unreachable sockets are skipped), the others name their failures.
TEST_F(CliTest, HelpFootersListTheExitCodesOfTheirCommand) {
    const Result devices = run_cli({"devices", "--help"});
    EXPECT_EQ(devices.code, kExitOk);
    EXPECT_NE(devices.out.find("Exit codes: 0 success, 2 usage error"), std::string::npos) << devices.out;
    const Result check = run_cli({"check", "--help"});
    EXPECT_NE(check.out.find("1 failure (an unreadable or invalid file; with --device"), std::string::npos)
        << check.out;
    const Result render = run_cli({"render", "--help"});
    EXPECT_NE(render.out.find("1 failure (an unreadable or invalid file, a sensation the engine refuses"),
              std::string::npos)
        << render.out;
}

}  // namespace
}  // namespace feel::cli::testing
