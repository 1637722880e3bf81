// feel bench loop: its flags are checked before anything runs, and a short run ends with
// the one summary line the README quotes, whose counts add up to seconds × rate.
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

using BenchLoop = CliTest;

TEST_F(BenchLoop, OutOfRangeFlagsNameTheFlagAndTheRange) {
    struct Case {
        std::vector<std::string> extra;
        const char* flag;
        const char* range;
    };
    const Case cases[] = {
        {{"--rate", "99"}, "--rate", "100..20000"},
        {{"--rate", "20001"}, "--rate", "100..20000"},
        {{"--rate", "1000.5"}, "--rate", "whole number"},
        {{"--rate", "fast"}, "--rate", "fast"},
        {{"--seconds", "0.5"}, "--seconds", "1..3600"},
        {{"--seconds", "3601"}, "--seconds", "1..3600"},
        {{"--seconds", "nan"}, "--seconds", "1..3600"},
        {{"--cpu", "-2"}, "--cpu", "allowed -1 for any CPU"},
        {{"--cpu", "0.5"}, "--cpu", "allowed -1 for any CPU"},
        {{"--cpu", "4096"}, "--cpu", "this machine's CPUs"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> argv{"feel", "bench", "loop"};
        argv.insert(argv.end(), c.extra.begin(), c.extra.end());
        std::ostringstream out, err;
        EXPECT_EQ(run(argv, out, err), kExitUsage) << c.flag << ": " << err.str();
        EXPECT_NE(err.str().find("feel bench loop: error: "), std::string::npos) << err.str();
        EXPECT_NE(err.str().find(c.flag), std::string::npos) << err.str();
        EXPECT_NE(err.str().find(c.range), std::string::npos) << err.str();
        EXPECT_EQ(out.str(), "") << c.flag;
    }
}

TEST_F(BenchLoop, AMissingOrUnknownBenchmarkListsTheAvailableOnes) {
    const Result none = run_cli({"bench"});
    EXPECT_EQ(none.code, kExitUsage);
    EXPECT_NE(none.err.find("no benchmark given (available: loop)"), std::string::npos) << none.err;
    const Result unknown = run_cli({"bench", "tick"});
    EXPECT_EQ(unknown.code, kExitUsage);
    EXPECT_NE(unknown.err.find("unknown benchmark \"tick\" (available: loop)"), std::string::npos) << unknown.err;
}

TEST_F(BenchLoop, EndsWithTheSummaryLine) {
    const Result r = run_cli({"bench", "loop", "--seconds", "1", "--rate", "500"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    ASSERT_FALSE(r.out.empty());
    ASSERT_EQ(r.out.back(), '\n');
    const std::string last = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
    std::smatch m;
    const std::regex line(R"(p50=(\d+\.\d)us p99=(\d+\.\d)us p99\.9=(\d+\.\d)us overruns=(\d+) ticks=(\d+)\n)");
    ASSERT_TRUE(std::regex_match(last, m, line)) << last;
    EXPECT_LE(std::stod(m[1]), std::stod(m[2]));
    EXPECT_LE(std::stod(m[2]), std::stod(m[3]));
    // Ticks run plus ticks skipped by overruns are the 500 of one second at 500 Hz.
    const std::regex missed(R"(missed ticks=(\d+))");
    std::smatch mm;
    ASSERT_TRUE(std::regex_search(r.out, mm, missed)) << r.out;
    EXPECT_EQ(std::stol(m[5]) + std::stol(mm[1]), 500);
    EXPECT_EQ(std::stol(mm[1]) == 0, std::stol(m[4]) == 0);
    EXPECT_NE(r.out.find("scheduler: "), std::string::npos);
}

// --floor runs the same loop with an empty tick: same summary line, no effects, and the
// setup line says the loop is pinned when --cpu asks for it.
TEST_F(BenchLoop, TheFloorRunsTheSameLoopWithAnEmptyTick) {
    const Result r = run_cli({"bench", "loop", "--floor", "--seconds", "1", "--rate", "500", "--cpu", "0"});
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_NE(r.out.find("empty tick"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cpu: 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("effects playing at the end=0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("page faults of the loop thread during the run: minor="), std::string::npos) << r.out;
    const std::string last = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
    const std::regex line(R"(p50=(\d+\.\d)us p99=(\d+\.\d)us p99\.9=(\d+\.\d)us overruns=(\d+) ticks=(\d+)\n)");
    std::smatch m;
    ASSERT_TRUE(std::regex_match(last, m, line)) << last;
    const std::regex missed(R"(missed ticks=(\d+))");
    std::smatch mm;
    ASSERT_TRUE(std::regex_search(r.out, mm, missed)) << r.out;
    EXPECT_EQ(std::stol(m[5]) + std::stol(mm[1]), 500);
}

}  // namespace
}  // namespace feel::cli::testing
