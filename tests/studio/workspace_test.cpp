// The workspace's path rules (docs/studio.md, "Safety"): every refusal, and the file
// operations that stay inside.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "feel/format/sensation_file.hpp"
#include "workspace.hpp"

namespace feel::studio {
namespace {
namespace fs = std::filesystem;

constexpr const char* kSpringFile = R"({"format": "feel/1", "sensations": {"s": {"type": "spring", "duration_us": "infinite",
  "axes": ["x"], "conditions": [{"pos_coefficient": 5000, "neg_coefficient": 5000}]}}})";

class WorkspaceTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("feel-ws-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                             "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        fs::create_directories(root_ / "inside");
        outside_ = root_.string() + "-outside";
        fs::create_directories(outside_);
        std::ofstream(outside_ / "secret.feel.json") << kSpringFile;
    }
    void TearDown() override {
        fs::remove_all(root_);
        fs::remove_all(outside_);
    }
    fs::path root_, outside_;
};

void expect_refused(const std::function<void()>& f, const std::string& words) {
    try {
        f();
        FAIL() << "not refused";
    } catch (const WorkspaceError& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST_F(WorkspaceTest, RefusesDotDotAbsoluteAndOddNames) {
    Workspace ws(root_);
    expect_refused([&] { (void)ws.read("../x.feel.json"); }, "'..'");
    expect_refused([&] { (void)ws.read("inside/../../x.feel.json"); }, "'..'");
    expect_refused([&] { (void)ws.read(outside_.string() + "/secret.feel.json"); }, "absolute");
    expect_refused([&] { (void)ws.read("a//b.feel.json"); }, "empty components");
    expect_refused([&] { (void)ws.read("x.json"); }, "*.feel.json");
    expect_refused([&] { (void)ws.read("x\n.feel.json"); }, "only letters");
    expect_refused([&] { (void)ws.read(""); }, "empty");
    expect_refused([&] { (void)ws.read(std::string(300, 'a') + ".feel.json"); }, "longer than 200");
    expect_refused([&] { (void)ws.read("missing.feel.json"); }, "no such file");
}

TEST_F(WorkspaceTest, RefusesSymlinksThatLeadOut) {
    fs::create_directory_symlink(outside_, root_ / "link");
    fs::create_symlink(outside_ / "secret.feel.json", root_ / "secret.feel.json");
    Workspace ws(root_);
    expect_refused([&] { (void)ws.read("link/secret.feel.json"); }, "leads out of the workspace");
    expect_refused([&] { (void)ws.read("secret.feel.json"); }, "leads out of the workspace");
    expect_refused([&] { (void)ws.save("link/new.feel.json", kSpringFile, false); }, "leads out of the workspace");
    EXPECT_TRUE(ws.list().empty());  // the links that lead out are not listed
    EXPECT_FALSE(fs::exists(outside_ / "new.feel.json"));
}

TEST_F(WorkspaceTest, SavesOnlyValidFilesInCanonicalFormAndBoundsSizes) {
    Workspace ws(root_);
    const std::string canonical = ws.save("inside/a.feel.json", kSpringFile, false);
    // The format's own writer is the reference for the canonical form.
    EXPECT_EQ(canonical, format::write_sensation_file(format::parse_sensation_file(kSpringFile, "t")));
    EXPECT_EQ(ws.read("inside/a.feel.json"), canonical);
    expect_refused([&] { (void)ws.save("inside/a.feel.json", kSpringFile, false); }, "already exists");
    EXPECT_THROW((void)ws.save("b.feel.json", R"({"format": "feel/1", "sensations": {}})", false), format::FormatError);
    EXPECT_FALSE(fs::exists(root_ / "b.feel.json"));
    expect_refused([&] { (void)ws.save("big.feel.json", std::string(kMaxFileBytes + 1, ' '), false); }, "limit");
    std::ofstream(root_ / "huge.feel.json") << std::string(kMaxFileBytes + 1, ' ');
    expect_refused([&] { (void)ws.read("huge.feel.json"); }, "limit");
}

TEST_F(WorkspaceTest, RenamesCopiesAndCombines) {
    Workspace ws(root_);
    (void)ws.save("a.feel.json", kSpringFile, false);
    ws.rename("a.feel.json", "inside/b.feel.json");
    EXPECT_EQ(ws.list(), std::vector<std::string>{"inside/b.feel.json"});
    const std::string other = R"({"format": "feel/1", "sensations": {"t": {"type": "sine", "duration_us": 1000,
      "axes": ["x"], "periodic": {"magnitude": 100, "period_us": 1000}}}})";
    (void)ws.save("c.feel.json", other, false);
    const std::string combined = ws.combine({"inside/b.feel.json", "c.feel.json"}, "both.feel.json");
    const format::SensationFile f = format::parse_sensation_file(combined, "both");
    ASSERT_EQ(f.sensations.size(), 2u);
    EXPECT_EQ(f.sensations[0].name, "s");
    EXPECT_EQ(f.sensations[1].name, "t");
    expect_refused([&] { (void)ws.combine({"c.feel.json", "c.feel.json"}, "twice.feel.json"); }, "is in both");
}

}  // namespace
}  // namespace feel::studio
