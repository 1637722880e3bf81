// feel export: the flags and their errors (the generated code itself: tests/codegen).
#include <string>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

using Export = CliTest;

TEST_F(Export, WritesTheSameCodeToAFileAsToStandardOutput) {
    const std::string file = path("effects.feel.json");
    write(file, format::write_sensation_file(sample_file()));
    const Result shown = run_cli({"export", file, "--lang", "cpp"});
    ASSERT_EQ(shown.code, kExitOk) << shown.err;
    for (const char* name : {"push_west", "hum", "pair", "kick"}) {
        EXPECT_NE(shown.out.find("create_" + std::string(name) + "(feel::host::Device& device)"), std::string::npos) << name;
    }
    const Result written = run_cli({"export", file, "--lang", "c", "--sensation", "hum", "-o", path("hum.c")});
    ASSERT_EQ(written.code, kExitOk) << written.err;
    EXPECT_EQ(written.out, "");
    const std::string c = read(path("hum.c"));
    EXPECT_NE(c.find("create_hum(feel_device* device)"), std::string::npos);
    EXPECT_EQ(c.find("create_pair"), std::string::npos) << "only the sensation asked for";
}

TEST_F(Export, RefusesWhatItCannotDo) {
    const std::string file = path("effects.feel.json");
    write(file, format::write_sensation_file(sample_file()));
    Result r = run_cli({"export", file, "--lang", "rust"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_EQ(r.err, "feel export: error: --lang \"rust\" is not a language (allowed: cpp, c, library)\n");
    r = run_cli({"export", file, "--lang", "cpp", "--sensation", "nope"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_EQ(r.err, "feel export: error: export: no sensation \"nope\" in " + file +
                         " (it has: push_west, hum, pair, kick)\n");
    r = run_cli({"export", file, "--lang", "library"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_EQ(r.err, "feel export: error: --lang library plays one sensation: give exactly one --sensation (" + file +
                         " has: push_west, hum, pair, kick)\n");
    r = run_cli({"export", path("missing.feel.json"), "--lang", "c"});
    EXPECT_EQ(r.code, kExitFailure);
    r = run_cli({"export", file, "--lang", "c", "-o", path("no/such/dir/x.c")});
    EXPECT_EQ(r.code, kExitFailure);
    EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace feel::cli::testing
