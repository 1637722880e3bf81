// A fixture for CLI tests: a scratch directory, sensation files written through the
// format library (so the tests do not depend on the file syntax), and run() with captured
// streams.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::cli::testing {

namespace fs = std::filesystem;

struct Result {
    int code = -1;
    std::string out;
    std::string err;
};

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               (std::string("feel_cli_test_") + info->test_suite_name() + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static Result run_cli(std::initializer_list<std::string> args) {
        std::vector<std::string> argv{"feel"};
        argv.insert(argv.end(), args.begin(), args.end());
        std::ostringstream out, err;
        Result r;
        r.code = run(argv, out, err);
        r.out = out.str();
        r.err = err.str();
        return r;
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    static void write(const std::string& p, const std::string& text) {
        std::ofstream(p, std::ios::binary) << text;
    }

    static std::vector<std::string> lines_of(const std::string& text) {
        std::vector<std::string> out;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) out.push_back(line);
        return out;
    }

    fs::path dir_;
};

// push_west: a vector force of magnitude 4321 and gain 5000 from polar 9000, 200 ms.
// hum: an endless sine on x. pair: a compound of two constants on x and y, the second
// delayed. kick: a dynamic_recoil on x and y.
inline format::SensationFile sample_file() {
    format::SensationFile file;

    EffectParams push;
    push.type = EffectType::vector_force;
    push.duration_us = 200'000;
    push.gain = 5000;
    push.axis_count = 2;
    push.direction.kind = DirectionKind::polar;
    push.direction.value[0] = 9000;
    push.constant.magnitude = 4321;
    file.sensations.push_back({"push_west", "a steady push to the left", false, {{push, {}, {}}}});

    EffectParams hum;
    hum.type = EffectType::sine;
    hum.duration_us = kInfiniteUs;
    hum.axis_count = 1;
    hum.periodic.magnitude = 3000;
    // 23 ms: no divisor of `feel monitor`'s 200 ms, so its samples cannot all fall on the
    // sine's zeros (a 20 ms period did, whenever the effect started on a sample's phase).
    hum.periodic.period_us = 23'000;
    file.sensations.push_back({"hum", std::nullopt, false, {{hum, {}, {}}}});

    EffectParams a;
    a.type = EffectType::constant;
    a.duration_us = 100'000;
    a.axis_count = 1;
    a.constant.magnitude = 2000;
    EffectParams b = a;
    b.axes[0] = Axis::y;
    b.start_delay_us = 150'000;
    file.sensations.push_back({"pair", "two taps", true, {{a, {}, {}}, {b, {}, {}}}});

    EffectParams kick;
    kick.type = EffectType::dynamic_recoil;
    kick.duration_us = 300'000;
    kick.axis_count = 2;
    kick.dynamic.blast_direction = 9000;
    kick.dynamic.blast_intensity = 6000;
    kick.dynamic.dynamic_mass = 2000;
    kick.dynamic.blast_resonance = 3000;
    kick.dynamic.blast_decay = 2000;
    file.sensations.push_back({"kick", std::nullopt, false, {{kick, {}, {}}}});
    return file;
}

}  // namespace feel::cli::testing
