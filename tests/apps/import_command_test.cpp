// feel import: a real DirectX 7 SDK file (tests/import/data/ORIGIN.md) becomes a sensation
// file that `feel check` accepts; its notes go to standard error; mistakes exit 1 or 2.
#include <string>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

using Import = CliTest;

const std::string kSliding = std::string(FEEL_SOURCE_DIR) + "/tests/import/data/sliding.ffe";

TEST_F(Import, ARealEffectFileBecomesACheckedSensationFile) {
    const std::string out = path("sliding.feel.json");
    const Result r = run_cli({"import", kSliding, "-o", out, "--name", "slide"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_NE(r.out.find("sensation \"slide\" (2 effects)"), std::string::npos) << r.out;
    // Force Editor's conditions have saturation 0: said, not changed.
    EXPECT_NE(r.err.find("note: effect 1 \"Friction2D2\": DICONDITION[0] has both saturations 0"), std::string::npos)
        << r.err;
    const format::SensationFile f = format::load_sensation_file(out);
    ASSERT_NE(f.find("slide"), nullptr);
    EXPECT_EQ(f.find("slide")->effects.size(), 2u);
    EXPECT_EQ(run_cli({"check", out}).code, kExitOk);
}

TEST_F(Import, MistakesAreNamed) {
    const Result axis = run_cli({"import", kSliding, "-o", path("a.json"), "--axis", "w"});
    EXPECT_EQ(axis.code, kExitUsage);
    EXPECT_NE(axis.err.find("--axis w is not an axis (allowed x, y, z, rx, ry, rz)"), std::string::npos) << axis.err;
    const std::string junk = path("junk.bin");
    write(junk, "not a known format");
    const Result unknown = run_cli({"import", junk, "-o", path("b.json")});
    EXPECT_EQ(unknown.code, kExitFailure);
    EXPECT_NE(unknown.err.find("unknown format"), std::string::npos) << unknown.err;
    const Result missing = run_cli({"import", path("none.ffe"), "-o", path("c.json")});
    EXPECT_EQ(missing.code, kExitFailure);
    EXPECT_NE(missing.err.find("none.ffe: cannot be read"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace feel::cli::testing
