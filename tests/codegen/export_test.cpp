// The generators' text (src/codegen): the §8 wrapper chosen for an effect follows the
// primer's wrapper table (docs/wrappers.md: XSpring is a spring on x with both coefficients,
// saturations and the deadband, §7.5's sample spring), what a wrapper does not set is
// assigned after it, and names and comments cannot break the program. Whether the programs
// compile and give a device the file's effects is exported_programs_test.cpp's business.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "codegen.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::codegen {
namespace {

format::SensationFile parse(const std::string& sensations) {
    return format::parse_sensation_file(R"({"format": "feel/1", "sensations": {)" + sensations + "}}", "test");
}

std::string cpp(const format::SensationFile& file) { return export_code(Language::cpp, file, {}, "test.feel.json"); }
std::string c(const format::SensationFile& file) { return export_code(Language::c, file, {}, "test.feel.json"); }

constexpr const char* kSpring = R"("stick": {"type": "spring", "axes": ["x"], "duration_us": "infinite",
    "conditions": [{"pos_coefficient": 1000, "neg_coefficient": 1000, "pos_saturation": 10000,
                    "neg_saturation": 10000}]})";

TEST(CppExport, TheSection75SpringIsOneXSpringCall) {
    const std::string code = cpp(parse(kSpring));
    EXPECT_NE(code.find("feel::EffectParams e = fi::x_spring(1000, 1000, 0, 10000, 10000, 0);\n        effects.push_back"),
              std::string::npos)
        << code;
}

TEST(CppExport, WhatTheWrapperDoesNotSetIsAssignedAfterIt) {
    // §8.5 fixes the gain at 10000 and no start delay: a gain of 5000 and a delay are assignments.
    const std::string code = cpp(parse(R"("hum": {"type": "sine", "axes": ["x", "y"], "direction": {"polar": 9000},
        "duration_us": 2000000, "gain": 5000, "start_delay_us": 100000,
        "periodic": {"magnitude": 2000, "period_us": 10000}})"));
    EXPECT_NE(code.find("fi::delayed_periodic(100000, feel::Waveform::sine, 2000, 0, 0, 10000, 2000000, 9000, "
                        "fi::kNoTrigger, 0);\n        e.gain = 5000;\n"),
              std::string::npos)
        << code;
}

TEST(CppExport, AnEffectNoWrapperMakesStartsFromTheDefaults) {
    // smart_pop has no §8 wrapper; a negative constant is outside ConstantForce's 1..10000.
    const std::string code = cpp(parse(R"("pop": {"type": "smart_pop", "axes": ["x"], "duration_us": 50000,
        "constant": {"magnitude": -4000}})"));
    EXPECT_NE(code.find("feel::EffectParams e = feel::EffectParams{};\n        e.type = feel::EffectType::smart_pop;\n"
                        "        e.duration_us = 50000;\n        e.constant.magnitude = -4000;\n"),
              std::string::npos)
        << code;
}

TEST(CExport, FillsTheParameterStructFromItsTypesDefaults) {
    const std::string code = c(parse(kSpring));
    EXPECT_NE(code.find("feel_effect_params_init(&p, FEEL_TYPE_SPRING);\n"
                        "    p.conditions[0].pos_coefficient = 1000;\n"
                        "    p.conditions[0].neg_coefficient = 1000;\n"
                        "    if (!create(device, &p, \"stick\", NULL, 0)) return false;\n"),
              std::string::npos)
        << code;
}

TEST(CExport, NamesTheFieldsTheCStructNamesDifferently) {
    const std::string code = c(parse(R"("slope": {"type": "ramp", "axes": ["x"], "duration_us": 1000000,
        "ramp": {"start": -3000, "end": 3000}},
        "gate": {"type": "axis_barrier", "axes": ["y"], "duration_us": "infinite", "barrier": {"pos_hardness": 8000, "neg_hardness": 8000,
        "thickness": 500, "offset_mode": "relative"}})"));
    EXPECT_NE(code.find("p.ramp_start = -3000;"), std::string::npos) << code;
    EXPECT_NE(code.find("p.ramp_end = 3000;"), std::string::npos) << code;
    EXPECT_NE(code.find("p.barrier_offset_mode = FEEL_OFFSET_RELATIVE;"), std::string::npos) << code;
    EXPECT_NE(code.find("p.axes[0] = FEEL_AXIS_Y;"), std::string::npos) << code;
}

TEST(Export, SensationNamesBecomeDistinctIdentifiers) {
    const format::SensationFile file = parse(std::string(R"("a-b": )") + R"({"type": "friction", "axes": ["x"], "duration_us": "infinite",
        "conditions": [{"pos_coefficient": 100, "neg_coefficient": 100}]}, "a.b": {"type": "friction", "axes": ["x"], "duration_us": "infinite",
        "conditions": [{"pos_coefficient": 100, "neg_coefficient": 100}]}, "9lives": {"type": "friction", "axes": ["x"], "duration_us": "infinite",
        "conditions": [{"pos_coefficient": 100, "neg_coefficient": 100}]})");
    for (const std::string& code : {cpp(file), c(file)}) {
        EXPECT_NE(code.find("create_a_b("), std::string::npos);
        EXPECT_NE(code.find("create_a_b_2("), std::string::npos);
        EXPECT_NE(code.find("create_s_9lives("), std::string::npos);
    }
}

TEST(Export, ADescriptionCannotCloseTheComment) {
    const std::string code = c(parse(R"("x": {"description": "ends here */ int evil; /* and\nnext line",
        "type": "friction", "axes": ["x"], "duration_us": "infinite", "conditions": [{"pos_coefficient": 1, "neg_coefficient": 1}]})"));
    EXPECT_EQ(code.find("*/ int evil"), std::string::npos) << code;
    EXPECT_EQ(code.find("\nnext line"), std::string::npos) << code;
}

TEST(Export, AnUnknownSensationIsRefusedWithTheFilesNames) {
    const std::vector<std::string> names = {"nope"};
    try {
        (void)export_code(Language::cpp, parse(kSpring), names, "test.feel.json");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "export: no sensation \"nope\" in test.feel.json (it has: stick)");
    }
}

TEST(Export, AFileWithoutSensationsHasNothingToExport) {
    for (Language language : {Language::cpp, Language::c, Language::library}) {
        try {
            (void)export_code(language, format::SensationFile{}, {}, "empty.feel.json");
            FAIL() << "no error";
        } catch (const std::invalid_argument& e) {
            EXPECT_STREQ(e.what(), "export: empty.feel.json has no sensations to export");
        }
    }
}

TEST(LibraryExport, IsTheTwoCallsOfSection95) {
    const std::vector<std::string> names = {"stick"};
    const std::string code = export_code(Language::library, parse(kSpring), names, "my/stick.feel.json");
    EXPECT_NE(code.find("feel::host::SensationLibrary::load(\"my/stick.feel.json\", address)"), std::string::npos);
    EXPECT_NE(code.find("library->play(\"stick\")"), std::string::npos);
}

TEST(Export, LanguageNames) {
    EXPECT_EQ(language_from_name("cpp"), Language::cpp);
    EXPECT_EQ(language_from_name("c"), Language::c);
    EXPECT_EQ(language_from_name("library"), Language::library);
    EXPECT_EQ(language_from_name("rust"), std::nullopt);
}

}  // namespace
}  // namespace feel::codegen
