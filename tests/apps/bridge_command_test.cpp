// `feel bridge`'s refusals before and at uinput: each says what is wrong and what to do. (The
// bridge itself is tested against the kernel in the VM: tests/linux.)
#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

class Bridge : public CliTest {};

TEST_F(Bridge, AMissingUinputSaysToLoadTheModule) {
    const Result r = run_cli({"bridge", "--uinput", path("uinput")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("is missing"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("modprobe uinput"), std::string::npos) << r.err;
}

TEST_F(Bridge, ANodeThatIsNotUinputIsRefusedByTheKernelNotACrash) {
    write(path("not-uinput"), "");
    const Result r = run_cli({"bridge", "--uinput", path("not-uinput")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("uinput: UI_SET_EVBIT"), std::string::npos) << r.err;
}

TEST_F(Bridge, CommandLineMistakesExitTwo) {
    Result r = run_cli({"bridge", "--device", "nosuch"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("unknown device profile \"nosuch\""), std::string::npos) << r.err;
    r = run_cli({"bridge", "--device", "tcp:localhost"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--device"), std::string::npos) << r.err;
    r = run_cli({"bridge", "--name", std::string(80, 'n')});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--name is 80 bytes long (allowed 0..79)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace feel::cli::testing
