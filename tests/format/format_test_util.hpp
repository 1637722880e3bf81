// Helpers for the sensation-file tests: building small files and catching their errors.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "feel/effect_validation.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::format::test {

// A whole file holding one sensation named `name` whose JSON is `sensation`.
inline std::string file_with(std::string_view sensation, std::string_view name = "hum") {
    return R"({"format": "feel/1", "sensations": {")" + std::string(name) + R"(": )" + std::string(sensation) + "}}";
}

// The message of the FormatError that parsing `text` throws; fails the test if it parses.
inline std::string error_of(std::string_view text, std::string_view origin = "bad.json") {
    try {
        (void)parse_sensation_file(text, origin);
    } catch (const FormatError& e) {
        return e.what();
    }
    ADD_FAILURE() << "parsed without error:\n" << text;
    return {};
}

// The params of the only effect of the only sensation of `text`.
inline EffectParams params_of(std::string_view text) {
    const SensationFile f = parse_sensation_file(text, "test.json");
    EXPECT_EQ(f.sensations.size(), 1u);
    EXPECT_EQ(f.sensations.at(0).effects.size(), 1u);
    return f.sensations.at(0).effects.at(0).params;
}

}  // namespace feel::format::test
