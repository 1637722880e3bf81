// feel check, feel devices, --help and --version.
#include <string>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

using Check = CliTest;

TEST_F(Check, AValidFileListsEverySensationWithItsTypeDurationAndAxes) {
    const std::string file = path("effects.feel.json");
    write(file, format::write_sensation_file(sample_file()));
    const Result r = run_cli({"check", file});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(r.err, "");
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 2u + 4u) << r.out;  // a verdict, a header, one line per sensation
    EXPECT_NE(lines[0].find("valid, 4 sensations"), std::string::npos) << lines[0];

    const auto line_of = [&](const std::string& name) {
        for (const std::string& l : lines) {
            if (l.rfind(name + " ", 0) == 0) return l;
        }
        return std::string();
    };
    const std::string push = line_of("push_west");
    EXPECT_NE(push.find("vector_force"), std::string::npos) << push;
    EXPECT_NE(push.find("200 ms"), std::string::npos) << push;
    EXPECT_NE(push.find("x,y"), std::string::npos) << push;
    EXPECT_NE(push.find("a steady push to the left"), std::string::npos) << push;

    const std::string hum = line_of("hum");
    EXPECT_NE(hum.find("sine"), std::string::npos) << hum;
    EXPECT_NE(hum.find("endless"), std::string::npos) << hum;

    // The compound ends when its delayed second tap does: 150 ms + 100 ms.
    const std::string pair = line_of("pair");
    EXPECT_NE(pair.find("compound of 2"), std::string::npos) << pair;
    EXPECT_NE(pair.find("250 ms"), std::string::npos) << pair;
    EXPECT_NE(pair.find("x,y"), std::string::npos) << pair;

    EXPECT_NE(line_of("kick").find("dynamic_recoil"), std::string::npos);
}

TEST_F(Check, AnInvalidFileFailsWithTheReadersMessageNamingTheField) {
    std::string text = format::write_sensation_file(sample_file());
    const size_t at = text.find("4321");
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, 4, "40000");  // push_west's magnitude, beyond ±10000
    const std::string file = path("bad.feel.json");
    write(file, text);

    const Result r = run_cli({"check", file});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("magnitude"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("40000"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("push_west"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("10000"), std::string::npos) << r.err;
}

TEST_F(Check, AMissingFileFailsNamingIt) {
    const std::string file = path("nowhere.feel.json");
    const Result r = run_cli({"check", file});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_NE(r.err.find("nowhere.feel.json"), std::string::npos) << r.err;
}

TEST_F(Check, WithoutAFileIsAUsageError) {
    const Result r = run_cli({"check"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("FILE"), std::string::npos) << r.err;
}

TEST_F(CliTest, DevicesListsEveryProfile) {
    const Result r = run_cli({"devices"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    for (const char* name : {"joystick", "wheel", "3axis"}) {
        EXPECT_NE(r.out.find(name), std::string::npos) << r.out;
    }
}

TEST_F(CliTest, VersionPrintsTheProjectVersion) {
    const Result r = run_cli({"--version"});
    EXPECT_EQ(r.code, kExitOk);
    EXPECT_EQ(r.out, std::string("feel ") + FEEL_TEST_VERSION + "\n");
}

TEST_F(CliTest, HelpListsTheCommands) {
    const Result r = run_cli({"--help"});
    EXPECT_EQ(r.code, kExitOk);
    for (const char* word : {"render", "check", "devices"}) {
        EXPECT_NE(r.out.find(word), std::string::npos) << r.out;
    }
}

TEST_F(CliTest, EachCommandHasHelp) {
    const Result render = run_cli({"render", "--help"});
    EXPECT_EQ(render.code, kExitOk);
    for (const char* flag : {"--sensation", "--device", "--motion", "--hand", "--duration",
                             "--rate", "--output", "--plot"}) {
        EXPECT_NE(render.out.find(flag), std::string::npos) << flag << " in\n" << render.out;
    }
    const Result check = run_cli({"check", "--help"});
    EXPECT_EQ(check.code, kExitOk);
    EXPECT_NE(check.out.find("FILE"), std::string::npos) << check.out;
}

TEST_F(CliTest, NoCommandOrAnUnknownOneIsAUsageError) {
    const Result none = run_cli({});
    EXPECT_EQ(none.code, kExitUsage);
    EXPECT_FALSE(none.err.empty());
    const Result unknown = run_cli({"frobnicate"});
    EXPECT_EQ(unknown.code, kExitUsage);
    EXPECT_NE(unknown.err.find("frobnicate"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace feel::cli::testing
