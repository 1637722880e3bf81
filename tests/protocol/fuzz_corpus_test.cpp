// The fuzz targets' seed corpora stay valid: every file of fuzz/corpus/protocol_decode/ is
// an accepted report (so the fuzzer starts from the inside of the decoder), one per sample
// report, and fuzz/corpus/descriptor_parser/ holds feel's descriptor. After a deliberate
// protocol change, rewrite them with FEEL_UPDATE_PROTOCOL_CORPUS=1 and review the diff.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "sample_reports.hpp"

namespace feel::protocol {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const fs::path& p, std::span<const uint8_t> bytes) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// "set_effect.bin", "set_effect_2.bin", ...: one seed per sample report.
std::map<std::string, std::vector<uint8_t>> expected_seeds() {
    std::map<std::string, std::vector<uint8_t>> seeds;
    std::map<std::string, int> seen;
    for (const AnyReport& r : test::sample_reports()) {
        std::string name(report_name(report_id_of(r)));
        for (char& c : name) c = c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const int n = ++seen[name];
        seeds[name + (n > 1 ? "_" + std::to_string(n) : "") + ".bin"] = encode(r);
    }
    return seeds;
}

bool updating() { return std::getenv("FEEL_UPDATE_PROTOCOL_CORPUS") != nullptr; }

TEST(FuzzCorpus, ProtocolDecodeSeedsAreAcceptedReports) {
    const fs::path dir = fs::path(FEEL_SOURCE_DIR) / "fuzz/corpus/protocol_decode";
    const auto seeds = expected_seeds();
    if (updating()) {
        fs::create_directories(dir);
        for (const auto& [name, bytes] : seeds) write_file(dir / name, bytes);
    }
    ASSERT_TRUE(fs::is_directory(dir));
    std::size_t files = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
        ++files;
        const std::vector<uint8_t> bytes = read_file(entry.path());
        SCOPED_TRACE(entry.path().filename().string());
        AnyReport out;
        const Error e = decode(bytes, out);
        ASSERT_TRUE(e.ok()) << e.message() << " (regenerate: FEEL_UPDATE_PROTOCOL_CORPUS=1)";
        EXPECT_EQ(encode(out), bytes);
    }
    for (const auto& [name, bytes] : seeds) {
        EXPECT_EQ(read_file(dir / name), bytes) << name << " (regenerate: FEEL_UPDATE_PROTOCOL_CORPUS=1)";
    }
    EXPECT_EQ(files, seeds.size());
}

TEST(FuzzCorpus, DescriptorParserSeedIsFeelsDescriptor) {
    const fs::path dir = fs::path(FEEL_SOURCE_DIR) / "fuzz/corpus/descriptor_parser";
    const fs::path file = dir / "feel_descriptor.bin";
    if (updating()) {
        fs::create_directories(dir);
        write_file(file, report_descriptor());
    }
    const std::vector<uint8_t> bytes = read_file(file);
    const std::span<const uint8_t> current = report_descriptor();
    EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), current.begin(), current.end()))
        << "regenerate: FEEL_UPDATE_PROTOCOL_CORPUS=1";
    EXPECT_TRUE(hid::parse_report_descriptor(bytes).ok());
}

}  // namespace
}  // namespace feel::protocol
