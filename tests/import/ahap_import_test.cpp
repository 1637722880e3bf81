// Apple AHAP: events at known times and parameters give the waves docs/import.md
// documents (f(s) = 30 + 70·s Hz; magnitude 10000·intensity; times in µs; a transient is
// one period faded to 0; attack and release are the envelope's settle and fade).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "feel/import/import.hpp"

namespace feel::import {
namespace {

std::string pattern(const std::string& entries) {
    return R"({"Version": 1.0, "Metadata": {"Project": "test"}, "Pattern": [)" + entries + "]}";
}

std::string transient(double t, double i, double s) {
    return R"({"Event": {"Time": )" + std::to_string(t) +
           R"(, "EventType": "HapticTransient", "EventParameters": [{"ParameterID": "HapticIntensity", "ParameterValue": )" +
           std::to_string(i) + R"(}, {"ParameterID": "HapticSharpness", "ParameterValue": )" + std::to_string(s) + "}]}}";
}

std::string ahap_error_of(const std::string& text) {
    try {
        (void)import_ahap(text, {});
    } catch (const ImportError& e) {
        return e.what();
    }
    return "(no error)";
}

int64_t period_us(double sharpness) { return std::llround(1e6 / (30.0 + 70.0 * sharpness)); }

TEST(AhapImport, TransientIsOneFadingPeriodOfASine) {
    const ImportResult r = import_ahap(pattern(transient(0.25, 0.8, 0.5)), {});
    ASSERT_EQ(r.sensation.effects.size(), 1u);
    const EffectParams& p = r.sensation.effects[0].params;
    EXPECT_EQ(p.type, EffectType::sine);
    EXPECT_EQ(p.start_delay_us, 250'000);
    EXPECT_EQ(p.periodic.magnitude, 8000);
    EXPECT_EQ(p.periodic.period_us, period_us(0.5));  // 65 Hz: 15385 µs
    EXPECT_EQ(p.periodic.period_us, 15385);
    EXPECT_EQ(p.duration_us, 15385);
    ASSERT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope, (Envelope{8000, 0, 0, 15385}));
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.direction.kind, DirectionKind::none);
}

TEST(AhapImport, ContinuousEventHasAttackAndReleaseOnTheChosenAxis) {
    const std::string event = R"({"Event": {"Time": 1.0, "EventType": "HapticContinuous", "EventDuration": 2.0,
        "EventParameters": [{"ParameterID": "HapticIntensity", "ParameterValue": 0.5},
                            {"ParameterID": "HapticSharpness", "ParameterValue": 0.0},
                            {"ParameterID": "AttackTime", "ParameterValue": 0.1},
                            {"ParameterID": "ReleaseTime", "ParameterValue": 0.3}]}})";
    ImportOptions o;
    o.axis = Axis::y;
    const ImportResult r = import_ahap(pattern(event + "," + transient(0, 1, 1)), o);
    ASSERT_EQ(r.sensation.effects.size(), 2u);
    EXPECT_TRUE(r.sensation.compound);
    const EffectParams& p = r.sensation.effects[0].params;
    EXPECT_EQ(p.axes[0], Axis::y);
    EXPECT_EQ(p.start_delay_us, 1'000'000);
    EXPECT_EQ(p.duration_us, 2'000'000);
    EXPECT_EQ(p.periodic.magnitude, 5000);
    EXPECT_EQ(p.periodic.period_us, 33333);  // 30 Hz
    EXPECT_EQ(p.envelope, (Envelope{0, 100'000, 0, 300'000}));
    EXPECT_EQ(r.sensation.effects[1].params.periodic.period_us, 10000);  // sharpness 1: 100 Hz
}

TEST(AhapImport, NotSustainedEndsAfterAttackAndDecay) {
    const std::string event = R"({"Event": {"Time": 0, "EventType": "HapticContinuous", "EventDuration": 5,
        "EventParameters": [{"ParameterID": "AttackTime", "ParameterValue": 0.2},
                            {"ParameterID": "DecayTime", "ParameterValue": 0.5},
                            {"ParameterID": "Sustained", "ParameterValue": false}]}})";
    const EffectParams p = import_ahap(pattern(event), {}).sensation.effects.at(0).params;
    EXPECT_EQ(p.duration_us, 700'000);
    EXPECT_EQ(p.periodic.magnitude, 10000);  // Core Haptics' default intensity 1
    EXPECT_EQ(p.envelope, (Envelope{0, 200'000, 0, 500'000}));
}

TEST(AhapImport, IntensityCurveBecomesStraightEnvelopeSegments) {
    const std::string event = R"({"Event": {"Time": 0, "EventType": "HapticContinuous", "EventDuration": 1,
        "EventParameters": [{"ParameterID": "HapticSharpness", "ParameterValue": 0.5}]}})";
    const std::string curve = R"({"ParameterCurve": {"ParameterID": "HapticIntensityControl", "Time": 0,
        "ParameterCurveControlPoints": [{"Time": 0, "ParameterValue": 0}, {"Time": 0.5, "ParameterValue": 1},
                                        {"Time": 1, "ParameterValue": 0.2}]}})";
    const ImportResult r = import_ahap(pattern(event + "," + curve), {});
    ASSERT_EQ(r.sensation.effects.size(), 2u);
    const EffectParams& up = r.sensation.effects[0].params;
    const EffectParams& down = r.sensation.effects[1].params;
    EXPECT_EQ(up.start_delay_us, 0);
    EXPECT_EQ(up.duration_us, 500'000);
    EXPECT_EQ(up.periodic.magnitude, 10000);
    EXPECT_EQ(up.envelope, (Envelope{0, 500'000, 0, 0}));  // 0 → 1 over the segment
    EXPECT_EQ(down.start_delay_us, 500'000);
    EXPECT_EQ(down.duration_us, 500'000);
    EXPECT_EQ(down.envelope, (Envelope{0, 0, 2000, 500'000}));  // 1 → 0.2
    // 0.5 s of a 65 Hz sine is 32.5 cycles: the second segment starts half a cycle in.
    EXPECT_EQ(down.periodic.phase, 18000);
}

TEST(AhapImport, WhatCannotBeMappedIsANote) {
    const std::string audio = R"({"Event": {"Time": 0, "EventType": "AudioCustom", "EventWaveformPath": "a.wav"}})";
    const std::string sharp = R"({"ParameterCurve": {"ParameterID": "HapticSharpnessControl", "Time": 0,
        "ParameterCurveControlPoints": [{"Time": 0, "ParameterValue": 0.1}]}})";
    const std::string param = R"({"Parameter": {"ParameterID": "HapticIntensityControl", "Time": 0, "ParameterValue": 0.5}})";
    const ImportResult r = import_ahap(pattern(transient(0, 1, 0) + "," + audio + "," + sharp + "," + param), {});
    EXPECT_EQ(r.sensation.effects.size(), 1u);
    ASSERT_EQ(r.notes.size(), 3u);
    EXPECT_NE(r.notes[0].find("HapticSharpnessControl"), std::string::npos);
    EXPECT_NE(r.notes[1].find("\"Parameter\""), std::string::npos);
    EXPECT_NE(r.notes[2].find("AudioCustom"), std::string::npos);
}

TEST(AhapImport, ErrorsNameTheEntryAndTheRange) {
    EXPECT_NE(ahap_error_of(pattern(transient(0, 1.5, 0))).find(
                  "Pattern[0].Event.EventParameters[0]: HapticIntensity = 1.5 is out of range (allowed 0..1)"),
              std::string::npos);
    EXPECT_NE(ahap_error_of(pattern(transient(-1, 1, 0))).find("Time (s) = -1 is out of range (allowed 0..65)"),
              std::string::npos);
    EXPECT_NE(ahap_error_of(pattern(transient(70, 1, 0))).find("allowed 0..65"), std::string::npos);
    EXPECT_NE(ahap_error_of("{\"Pattern\": [").find("not valid JSON"), std::string::npos);
    // Found by fuzz_ahap_import: a number too large for a double is the JSON reader's
    // out_of_range, not its parse_error, and escaped the importer.
    EXPECT_NE(ahap_error_of(pattern(R"({"Event": {"Time": 1e999, "EventType": "HapticTransient"}})")).find("not valid JSON"),
              std::string::npos);
    EXPECT_NE(ahap_error_of("{}").find("\"Pattern\" is missing"), std::string::npos);
    EXPECT_NE(ahap_error_of(pattern("")).find("holds no haptic event"), std::string::npos);
    EXPECT_NE(ahap_error_of(pattern(R"({"Event": {"Time": 0, "EventType": "Buzz"}})")).find("EventType \"Buzz\""),
              std::string::npos);
    EXPECT_NE(ahap_error_of(pattern(R"({"Event": {"Time": 0, "EventType": "HapticContinuous", "EventDuration": 0}})"))
                  .find("EventDuration = 0"),
              std::string::npos);
    EXPECT_NE(ahap_error_of(pattern(R"({"Event": {"Time": "soon", "EventType": "HapticTransient"}})")).find("must be a number"),
              std::string::npos);
}

}  // namespace
}  // namespace feel::import
