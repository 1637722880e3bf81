// DirectInput effect files: files made by our writer from known DIEFFECT values, and three
// real files of the DirectX 7 SDK (tests/import/data/ORIGIN.md), import to the values the
// mapping of docs/import.md gives. The expectations are DirectInput's definitions (units:
// magnitudes 0..10000, µs, hundredths of a degree; DIJOFS_BUTTON(n) = 48 + n; DirectInput's
// +y toward the user, feel's +y forward) applied by hand, not the importer's output.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "feel/import/import.hpp"
#include "import/ffe_writer.hpp"

namespace feel::import {
namespace {

using test::DiFileEffect;
using test::ffe_file;

ImportResult import(const std::string& bytes) { return import_ffe(bytes, ImportOptions{}); }

std::string ffe_error_of(const std::string& bytes) {
    try {
        (void)import(bytes);
    } catch (const ImportError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string read_data(const char* name) {
    std::ifstream in(std::string(FEEL_SOURCE_DIR) + "/tests/import/data/" + name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FfeImport, SineWithEnvelopeTriggerDelayAndPolarDirection) {
    DiFileEffect e;
    e.name = "Hum";
    e.guid = test::kGuidSine;
    e.duration_us = 2'500'000;
    e.gain = 7000;
    e.trigger_button = 48 + 2;  // DIJOFS_BUTTON2: the third button
    e.trigger_repeat_us = 250'000;
    e.start_delay_us = 120'000;
    e.iterations = 3;
    e.direction = {13500, 0};  // from behind on the right (§6.5.b's example)
    e.envelope = test::DiEnvelope{2000, 300'000, 500, 400'000};
    e.type_specific = {6000, -1000, 9000, 20'000};  // DIPERIODIC magnitude, offset, phase, period
    const ImportResult r = import(ffe_file({e}));
    const format::Sensation& s = r.sensation;
    EXPECT_EQ(s.name, "Hum");
    ASSERT_FALSE(s.compound);
    ASSERT_EQ(s.effects.size(), 1u);
    const EffectParams& p = s.effects[0].params;
    EXPECT_EQ(p.type, EffectType::sine);
    EXPECT_EQ(p.duration_us, 2'500'000);
    EXPECT_EQ(p.gain, 7000);
    EXPECT_EQ(p.trigger.kind, TriggerKind::button);
    EXPECT_EQ(p.trigger.index, 3);
    EXPECT_EQ(p.trigger_repeat_interval_us, 250'000);
    EXPECT_EQ(p.start_delay_us, 120'000);
    EXPECT_EQ(p.iterations, 3);
    ASSERT_EQ(p.axis_count, 2);
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.axes[1], Axis::y);
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], 13500);
    ASSERT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope, (Envelope{2000, 300'000, 500, 400'000}));
    EXPECT_EQ(p.periodic.magnitude, 6000);
    EXPECT_EQ(p.periodic.offset, -1000);
    EXPECT_EQ(p.periodic.phase, 9000);
    EXPECT_EQ(p.periodic.period_us, 20'000);
}

TEST(FfeImport, EveryPredefinedTypeMapsToItsFeelType) {
    struct Case {
        uint8_t guid;
        std::vector<int32_t> type_specific;
        EffectType expected;
    };
    const std::vector<Case> cases = {
        {test::kGuidConstant, {-4000}, EffectType::constant},
        {test::kGuidRamp, {-10000, 5000}, EffectType::ramp},
        {test::kGuidSquare, {5000, 0, 0, 10000}, EffectType::square},
        {test::kGuidSine, {5000, 0, 0, 10000}, EffectType::sine},
        {test::kGuidTriangle, {5000, 0, 0, 10000}, EffectType::triangle},
        {test::kGuidSawUp, {5000, 0, 0, 10000}, EffectType::saw_up},
        {test::kGuidSawDown, {5000, 0, 0, 10000}, EffectType::saw_down},
        {test::kGuidSpring, {0, 5000, 5000, 10000, 10000, 0, 0, 5000, 5000, 10000, 10000, 0}, EffectType::spring},
        {test::kGuidDamper, {0, 5000, 5000, 10000, 10000, 0, 0, 5000, 5000, 10000, 10000, 0}, EffectType::damper},
        {test::kGuidInertia, {0, 5000, 5000, 10000, 10000, 0, 0, 5000, 5000, 10000, 10000, 0}, EffectType::inertia},
        {test::kGuidFriction, {0, 5000, 5000, 10000, 10000, 0, 0, 5000, 5000, 10000, 10000, 0}, EffectType::friction},
    };
    for (const Case& c : cases) {
        DiFileEffect e;
        e.guid = c.guid;
        e.type_specific = c.type_specific;
        const ImportResult r = import(ffe_file({e}));
        EXPECT_EQ(r.sensation.effects.at(0).params.type, c.expected) << effect_type_name(c.expected);
    }
    DiFileEffect ramp;
    ramp.guid = test::kGuidRamp;
    ramp.type_specific = {-10000, 5000};
    const EffectParams p = import(ffe_file({ramp})).sensation.effects.at(0).params;
    EXPECT_EQ(p.ramp.start, -10000);
    EXPECT_EQ(p.ramp.end, 5000);
}

TEST(FfeImport, CartesianDirectionFlipsDirectInputsY) {
    // DirectInput's (0, 1) comes from +y there: toward the user, which is feel's -y.
    DiFileEffect e;
    e.flags = test::kObjectOffsets | test::kCartesian;
    e.direction = {0, 1};
    e.guid = test::kGuidConstant;
    e.type_specific = {5000};
    const EffectParams p = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_EQ(p.direction.kind, DirectionKind::cartesian);
    EXPECT_EQ(p.direction.value[0], 0);
    EXPECT_EQ(p.direction.value[1], -10000);
    // (3, -4): x from +x, y from DirectInput's -y (away from the user) = feel's +y.
    e.direction = {3, -4};
    const EffectParams q = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_EQ(q.direction.value[0], 7500);   // 3/4 of the largest
    EXPECT_EQ(q.direction.value[1], 10000);
}

TEST(FfeImport, SphericalDirectionBecomesCartesianInFeelsFrame) {
    DiFileEffect e;
    e.flags = test::kObjectOffsets | test::kSpherical;
    e.axes = {test::kDijofsX, test::kDijofsY, test::kDijofsZ};
    e.guid = test::kGuidConstant;
    e.type_specific = {5000};
    e.direction = {9000, 0, 0};  // θ = 90°: from DirectInput's +y (the user's side)
    EffectParams p = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_EQ(p.direction.kind, DirectionKind::cartesian);
    EXPECT_EQ(p.direction.value[0], 0);
    EXPECT_EQ(p.direction.value[1], -10000);
    EXPECT_EQ(p.direction.value[2], 0);
    e.direction = {0, 9000, 0};  // φ = 90°: from +z
    p = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_EQ(p.direction.value[0], 0);
    EXPECT_EQ(p.direction.value[1], 0);
    EXPECT_EQ(p.direction.value[2], 10000);
}

TEST(FfeImport, PerAxisConditionOnYSwapsItsSides) {
    DiFileEffect e;
    e.guid = test::kGuidSpring;
    // x: offset 1000, +coef 2000, -coef 3000, +sat 4000, -sat 5000, deadband 600; y: the same.
    e.type_specific = {1000, 2000, 3000, 4000, 5000, 600, 1000, 2000, 3000, 4000, 5000, 600};
    const EffectParams p = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_EQ(p.direction.kind, DirectionKind::none);
    EXPECT_EQ(p.conditions[0], (ConditionBlock{2000, 3000, 1000, 4000, 5000, 600}));
    // DirectInput's +y side is feel's -y side: offset negated, sides swapped.
    EXPECT_EQ(p.conditions[1], (ConditionBlock{3000, 2000, -1000, 5000, 4000, 600}));
}

TEST(FfeImport, OneConditionOnTwoAxesActsAlongTheDirection) {
    DiFileEffect e;
    e.guid = test::kGuidDamper;
    e.direction = {9000, 0};
    e.type_specific = {0, 4000, 4000, 10000, 10000, 0};
    const EffectParams p = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_TRUE(is_directed_condition(p));
    EXPECT_EQ(p.direction.value[0], 9000);
    EXPECT_EQ(p.conditions[0].pos_coefficient, 4000);
}

TEST(FfeImport, CustomForceBecomesAForceProfile) {
    DiFileEffect e;
    e.guid = test::kGuidCustom;
    e.flags = test::kObjectOffsets | test::kCartesian;
    e.axes = {test::kDijofsX};
    e.direction = {0};
    e.type_specific = {1, 5000, 4, 0};  // cChannels, dwSamplePeriod, cSamples, rglForceData
    e.custom_samples = std::vector<int32_t>{0, 10000, -10000, 2500};
    e.duration_us = 20'000;
    const format::EffectSpec spec = import(ffe_file({e})).sensation.effects.at(0);
    EXPECT_EQ(spec.params.type, EffectType::force_profile);
    EXPECT_EQ(spec.params.custom.channels, 1);
    EXPECT_EQ(spec.params.custom.sample_period_us, 5000);
    EXPECT_EQ(spec.params.custom.sample_count, 4);
    EXPECT_EQ(spec.samples, (std::vector<int16_t>{0, 10000, -10000, 2500}));
    EXPECT_EQ(spec.params.direction.kind, DirectionKind::none);  // one axis, zero direction: own sign
}

TEST(FfeImport, SeveralEffectsAreACompoundAndDx5EffectsHaveNoDelay) {
    DiFileEffect a;
    a.name = "A";
    a.guid = test::kGuidConstant;
    a.type_specific = {3000};
    a.start_delay_us = 0;
    DiFileEffect b = a;
    b.name = "B";
    b.dx5 = true;
    b.type_specific = {-3000};
    const format::Sensation s = import(ffe_file({a, b}, true)).sensation;
    EXPECT_TRUE(s.compound);
    ASSERT_EQ(s.effects.size(), 2u);
    EXPECT_EQ(s.effects[0].params.constant.magnitude, 3000);
    EXPECT_EQ(s.effects[1].params.constant.magnitude, -3000);
    EXPECT_EQ(s.effects[1].params.start_delay_us, 0);
    EXPECT_NE(s.description->find("A, B"), std::string::npos);
}

TEST(FfeImport, InfiniteDurationAndNoTrigger) {
    DiFileEffect e;
    e.guid = test::kGuidConstant;
    e.type_specific = {3000};
    e.duration_us = test::kDiInfinite;
    const EffectParams p = import(ffe_file({e})).sensation.effects.at(0).params;
    EXPECT_EQ(p.duration_us, kInfiniteUs);
    EXPECT_EQ(p.trigger.kind, TriggerKind::none);
    EXPECT_EQ(p.trigger_repeat_interval_us, 0);
}

// Real files (tests/import/data/ORIGIN.md); the values were read from a hex dump.
TEST(FfeImport, RealFileClick1) {
    const format::Sensation s = import_sensation(read_data("click1.ffe"), "click1.ffe", {}).sensation;
    EXPECT_EQ(s.name, "click1");
    ASSERT_EQ(s.effects.size(), 1u);
    const EffectParams& p = s.effects[0].params;
    EXPECT_EQ(p.type, EffectType::ramp);
    EXPECT_EQ(p.duration_us, 25'000);
    EXPECT_EQ(p.gain, 10000);
    EXPECT_EQ(p.trigger.kind, TriggerKind::button);  // 0x30 = DIJOFS_BUTTON0
    EXPECT_EQ(p.trigger.index, 1);
    EXPECT_EQ(p.trigger_repeat_interval_us, 0);      // INFINITE: no repeat
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], 0);
    EXPECT_EQ(p.ramp.start, -10000);
    EXPECT_EQ(p.ramp.end, 0);
    EXPECT_FALSE(p.has_envelope);
}

TEST(FfeImport, RealFileMagnetaHasEnvelopeAndDelay) {
    const format::Sensation s = import_sensation(read_data("magneta.ffe"), "magneta.ffe", {}).sensation;
    ASSERT_EQ(s.effects.size(), 1u);
    const EffectParams& p = s.effects[0].params;
    EXPECT_EQ(p.type, EffectType::constant);
    EXPECT_EQ(p.duration_us, 6'874'000);
    EXPECT_EQ(p.start_delay_us, 455'000);
    EXPECT_EQ(p.direction.value[0], 9000);
    EXPECT_EQ(p.constant.magnitude, -10000);
    ASSERT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope, (Envelope{0, 962'360, 0, 1'099'840}));
}

TEST(FfeImport, RealFileSlidingIsAFrictionAndASpring) {
    const format::Sensation s = import_sensation(read_data("sliding.ffe"), "sliding.ffe", {}).sensation;
    EXPECT_TRUE(s.compound);
    ASSERT_EQ(s.effects.size(), 2u);
    EXPECT_EQ(s.effects[0].params.type, EffectType::friction);
    EXPECT_EQ(s.effects[0].params.duration_us, 10'000'000);
    EXPECT_EQ(s.effects[0].params.conditions[0].pos_coefficient, -10000);
    EXPECT_EQ(s.effects[0].params.conditions[0].neg_coefficient, -10000);
    EXPECT_EQ(s.effects[1].params.type, EffectType::spring);
    EXPECT_EQ(s.effects[1].params.conditions[0].offset, -2600);
    EXPECT_EQ(s.effects[1].params.conditions[1].offset, 0);
}

TEST(FfeImport, ErrorsNameTheFieldAndTheAllowedRange) {
    DiFileEffect e;
    e.guid = test::kGuidSine;
    e.type_specific = {12000, 0, 0, 10000};
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("DIPERIODIC.dwMagnitude = 12000 is out of range (allowed 0..10000)"),
              std::string::npos);
    e.type_specific = {5000, 0, 36000, 10000};
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("DIPERIODIC.dwPhase = 36000 is out of range (allowed 0..35999)"),
              std::string::npos);
    e.type_specific = {5000, 0, 0, 10000};
    e.guid = 0x77;
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("unknown effect GUID {13541C77-8E33-11D0-9AD0-00A0C9A06E35}"),
              std::string::npos);
    e.guid = test::kGuidSine;
    e.trigger_button = 12;
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("dwTriggerButton = 12 is not a button: allowed DIJOFS_BUTTON0..31 (48..79)"),
              std::string::npos);
    e.trigger_button = test::kDiInfinite;
    e.flags = 0x01 | test::kPolar;
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("DIEFF_OBJECTIDS"), std::string::npos);
    e.flags = test::kObjectOffsets | test::kPolar;
    e.axes = {test::kDijofsX, 28};
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("object offset 28"), std::string::npos);
    e.axes = {test::kDijofsX, test::kDijofsY};
    e.type_specific = {5000, 0, 0};
    EXPECT_NE(ffe_error_of(ffe_file({e})).find("cbTypeSpecificParams = 12 for GUID_Sine: DIPERIODIC has 16 bytes"),
              std::string::npos);
    EXPECT_NE(ffe_error_of(std::string("RIFF\0\0\0\0WAVE", 12)).find("not \"FORC\""), std::string::npos);
    EXPECT_NE(ffe_error_of(ffe_file({})).find("holds no effect"), std::string::npos);
}

// Found by fuzz_ffe_import: a RIFF size smaller than the form type and the file's GUID
// made the body end before it began (a crash, not an error).
TEST(FfeImport, ARiffSizeSmallerThanItsHeaderIsRefusedWithTheAllowedRange) {
    DiFileEffect e;
    e.type_specific = {5000, 0, 0, 10000};
    std::string file = ffe_file({e});
    for (const int size : {1, 3, 19}) {
        file[4] = static_cast<char>(size);
        file[5] = file[6] = file[7] = 0;
        const std::string msg = ffe_error_of(file);
        EXPECT_NE(msg.find("the RIFF header says " + std::to_string(size) + " bytes follow it (allowed 0"),
                  std::string::npos)
            << msg;
    }
}

TEST(FfeImport, EveryTruncationIsAClearErrorNeverACrash) {
    DiFileEffect e;
    e.envelope = test::DiEnvelope{0, 1000, 0, 1000};
    e.type_specific = {5000, 0, 0, 10000};
    const std::string whole = ffe_file({e, e});
    for (size_t n = 0; n < whole.size(); ++n) {
        // The RIFF size still names the whole file, so every cut is a truncation.
        const std::string msg = ffe_error_of(whole.substr(0, n));
        EXPECT_NE(msg, "(no error)") << n;
        if (n >= 12) {
            EXPECT_NE(msg.find("truncated"), std::string::npos) << n << ": " << msg;
        }
    }
    // With the RIFF size 0 (Force Editor), a cut inside a chunk names the chunk.
    const std::string zero = ffe_file({e}, true);
    const std::string msg = ffe_error_of(zero.substr(0, zero.size() - 6));
    EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
}

}  // namespace
}  // namespace feel::import
