// The field description the forms are generated from: every type, ranges as the
// validator enforces them (checked against the primer's ranges, §6.3, §6.6).
#include <gtest/gtest.h>

#include <map>
#include <string>

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
    // §6.3: an effect's gain 0..10000; a choice has no unit
    for (const json& c : d["common"]) {
        if (c["name"] == "gain") {
            EXPECT_EQ(c["min"], 0);
            EXPECT_EQ(c["max"], 10000);
        }
    }
    EXPECT_EQ(field(d, "axis_wall", "sense")["unit"], "");
}

// §6.5: polar 0..35999 and spherical azimuth 0..35999, elevation 0..18000 hundredths of a
// degree (shown in degrees); cartesian and moments components ±10000, one per axis.
TEST(FieldSchema, DirectionFormsAreThePrimers) {
    const json d = describe();
    std::map<std::string, json> forms;
    for (const json& f : d["direction"]["forms"]) forms[f["form"].get<std::string>()] = f;
    ASSERT_EQ(forms.size(), 4u);
    const json& polar = forms["polar"]["components"][0];
    EXPECT_EQ(polar["min"], 0);
    EXPECT_EQ(polar["max"], 35999);
    EXPECT_EQ(polar["unit"], "0.01°");
    EXPECT_EQ(polar["shown_unit"], "°");
    EXPECT_DOUBLE_EQ(polar["scale"].get<double>(), 0.01);
    EXPECT_EQ(forms["polar"]["axes"], json({"x", "y"}));
    EXPECT_TRUE(forms["polar"]["exact_axes"].get<bool>());
    EXPECT_EQ(forms["spherical"]["components"][0]["max"], 35999);
    EXPECT_EQ(forms["spherical"]["components"][1]["min"], 0);
    EXPECT_EQ(forms["spherical"]["components"][1]["max"], 18000);
    EXPECT_EQ(forms["spherical"]["axes"], json({"x", "y", "z"}));
    for (const char* vector : {"cartesian", "moments"}) {
        EXPECT_TRUE(forms[vector]["per_axis"].get<bool>());
        EXPECT_FALSE(forms[vector]["exact_axes"].get<bool>());
        EXPECT_EQ(forms[vector]["components"][0]["min"], -10000) << vector;
        EXPECT_EQ(forms[vector]["components"][0]["max"], 10000) << vector;
    }
    EXPECT_EQ(forms["moments"]["axes"], json({"rx", "ry", "rz"}));
    // every angle field is shown in degrees
    EXPECT_DOUBLE_EQ(field(d, "sine", "phase")["scale"].get<double>(), 0.01);
    EXPECT_FALSE(field(d, "sine", "magnitude").contains("scale"));
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
