// Lossless writing: canonical text comes back byte for byte, any valid file comes back
// as the same model, and the writer refuses models it could not read back.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

using ::testing::HasSubstr;

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string primer_path() { return std::string(FEEL_SOURCE_DIR) + "/examples/primer.feel.json"; }

// Canonical form, written by hand from docs/sensation-format.md: keys in the documented
// order, optional fields exactly where spelled out, two-space indent, one value per line.
constexpr const char* kCanonical = R"({
  "format": "feel/1",
  "sensations": {
    "reflex_jolt": {
      "description": "hat 2, with its defaults spelled out",
      "type": "constant",
      "duration_us": 30000,
      "start_delay_us": 0,
      "iterations": 1,
      "axes": [
        "x",
        "y"
      ],
      "direction": {
        "cartesian": [
          0,
          -10000
        ]
      },
      "gain": 10000,
      "trigger_button": "hat2",
      "trigger_repeat_interval_us": 0,
      "constant": {
        "magnitude": 7500
      }
    },
    "law": {
      "type": "dynamic_control_law",
      "duration_us": "infinite",
      "iterations": "infinite",
      "axes": [
        "x"
      ],
      "dynamic": {
        "control_law": [
          {
            "mass": 100,
            "k_pos": 2000,
            "k_neg": 2000,
            "b": 0,
            "gravity": -300
          }
        ],
        "interim_reporting": false
      }
    },
    "burst": {
      "effects": [
        {
          "type": "force_profile",
          "duration_us": 20000,
          "axes": [
            "x",
            "y"
          ],
          "custom": {
            "channels": 2,
            "sample_period_us": 10000,
            "samples": [
              100,
              -100,
              0,
              0
            ]
          }
        },
        {
          "type": "vector_force",
          "start_delay_us": 40000,
          "axes": [
            "rz"
          ],
          "direction": {
            "moments": [
              -1
            ]
          },
          "constant": {
            "magnitude": -3000
          }
        }
      ]
    }
  }
}
)";

TEST(SensationRoundTrip, HandWrittenCanonicalTextIsByteIdentical) {
    const SensationFile f = parse_sensation_file(kCanonical, "canonical.json");
    EXPECT_EQ(write_sensation_file(f), kCanonical);
}

TEST(SensationRoundTrip, PrimerExamplesAreCanonical) {
    const std::string text = read_text(primer_path());
    ASSERT_FALSE(text.empty());
    const SensationFile f = load_sensation_file(primer_path());
    EXPECT_EQ(write_sensation_file(f), text);
}

// Every example file in examples/ is valid and in canonical form.
TEST(SensationRoundTrip, EveryExampleFileIsCanonical) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(FEEL_SOURCE_DIR) + "/examples")) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        const std::string text = read_text(entry.path().string());
        const SensationFile f = load_sensation_file(entry.path());
        EXPECT_EQ(write_sensation_file(f), text) << entry.path();
    }
    EXPECT_GE(files, 1);
}

TEST(SensationRoundTrip, PrimerExamplesFollowThePrimer) {
    const SensationFile f = load_sensation_file(primer_path());
    for (const Sensation& s : f.sensations) EXPECT_TRUE(s.description.has_value()) << s.name;

    // §1.2.c reflex table. Button #4: 100 Hz sine, 20% magnitude, left-right.
    const EffectParams& hum = f.find("afterburner_hum")->effects.at(0).params;
    EXPECT_EQ(hum.type, EffectType::sine);
    EXPECT_EQ(hum.periodic.period_us, 1'000'000 / 100);
    EXPECT_EQ(hum.periodic.magnitude, 10000 * 20 / 100);
    EXPECT_EQ(hum.trigger.kind, TriggerKind::button);
    EXPECT_EQ(hum.trigger.index, 4);
    EXPECT_EQ(hum.direction.kind, DirectionKind::polar);
    EXPECT_EQ(hum.direction.value[0] % 18000, 9000);  // along east-west
    // Hat switch #2: a 30 ms jolt at 75%.
    const EffectParams& missile = f.find("patriot_missile")->effects.at(0).params;
    EXPECT_EQ(missile.duration_us, 30'000);
    EXPECT_EQ(missile.constant.magnitude, 10000 * 75 / 100);
    EXPECT_EQ(missile.trigger.kind, TriggerKind::hat);
    EXPECT_EQ(missile.trigger.index, 2);
    // Trigger #1: 10 Hz square at 70%.
    const EffectParams& guns = f.find("machine_guns")->effects.at(0).params;
    EXPECT_EQ(guns.type, EffectType::square);
    EXPECT_EQ(guns.periodic.period_us, 1'000'000 / 10);
    EXPECT_EQ(guns.periodic.magnitude, 10000 * 70 / 100);
    EXPECT_EQ(guns.trigger.index, 1);

    // §4.2.a railing: a high impulse that settles quickly to a mild steady state.
    const EffectParams& railing = f.find("railing_impact")->effects.at(0).params;
    EXPECT_TRUE(railing.has_envelope);
    EXPECT_GT(railing.envelope.impulse_level, 2 * railing.constant.magnitude);
    EXPECT_LT(railing.envelope.settle_time_us, 100'000);  // "tens of milliseconds"

    // §4.2.a cross wind: an impulse-shaped wind plus jolts on top that stay in range.
    const Sensation& wind = *f.find("cross_wind_with_gun_blasts");
    ASSERT_TRUE(wind.compound);
    ASSERT_EQ(wind.effects.size(), 2u);
    const EffectParams& gust = wind.effects[0].params;
    const EffectParams& blasts = wind.effects[1].params;
    EXPECT_TRUE(gust.has_envelope);
    EXPECT_GT(gust.envelope.impulse_level, gust.constant.magnitude);
    EXPECT_GT(blasts.start_delay_us, 0);
    EXPECT_LE(gust.constant.magnitude + blasts.periodic.offset + blasts.periodic.magnitude, 10000);

    // §7.5: a spring on x and a texture felt along y.
    const Sensation& pair = *f.find("stiff_spring_and_washboard");
    ASSERT_EQ(pair.effects.size(), 2u);
    EXPECT_EQ(pair.effects[0].params.type, EffectType::spring);
    EXPECT_EQ(pair.effects[0].params.axes[0], Axis::x);
    EXPECT_EQ(pair.effects[0].params.conditions[0].pos_coefficient, 1000);
    EXPECT_EQ(pair.effects[1].params.type, EffectType::texture);
    EXPECT_EQ(pair.effects[1].params.texture.spacing, 2000);
    EXPECT_EQ(pair.effects[1].params.texture.density, 7500);

    // One sample of each temporal wave type (§6.4.b), plus the custom profile.
    std::vector<EffectType> waves;
    for (const Sensation& s : f.sensations) {
        for (const EffectSpec& e : s.effects) {
            if (effect_class(e.params.type) == EffectClass::wave) waves.push_back(e.params.type);
        }
    }
    for (EffectType t : {EffectType::vector_force, EffectType::constant, EffectType::smart_pop, EffectType::sine,
                         EffectType::square, EffectType::triangle, EffectType::saw_up, EffectType::saw_down,
                         EffectType::sweep_sine, EffectType::sweep_square, EffectType::sweep_triangle,
                         EffectType::sweep_saw_up, EffectType::sweep_saw_down, EffectType::force_profile,
                         EffectType::ramp}) {
        EXPECT_NE(std::find(waves.begin(), waves.end(), t), waves.end()) << effect_type_name(t);
    }
    const EffectSpec& gyro = f.find("gyro_blaster")->effects.at(0);
    EXPECT_EQ(gyro.params.custom.channels, 2);
    EXPECT_EQ(gyro.samples.size() % 2, 0u);
}

TEST(SensationRoundTrip, NonCanonicalInputKeepsItsModel) {
    // Keys out of order, compact layout, escapes, defaults partly spelled out.
    const std::string text = R"({"sensations": {"b": {"periodic": {"phase": 0, "period_us": 10000, "magnitude": 2000},
        "axes": ["x", "y"], "gain": 10000, "type": "sine", "direction": {"polar": 9000}, "duration_us": 2000000,
        "description": "tab\there \u00e9"},
        "a": {"effects": [{"constant": {"magnitude": -5}, "axes": ["y"], "type": "vector_force", "duration_us": "infinite"}]}},
        "format": "feel/1"})";
    const SensationFile first = parse_sensation_file(text, "messy.json");
    const std::string canonical = write_sensation_file(first);
    const SensationFile second = parse_sensation_file(canonical, "canonical.json");
    EXPECT_EQ(second, first);
    EXPECT_EQ(write_sensation_file(second), canonical);

    // The canonical text, by hand: documented key order, and the optional fields the
    // input spelled out (phase, gain, the vector force's duration) are kept.
    const std::string expected = "{\n"
                                 "  \"format\": \"feel/1\",\n"
                                 "  \"sensations\": {\n"
                                 "    \"b\": {\n"
                                 "      \"description\": \"tab\\there \u00e9\",\n"
                                 "      \"type\": \"sine\",\n"
                                 "      \"duration_us\": 2000000,\n"
                                 "      \"axes\": [\n"
                                 "        \"x\",\n"
                                 "        \"y\"\n"
                                 "      ],\n"
                                 "      \"direction\": {\n"
                                 "        \"polar\": 9000\n"
                                 "      },\n"
                                 "      \"gain\": 10000,\n"
                                 "      \"periodic\": {\n"
                                 "        \"magnitude\": 2000,\n"
                                 "        \"period_us\": 10000,\n"
                                 "        \"phase\": 0\n"
                                 "      }\n"
                                 "    },\n"
                                 "    \"a\": {\n"
                                 "      \"effects\": [\n"
                                 "        {\n"
                                 "          \"type\": \"vector_force\",\n"
                                 "          \"duration_us\": \"infinite\",\n"
                                 "          \"axes\": [\n"
                                 "            \"y\"\n"
                                 "          ],\n"
                                 "          \"constant\": {\n"
                                 "            \"magnitude\": -5\n"
                                 "          }\n"
                                 "        }\n"
                                 "      ]\n"
                                 "    }\n"
                                 "  }\n"
                                 "}\n";
    EXPECT_EQ(canonical, expected);
}

TEST(SensationRoundTrip, ExplicitFieldsAreRecordedAsPointers) {
    const SensationFile f = parse_sensation_file(file_with(R"({"type": "spring", "duration_us": "infinite", "axes": ["x", "y"],
        "gain": 10000, "conditions": [{"pos_coefficient": 1, "neg_coefficient": 1, "deadband": 0},
                                      {"pos_coefficient": 1, "neg_coefficient": 1, "pos_saturation": 10000}]})"),
                                                 "t.json");
    EXPECT_EQ(f.sensations[0].effects[0].explicit_fields,
              (std::vector<std::string>{"/gain", "/conditions/0/deadband", "/conditions/1/pos_saturation"}));
}

TEST(SensationRoundTrip, OmittedDefaultsStayOmitted) {
    const std::string text = file_with(R"({"type": "sine", "duration_us": 1000, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})");
    const std::string out = write_sensation_file(parse_sensation_file(text, "t.json"));
    for (const char* absent : {"gain", "start_delay_us", "iterations", "offset", "phase", "direction", "envelope", "trigger"}) {
        EXPECT_EQ(out.find(absent), std::string::npos) << absent;
    }
}

TEST(SensationRoundTrip, WrittenFromAModelBuiltInCode) {
    // A model that never came from a file: non-default values are written, defaults not.
    SensationFile file;
    Sensation s;
    s.name = "patriot_missile";
    EffectSpec e;
    e.params.type = EffectType::constant;
    e.params.duration_us = 30'000;
    e.params.axis_count = 1;
    e.params.axes[0] = Axis::y;
    e.params.trigger = {TriggerKind::hat, 2};
    e.params.constant.magnitude = -7500;
    s.effects.push_back(e);
    file.sensations.push_back(s);
    const std::string text = write_sensation_file(file);
    EXPECT_EQ(text, "{\n"
                    "  \"format\": \"feel/1\",\n"
                    "  \"sensations\": {\n"
                    "    \"patriot_missile\": {\n"
                    "      \"type\": \"constant\",\n"
                    "      \"duration_us\": 30000,\n"
                    "      \"axes\": [\n"
                    "        \"y\"\n"
                    "      ],\n"
                    "      \"trigger_button\": \"hat2\",\n"
                    "      \"constant\": {\n"
                    "        \"magnitude\": -7500\n"
                    "      }\n"
                    "    }\n"
                    "  }\n"
                    "}\n");
    EXPECT_EQ(parse_sensation_file(text, "t.json"), file);
}

TEST(SensationRoundTrip, WriterRefusesInvalidModels) {
    auto message_of = [](const SensationFile& f) {
        try {
            (void)write_sensation_file(f);
        } catch (const FormatError& e) {
            return std::string(e.what());
        }
        ADD_FAILURE() << "written";
        return std::string();
    };
    EXPECT_EQ(message_of({}), "cannot write a sensation file with no sensations (a file defines at least one)");

    SensationFile good = parse_sensation_file(kCanonical, "canonical.json");
    SensationFile f = good;
    f.sensations[0].effects[0].params.constant.magnitude = 10001;
    EXPECT_EQ(message_of(f), R"(cannot write sensation "reflex_jolt": constant.magnitude = 10001 is out of range (allowed -10000..10000))");

    f = good;
    f.sensations[2].effects[1].params.direction.value[0] = 0;
    EXPECT_EQ(message_of(f), R"(cannot write sensation "burst": effects[1].direction.moments: the zero vector names no direction)");

    f = good;
    f.sensations[1].name = "reflex_jolt";
    EXPECT_EQ(message_of(f), R"(cannot write sensation "reflex_jolt": the name is used twice)");

    f = good;
    f.sensations[1].name = "two words";
    EXPECT_THAT(message_of(f), HasSubstr("the name is not valid"));

    f = good;
    f.sensations[0].effects.push_back(f.sensations[0].effects[0]);
    EXPECT_EQ(message_of(f), R"(cannot write sensation "reflex_jolt": a sensation that is not a compound has exactly one effect, found 2)");

    f = good;
    f.sensations[2].effects.clear();
    EXPECT_EQ(message_of(f), R"(cannot write sensation "burst": it has no effects)");

    f = good;
    f.sensations[0].description = std::string("caf\xC3", 4);
    EXPECT_EQ(message_of(f), R"(cannot write sensation "reflex_jolt": the description is not valid UTF-8)");

    f = good;
    f.sensations[2].effects[0].samples.pop_back();  // 3 samples, count says 4
    EXPECT_THAT(message_of(f), HasSubstr("effects[0].custom.samples: the number of samples passed must equal"));
}

}  // namespace
}  // namespace feel::format::test
