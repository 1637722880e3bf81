// The built `feel` binary itself: exit codes as the shell sees them, real stdout/stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace {

struct Process {
    int code = -1;
    std::string out;  // stdout, with stderr discarded or merged as the command says
};

Process shell(const std::string& command) {
    Process r;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return r;
    std::array<char, 4096> buf{};
    while (size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) r.out.append(buf.data(), n);
    const int status = ::pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

const std::string kFeel = std::string("'") + FEEL_EXECUTABLE + "'";

TEST(FeelBinary, VersionExitsZero) {
    const Process r = shell(kFeel + " --version 2>/dev/null");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out, std::string("feel ") + FEEL_TEST_VERSION + "\n");
}

TEST(FeelBinary, ABadFlagExitsTwoWithTheFlagOnStderr) {
    const Process r = shell(kFeel + " check --frobnicate 2>&1 >/dev/null");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("--frobnicate"), std::string::npos) << r.out;
}

TEST(FeelBinary, AMissingFileExitsOne) {
    const Process r = shell(kFeel + " check /nonexistent/feel/file.json 2>&1");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find("/nonexistent/feel/file.json"), std::string::npos) << r.out;
}

}  // namespace
