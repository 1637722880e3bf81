// feel caps and the device classes on the command line: what a device reports through the
// host API (in process here; over sockets in device_process_test.cpp), and a render that
// the device's class refuses.
#include <sstream>
#include <string>

#include "cli_fixture.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli::testing {
namespace {

// The value of the line "KEY: value" of feel caps, "" when there is none.
class Caps : public CliTest {};

std::string value_of(const std::string& text, const std::string& key) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const size_t start = line.find_first_not_of(' ');
        if (start == std::string::npos || line.compare(start, key.size() + 1, key + ":") != 0) continue;
        const size_t value = line.find_first_not_of(' ', start + key.size() + 1);
        return value == std::string::npos ? "" : line.substr(value);
    }
    return "";
}

TEST_F(Caps, DefaultsToTheInProcessIforce2) {
    const Result r = run_cli({"caps"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(value_of(r.out, "device"), "iforce2") << r.out;
    EXPECT_EQ(value_of(r.out, "address"), "sim:iforce2") << r.out;
    EXPECT_EQ(value_of(r.out, "class"), "I-FORCE 2.0") << r.out;
    EXPECT_EQ(value_of(r.out, "effect types"), "33 of 33") << r.out;
    EXPECT_EQ(value_of(r.out, "effect slots"), "32") << r.out;
    EXPECT_EQ(value_of(r.out, "parameter memory"), "16384 bytes") << r.out;
    EXPECT_EQ(value_of(r.out, "local reflexes"), "yes") << r.out;
    EXPECT_EQ(value_of(r.out, "protocol"), "HID PID 1.0 + feel vendor 2") << r.out;
    EXPECT_EQ(value_of(r.out, "firmware"), "feel-sim 0.1.0") << r.out;
}

TEST_F(Caps, OfAnIforce1ListNoDynamicsFewerSlotsAndNoLocalReflexes) {
    const Result r = run_cli({"caps", "--device", "iforce1"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(value_of(r.out, "class"), "I-FORCE 1.x") << r.out;
    EXPECT_EQ(value_of(r.out, "effect slots"), "16") << r.out;
    EXPECT_EQ(value_of(r.out, "parameter memory"), "4096 bytes") << r.out;
    EXPECT_EQ(value_of(r.out, "Dynamics"), "none") << r.out;
    EXPECT_EQ(value_of(r.out, "effect types"), "25 of 33") << r.out;
    EXPECT_EQ(value_of(r.out, "local reflexes"), "no (the host emulates them)") << r.out;
    EXPECT_EQ(r.out.find("dynamic_"), std::string::npos) << r.out;
}

TEST_F(Caps, OfEveryProfileSucceeds) {
    for (const std::string name : {"joystick", "wheel", "3axis", "iforce1", "iforce2"}) {
        const Result r = run_cli({"caps", "--device", name});
        ASSERT_EQ(r.code, kExitOk) << name << ": " << r.err;
        EXPECT_EQ(value_of(r.out, "device"), name) << r.out;
        // The same device by its address, and what the runtime itself prints of the
        // profile: the protocol carried every line across.
        const Result by_address = run_cli({"caps", "--device", "sim:" + name});
        EXPECT_EQ(by_address.out, r.out);
        const sim::DeviceProfile& profile = *sim::find_device_profile(name);
        const auto expected = lines_of(runtime::format_capabilities(runtime::capabilities_for(profile)));
        const auto got = lines_of(r.out);
        ASSERT_GE(got.size(), expected.size()) << r.out;
        for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(got[i], expected[i]) << name;
    }
    EXPECT_EQ(value_of(run_cli({"caps", "--device", "3axis"}).out, "axes"), "3");
}

TEST_F(Caps, OfAnUnknownDeviceListsTheProfiles) {
    const Result r = run_cli({"caps", "--device", "iforce3"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("feel caps: error: --device \"iforce3\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("joystick, wheel, 3axis, iforce1, iforce2"), std::string::npos) << r.err;
    // Addresses that are not one of the forms.
    for (const char* bad : {"tcp:localhost", "tcp:127.0.0.1:99999", "unix:", "usb:1"}) {
        const Result form = run_cli({"caps", "--device", bad});
        EXPECT_EQ(form.code, kExitUsage) << bad;
        EXPECT_NE(form.err.find("feel caps: error: --device"), std::string::npos) << form.err;
        EXPECT_NE(form.err.find(bad), std::string::npos) << form.err;
    }
}

TEST_F(Caps, HasHelpAndIsListedAsACommand) {
    const Result help = run_cli({"caps", "--help"});
    EXPECT_EQ(help.code, kExitOk);
    EXPECT_NE(help.out.find("--device"), std::string::npos) << help.out;
    EXPECT_NE(run_cli({"--help"}).out.find("caps"), std::string::npos);
    const Result unknown = run_cli({"capz"});
    EXPECT_EQ(unknown.code, kExitUsage);
    EXPECT_NE(unknown.err.find("caps"), std::string::npos) << unknown.err;
}

TEST_F(Caps, RenderingADynamicOnAnIforce1IsRefusedNamingTheTypeAndTheClass) {
    const std::string file = path("effects.feel.json");
    write(file, format::write_sensation_file(sample_file()));
    const Result refused = run_cli({"render", file, "--sensation", "kick", "--device", "iforce1",
                                    "-o", path("kick.csv")});
    EXPECT_EQ(refused.code, kExitFailure);
    for (const char* word : {"kick", "dynamic_recoil", "not supported", "I-FORCE 1.x"}) {
        EXPECT_NE(refused.err.find(word), std::string::npos) << word << " in\n" << refused.err;
    }
    // A wave plays on it, and the same recoil plays on the 2.0 class.
    EXPECT_EQ(run_cli({"render", file, "--sensation", "hum", "--device", "iforce1", "--duration", "0.1",
                       "-o", path("hum.csv")}).code, kExitOk);
    const Result two = run_cli({"render", file, "--sensation", "kick", "--device", "iforce2", "-o",
                                path("kick2.csv")});
    EXPECT_EQ(two.code, kExitOk) << two.err;
}

}  // namespace
}  // namespace feel::cli::testing
