// write_plot(): SVG and PNG files, chosen by extension; clear errors otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "feel/render/render.hpp"

namespace feel::render {
namespace {

namespace fs = std::filesystem;

class Plot : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("feel_plot_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static std::string read(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    // A 2-axis trace: a decaying 20 Hz force on x, a slow drift on y.
    static Trace sample_trace(size_t rows) {
        Trace t;
        t.axis_count = 2;
        t.rate_hz = 1000;
        for (size_t n = 0; n < rows; ++n) {
            TraceRow r;
            r.t_us = static_cast<int64_t>(n) * 1000;
            const double s = static_cast<double>(n) * 1e-3;
            r.force[0] = static_cast<float>(8000 * std::exp(-3 * s) * std::sin(2 * 3.14159265 * 20 * s));
            r.force[1] = static_cast<float>(-2500 * s);
            r.position[0] = static_cast<float>(1500 * std::sin(2 * 3.14159265 * 2 * s));
            r.position[1] = static_cast<float>(400 * s);
            t.rows.push_back(r);
        }
        return t;
    }

    fs::path dir_;
};

TEST_F(Plot, WritesAnSvgDocument) {
    const fs::path path = dir_ / "trace.svg";
    write_plot(sample_trace(1500), "test \u2014 svg", path.string());
    const std::string text = read(path);
    ASSERT_FALSE(text.empty());
    EXPECT_TRUE(text.rfind("<?xml", 0) == 0 || text.rfind("<svg", 0) == 0) << text.substr(0, 80);
    EXPECT_NE(text.find("</svg>"), std::string::npos);
}

TEST_F(Plot, WritesAPngImage) {
    const fs::path path = dir_ / "trace.png";
    write_plot(sample_trace(1500), "test png", path.string());
    const std::string bytes = read(path);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(Plot, ALongTraceAndASingleRowBothPlot) {
    write_plot(sample_trace(200'000), "long", (dir_ / "long.png").string());
    EXPECT_GT(fs::file_size(dir_ / "long.png"), 1000u);
    write_plot(sample_trace(1), "one tick", (dir_ / "one.svg").string());
    EXPECT_GT(fs::file_size(dir_ / "one.svg"), 100u);
}

TEST_F(Plot, UppercaseExtensionsAreAccepted) {
    write_plot(sample_trace(10), "caps", (dir_ / "CAPS.PNG").string());
    EXPECT_TRUE(fs::exists(dir_ / "CAPS.PNG"));
}

TEST_F(Plot, AnUnknownExtensionListsTheFormats) {
    for (const char* name : {"trace.pdf", "trace", "dir.svg/trace"}) {
        try {
            write_plot(sample_trace(10), "x", (dir_ / name).string());
            ADD_FAILURE() << "accepted " << name;
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(".svg"), std::string::npos) << message;
            EXPECT_NE(message.find(".png"), std::string::npos) << message;
        }
    }
}

TEST_F(Plot, AnEmptyTraceIsRefused) {
    Trace empty;
    empty.axis_count = 2;
    EXPECT_THROW(write_plot(empty, "x", (dir_ / "e.svg").string()), std::invalid_argument);
}

TEST_F(Plot, AnUnwritablePathIsARuntimeErrorNamingIt) {
    for (const char* name : {"missing/dir/x.png", "missing/dir/x.svg"}) {
        const std::string path = (dir_ / name).string();
        try {
            write_plot(sample_trace(10), "x", path);
            ADD_FAILURE() << "wrote " << path;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
}

// The x-y view needs an x and a y: a 1-axis trace is refused naming the flag.
TEST_F(Plot, TheXyViewOfAOneAxisTraceIsRefused) {
    Trace one = sample_trace(10);
    one.axis_count = 1;
    const fs::path path = dir_ / "one.svg";
    try {
        write_xy_plot(one, "one", path.string());
        FAIL() << "a 1-axis x-y plot was drawn";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--plot-xy needs a 2-axis device"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path));
    write_xy_plot(sample_trace(500), "two", path.string());
    EXPECT_NE(read(path).find("</svg>"), std::string::npos);
}

}  // namespace
}  // namespace feel::render
