// The field description the forms are generated from: every type, ranges as the
// validator enforces them (checked against the primer's ranges, §6.3, §6.6).
#include <gtest/gtest.h>

#include "feel/effect_type.hpp"
#include "field_schema.hpp"
#include "studio_assets.hpp"

namespace feel::studio {
namespace {

using json = nlohmann::json;

json describe() {
    return describe_fields(format::parse_sensation_file(find_data_asset("starters.feel.json")->text(), "starters"));
}

const json& field(const json& d, std::string_view type, std::string_view name) {
    for (const json& t : d["types"]) {
        if (t["type"] != type) continue;
        for (const json& f : t["fields"]) {
            if (f["name"] == name) return f;
        }
    }
    static const json none;
    return none;
}

TEST(FieldSchema, DescribesEveryTypeFromTheFormatsTable) {
    const json d = describe();
    ASSERT_EQ(d["types"].size(), static_cast<size_t>(kEffectTypeCount));
    for (const json& t : d["types"]) EXPECT_FALSE(t["fields"].empty()) << t["type"];
}

TEST(FieldSchema, RangesAreThePrimers) {
    const json d = describe();
    // §6.6.b: magnitude 0..10000, phase 0..35999 hundredths of a degree
    EXPECT_EQ(field(d, "sine", "magnitude")["min"], 0);
    EXPECT_EQ(field(d, "sine", "magnitude")["max"], 10000);
    EXPECT_EQ(field(d, "sine", "phase")["max"], 35999);
    EXPECT_EQ(field(d, "sine", "phase")["unit"], "0.01°");
    // §6.6.a: condition coefficients ±10000, saturation 0..10000
    EXPECT_EQ(field(d, "spring", "pos_coefficient")["min"], -10000);
    EXPECT_EQ(field(d, "spring", "pos_saturation")["min"], 0);
    EXPECT_EQ(field(d, "axis_wall", "sense")["kind"], "choice");
    EXPECT_EQ(field(d, "axis_wall", "clipping")["kind"], "boolean");
    EXPECT_EQ(field(d, "sine", "period_us")["unit"], "µs");
    bool duration = false;
    for (const json& c : d["common"]) {
        if (c["name"] == "duration_us") {
            duration = true;
            EXPECT_EQ(c["max"], 65000000);  // §6.3
            EXPECT_TRUE(c["infinite"].get<bool>());
        }
    }
    EXPECT_TRUE(duration);
}

TEST(FieldSchema, TheFormsOfIssue16Section3AreDescribed) {
    const json d = describe();
    // §3.8: a barrier's Offset-Flag, "same as the wall".
    for (std::string_view type : {"axis_barrier", "angle_barrier"}) {
        const json& f = field(d, type, "offset_mode");
        EXPECT_EQ(f["kind"], "choice") << type;
        EXPECT_EQ(f["choices"], json::array({"absolute", "relative"})) << type;
    }
    // §3.1: spring, damper, inertia and friction take one block along a direction; the
    // angle_spring always has one block, the texture no condition blocks at all.
    for (const json& t : d["types"]) {
        const std::string type = t["type"];
        const bool directed = type == "spring" || type == "damper" || type == "inertia" || type == "friction";
        EXPECT_EQ(t.value("one_block_with_direction", false), directed) << type;
    }
}

}  // namespace
}  // namespace feel::studio
