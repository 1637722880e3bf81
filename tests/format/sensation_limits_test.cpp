// What keeps any file within memory (docs/sensation-format.md, "Limits"): the reader
// refuses excess while it reads, naming the field and the allowed range, never after
// building it. The limits come from the format: a force profile holds at most 65535
// samples (range::kSampleCount, the PID Byte Count of §6.6.d's profile), a file at most
// kMaxFileEffects effects. The memory these bounds buy is measured by
// tests/apps/check_memory_test.cpp.
#include <string>

#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kConstant = R"({"type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}})";

// A force profile on x with `count` samples 0, 1, 2, ... (mod 100).
std::string profile_with(size_t count) {
    std::string samples;
    samples.reserve(count * 3);
    for (size_t i = 0; i < count; ++i) {
        if (i) samples += ',';
        samples += std::to_string(i % 100);
    }
    return file_with(R"({"type": "force_profile", "duration_us": 1000000, "axes": ["x"],
        "custom": {"sample_period_us": 1000, "samples": [)" + samples + "]}}");
}

// A file of `count` single-effect sensations s0, s1, ...
std::string sensations(size_t count) {
    std::string text = R"({"format": "feel/1", "sensations": {)";
    for (size_t i = 0; i < count; ++i) text += (i ? ", \"s" : "\"s") + std::to_string(i) + "\": " + kConstant;
    return text + "}}";
}

std::string compound_of(size_t count) {
    std::string effects;
    for (size_t i = 0; i < count; ++i) effects += (i ? ", " : "") + kConstant;
    return file_with(R"({"effects": [)" + effects + "]}");
}

TEST(SensationFileLimits, AForceProfileHoldsAtMost65535Samples) {
    const SensationFile most = parse_sensation_file(profile_with(65535), "ok.json");
    ASSERT_EQ(most.sensations.at(0).effects.at(0).samples.size(), 65535u);
    EXPECT_EQ(most.sensations[0].effects[0].samples[65534], 65534 % 100);
    const std::string refused = R"(bad.json: sensation "hum": custom.samples: more than 65535 samples (allowed 1..65535))";
    EXPECT_EQ(error_of(profile_with(65536)), refused);
    EXPECT_EQ(error_of(profile_with(3'000'000)), refused);  // the audit's 3 M samples, refused at the 65536th
}

TEST(SensationFileLimits, NoOtherArrayIsLonger) {
    std::string zeros = "0";
    for (int i = 1; i < 70'000; ++i) zeros += ",0";
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "x": [)" + zeros + "]}")),
              R"(bad.json: sensation "hum": x: more than 65535 values in one array (the longest array of the format, a force profile's samples, holds at most 65535))");
    // In a compound, a whole effect can be the long array: refused as an effect at once.
    EXPECT_EQ(error_of(file_with(R"({"effects": [[)" + zeros + "]]}")),
              R"(bad.json: sensation "hum": effects[0]: expected an effect object, found an array)");
}

TEST(SensationFileLimits, NoObjectHasMoreThan64Members) {
    std::string members;
    for (int i = 0; i < 65; ++i) members += (i ? ", \"k" : "\"k") + std::to_string(i) + "\": 1";
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "periodic": {)" + members + "}}")),
              R"(bad.json: sensation "hum": periodic: more than 64 members in one object (no object of the format has that many))");
}

TEST(SensationFileLimits, AnEffectHoldsAtMostSamplesAndItsFieldsInValues) {
    // Two arrays, each within the array limit, together beyond what any effect holds.
    std::string zeros = "0";
    for (int i = 1; i < 60'000; ++i) zeros += ",0";
    const std::string msg = error_of(file_with(R"({"type": "sine", "x": [[)" + zeros + "], [" + zeros + "]]}"));
    EXPECT_THAT(msg, StartsWith(R"(bad.json: sensation "hum": x[1][)"));
    EXPECT_THAT(msg, HasSubstr("more than 69631 JSON values in one effect (a valid one holds at most 65535 samples and its fields)"));
}

TEST(SensationFileLimits, AFileHoldsAtMost4096Effects) {
    EXPECT_EQ(parse_sensation_file(sensations(kMaxFileEffects), "ok.json").sensations.size(), kMaxFileEffects);
    EXPECT_EQ(error_of(sensations(kMaxFileEffects + 1)),
              R"(bad.json: sensation "s4096": the file has more than 4096 effects (allowed 1..4096 in one file, all sensations together))");
    EXPECT_EQ(parse_sensation_file(compound_of(kMaxFileEffects), "ok.json").sensations.at(0).effects.size(), kMaxFileEffects);
    EXPECT_EQ(error_of(compound_of(kMaxFileEffects + 1)),
              R"(bad.json: sensation "hum": effects[4096]: the file has more than 4096 effects (allowed 1..4096 in one file, all sensations together))");
}

TEST(SensationFileLimits, TheWriterRefusesWhatTheReaderWould) {
    SensationFile file = parse_sensation_file(compound_of(kMaxFileEffects), "ok.json");
    EXPECT_EQ(parse_sensation_file(write_sensation_file(file), "again.json"), file);
    file.sensations[0].effects.push_back(file.sensations[0].effects[0]);
    try {
        (void)write_sensation_file(file);
        FAIL() << "4097 effects written";
    } catch (const FormatError& e) {
        EXPECT_STREQ(e.what(), "cannot write 4097 effects in one file (allowed 1..4096: a reader would refuse it)");
    }
}

TEST(SensationFileLimits, EmptyObjectsAreRefusedAtTheFirst) {
    // The audit's 7.4 M empty objects: the first one is an effect without a type.
    std::string many;
    many.reserve(3'000'000);
    for (int i = 0; i < 1'000'000; ++i) many += i ? ",{}" : "{}";
    EXPECT_EQ(error_of(file_with(R"({"effects": [)" + many + "]}")),
              R"(bad.json: sensation "hum": effects[0].type: required field is missing (an effect names its type, e.g. "sine"; a compound sensation lists its effects in "effects"))");
}

TEST(SensationFileLimits, LongStringsAreShortenedInMessages) {
    const std::string name(100'000, 'n');
    EXPECT_EQ(error_of(file_with(kConstant, name)),
              R"(bad.json: sensation name "nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn..." (100000 bytes) is not valid (use 1 to 64 letters, digits, '_', '-' or '.'))");
}

}  // namespace
}  // namespace feel::format::test
