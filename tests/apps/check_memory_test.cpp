// Files cannot exhaust memory: `feel check`'s peak resident memory on the files of the
// audit (issue 17) stays within 4 × the file's size plus a constant.
//
// The measure is the kernel's: `feel check` runs as a child process (posix_spawn) and
// wait4() returns its ru_maxrss, the high-water mark of its resident set. Linux carries
// the spawning process's high-water mark over exec into the child's, so this test keeps
// its own memory small (files are written in chunks of at most a few hundred KB): what it
// adds can only make the figure larger, never hide feel's. The constant is `feel check`'s own peak on a one-line file
// (its code and libraries), measured here too, plus 16 MiB: the most that one sensation's
// tree can take (json_document.hpp: 69631 values of about 100 bytes, and a vector's
// growth). Figures are printed for docs/sensation-format.md; the bound is asserted.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/sanitizers.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

constexpr double kMiB = 1024.0 * 1024.0;

struct CheckRun {
    int code = -1;
    double peak_bytes = 0;  // ru_maxrss
    std::string output;     // stdout and stderr
};

CheckRun feel_check(const fs::path& file) {
    const fs::path log = file.string() + ".out";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::string exe = FEEL_EXECUTABLE, command = "check", path = file.string();
    char* argv[] = {exe.data(), command.data(), path.data(), nullptr};
    pid_t pid = 0;
    CheckRun r;
    const int spawned = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
        ADD_FAILURE() << "cannot run " << exe;
        return r;
    }
    int status = 0;
    rusage usage{};
    if (::wait4(pid, &status, 0, &usage) != pid) {
        ADD_FAILURE() << "wait4 failed";
        return r;
    }
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.peak_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux: KiB
    // The start of the output only: a valid file's listing holds its descriptions.
    std::ifstream in(log, std::ios::binary);
    r.output.resize(64 * 1024);
    in.read(r.output.data(), static_cast<std::streamsize>(r.output.size()));
    r.output.resize(static_cast<size_t>(in.gcount()));
    return r;
}

class CheckMemory : public ::testing::Test {
protected:
    void SetUp() override {
        FEEL_SKIP_UNDER_SANITIZER("peak memory is the sanitizer's (shadow memory, quarantine), not feel's");
        dir_ = fs::temp_directory_path() /
               ("feel_check_memory_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        const fs::path tiny = dir_ / "tiny.json";
        std::ofstream(tiny) << R"({"format": "feel/1", "sensations": {"c": )" << kConstant << "}}";
        const CheckRun base = feel_check(tiny);
        ASSERT_EQ(base.code, 0) << base.output;
        baseline_ = base.peak_bytes;
    }
    void TearDown() override {
        if (!dir_.empty()) fs::remove_all(dir_);
    }

    // Runs feel check on `file` (written by the caller), asserts the bound, prints the figure.
    CheckRun measure(const fs::path& file, const char* what) {
        const double size = static_cast<double>(fs::file_size(file));
        const CheckRun r = feel_check(file);
        const double allowed = 4 * size + baseline_ + 16 * kMiB;
        std::printf("feel check, %s: file %.1f MiB, peak %.1f MiB (%.2f x the file; baseline %.1f MiB)\n", what,
                    size / kMiB, r.peak_bytes / kMiB, (r.peak_bytes - baseline_) / size, baseline_ / kMiB);
        EXPECT_LE(r.peak_bytes, allowed) << what << ": peak " << r.peak_bytes / kMiB << " MiB, allowed 4 x "
                                         << size / kMiB << " MiB + " << (baseline_ + 16 * kMiB) / kMiB << " MiB";
        return r;
    }

    static constexpr const char* kConstant =
        R"({"type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}})";
    fs::path dir_;
    double baseline_ = 0;
};

TEST_F(CheckMemory, ASixtyMegabyteFileOfForceProfiles) {
    // A valid file just under 64 MiB: 457 force profiles of 65535 one-digit samples, the
    // densest a file can be in samples (2 bytes of text each, 2 bytes in the model).
    const fs::path file = dir_ / "profiles.json";
    std::string samples;
    for (int i = 0; i < 65535; ++i) samples += (i ? "," : "") + std::to_string(i * 7 % 10);
    {
        std::ofstream out(file, std::ios::binary);
        out << R"({"format": "feel/1", "sensations": {)";
        for (int s = 0; s < 457; ++s) {
            out << (s ? ",\n" : "\n") << "\"p" << s << R"(": {"type": "force_profile", "duration_us": 1000000, )"
                << R"("axes": ["x"], "custom": {"sample_period_us": 1000, "samples": [)" << samples << "]}}";
        }
        out << "}}\n";
    }
    ASSERT_GT(fs::file_size(file), 58'000'000u);
    const CheckRun r = measure(file, "60 MB of force profiles (valid)");
    EXPECT_EQ(r.code, 0) << r.output.substr(0, 300);
    EXPECT_NE(r.output.find(": valid, 457 sensations"), std::string::npos) << r.output.substr(0, 300);
}

TEST_F(CheckMemory, ASixtyMegabyteDescription) {
    const fs::path file = dir_ / "description.json";
    {
        std::ofstream out(file, std::ios::binary);
        out << R"({"format": "feel/1", "sensations": {"d": {"description": ")";
        const std::string chunk(100'000, 'd');
        for (int i = 0; i < 600; ++i) out << chunk;
        out << R"(", "type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}}}})";
    }
    const CheckRun r = measure(file, "a 60 MB description (valid)");
    EXPECT_EQ(r.code, 0) << r.output.substr(0, 300);
}

TEST_F(CheckMemory, SevenMillionEmptyObjects) {
    // 7.4 M empty objects as the effects of a compound (the audit's 823 MB): refused at the first.
    const fs::path file = dir_ / "empty_objects.json";
    {
        std::ofstream out(file, std::ios::binary);
        out << R"({"format": "feel/1", "sensations": {"hum": {"effects": [{})";
        const std::string block = [] {
            std::string b;
            for (int i = 0; i < 100'000; ++i) b += ",{}";
            return b;
        }();
        for (int i = 0; i < 74; ++i) out << block;
        out << "]}}}";
    }
    const CheckRun r = measure(file, "7.4 M empty objects");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.output.find(R"(sensation "hum": effects[0].type: required field is missing)"), std::string::npos)
        << r.output;
}

TEST_F(CheckMemory, AForceProfileOfThreeMillionSamples) {
    // The audit's 411 MB before being refused: now refused at the 65536th sample.
    const fs::path file = dir_ / "long_profile.json";
    {
        std::ofstream out(file, std::ios::binary);
        out << R"({"format": "feel/1", "sensations": {"long": {"type": "force_profile", "duration_us": 1000000, )"
            << R"("axes": ["x"], "custom": {"sample_period_us": 1000, "samples": [0)";
        const std::string block = [] {
            std::string b;
            for (int i = 0; i < 100'000; ++i) b += ",1";
            return b;
        }();
        for (int i = 0; i < 30; ++i) out << block;
        out << "]}}}}";
    }
    const CheckRun r = measure(file, "a force profile of 3 M samples");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.output.find(R"(sensation "long": custom.samples: more than 65535 samples (allowed 1..65535))"),
              std::string::npos)
        << r.output;
}

}  // namespace
