// The Studio's export_code message (src/studio/export_request.cpp): the current sensation,
// read by the format's reader, as code; a sensation the reader refuses is answered with its
// sentence and no code.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "export_request.hpp"

namespace feel::studio {
namespace {

using json = nlohmann::json;

json request(const std::string& lang, json effects) {
    return {{"type", "export_code"}, {"seq", 7}, {"lang", lang}, {"name", "My_Favorites.stick"},
            {"file", "favorites.feel.json"}, {"effects", std::move(effects)}};
}

const json kSpringEffects = json::array({json{{"type", "spring"}, {"axes", {"x"}}, {"duration_us", "infinite"},
                                       {"conditions", {{{"pos_coefficient", 1000}, {"neg_coefficient", 1000}}}}}});

TEST(ExportRequest, AnswersWithTheCodeAndAFileName) {
    const json cpp = export_reply(request("cpp", kSpringEffects));
    ASSERT_EQ(cpp["type"], "exported") << cpp;
    EXPECT_EQ(cpp["seq"], 7);
    EXPECT_EQ(cpp["lang"], "cpp");
    EXPECT_EQ(cpp["filename"], "My_Favorites_stick.cpp");
    // §7.5's spring on x is XSpring (§8.2), full saturations and no deadband by default
    EXPECT_NE(cpp["code"].get<std::string>().find("fi::x_spring(1000, 1000, 0, 10000, 10000, 0)"), std::string::npos);
    const json c = export_reply(request("c", kSpringEffects));
    EXPECT_EQ(c["filename"], "My_Favorites_stick.c");
    EXPECT_NE(c["code"].get<std::string>().find("feel_effect_params_init(&p, FEEL_TYPE_SPRING);"), std::string::npos);
    const json lib = export_reply(request("library", kSpringEffects));
    EXPECT_NE(lib["code"].get<std::string>().find(
                  R"(SensationLibrary::load("favorites.feel.json", address))"),
              std::string::npos);
    EXPECT_NE(lib["code"].get<std::string>().find(R"(library->play("My_Favorites.stick"))"), std::string::npos);
}

TEST(ExportRequest, ASensationTheFormatRefusesGetsItsSentence) {
    json effects = kSpringEffects;
    effects[0]["conditions"][0]["deadband"] = 12000;
    const json e = export_reply(request("cpp", effects));
    EXPECT_EQ(e["type"], "error");
    EXPECT_EQ(e["request"], "export_code");
    EXPECT_EQ(e["message"], "export_code: favorites.feel.json: sensation \"My_Favorites.stick\": "
                            "conditions[0].deadband = 12000 is out of range (allowed 0..10000)");
}

TEST(ExportRequest, AnEmptySensationHasNothingToExport) {
    const json e = export_reply(request("cpp", json::array()));
    EXPECT_EQ(e["type"], "error");
    EXPECT_EQ(e["message"], "export_code: the sensation \"My_Favorites.stick\" has no effects to export");
}

}  // namespace
}  // namespace feel::studio
