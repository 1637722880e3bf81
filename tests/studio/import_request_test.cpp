// The Studio's import_file (src/studio/import_request.cpp): base64 from the browser, the
// importer, a new workspace file. The base64 below was made by Python's base64 module from
// the AHAP text beside it, so the decoder is checked against an outside encoder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "import_request.hpp"
#include "workspace.hpp"

namespace feel::studio {
namespace {

namespace fs = std::filesystem;

// {"Pattern": [{"Event": {"Time": 0.5, "EventType": "HapticTransient", "EventParameters":
//   [{"ParameterID": "HapticIntensity", "ParameterValue": 0.25}]}}]}
constexpr const char* kAhapBase64 =
    "eyJQYXR0ZXJuIjogW3siRXZlbnQiOiB7IlRpbWUiOiAwLjUsICJFdmVudFR5cGUiOiAiSGFwdGljVHJhbnNpZW50IiwgIkV2ZW50UGFyYW1l"
    "dGVycyI6IFt7IlBhcmFtZXRlcklEIjogIkhhcHRpY0ludGVuc2l0eSIsICJQYXJhbWV0ZXJWYWx1ZSI6IDAuMjV9XX19XX0=";

class ImportRequest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("feel-import-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

std::string error_of(Workspace& ws, const nlohmann::json& m) {
    try {
        (void)import_into_workspace(ws, m);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

TEST_F(ImportRequest, AhapBecomesANewWorkspaceFileOnTheChosenAxis) {
    Workspace ws(root_);
    const nlohmann::json m = {{"type", "import_file"}, {"name", "tap.ahap"}, {"data", kAhapBase64}, {"axis", "y"}};
    const nlohmann::json answer = import_into_workspace(ws, m);
    EXPECT_EQ(answer["type"], "imported");
    EXPECT_EQ(answer["file"], "tap.feel.json");
    EXPECT_EQ(answer["sensation"], "tap");
    const nlohmann::json saved = nlohmann::json::parse(std::ifstream(root_ / "tap.feel.json"));
    const nlohmann::json& s = saved["sensations"]["tap"];
    EXPECT_EQ(s["type"], "sine");
    EXPECT_EQ(s["axes"], nlohmann::json::array({"y"}));
    EXPECT_EQ(s["start_delay_us"], 500000);
    EXPECT_EQ(s["periodic"]["magnitude"], 2500);
    // The same name again: a free one, never an overwrite.
    EXPECT_EQ(import_into_workspace(ws, m)["file"], "tap_2.feel.json");
}

TEST_F(ImportRequest, RefusalsSayWhy) {
    Workspace ws(root_);
    EXPECT_NE(error_of(ws, {{"name", "a.ahap"}, {"data", "abc"}}).find("not a multiple of 4"), std::string::npos);
    EXPECT_NE(error_of(ws, {{"name", "a.ahap"}, {"data", "ab!d"}}).find("character 2 is not one of"), std::string::npos);
    EXPECT_NE(error_of(ws, {{"name", "a.ahap"}, {"data", "a=bc"}}).find("character 1"), std::string::npos);
    // "e30=" is "{}": an AHAP file without a pattern.
    EXPECT_NE(error_of(ws, {{"name", "a.ahap"}, {"data", "e30="}}).find("\"Pattern\" is missing"), std::string::npos);
    EXPECT_TRUE(fs::is_empty(root_));
}

}  // namespace
}  // namespace feel::studio
