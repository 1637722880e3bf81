// EffectParams -> PID reports, checked against the protocol's definitions: one condition
// block per axis, Custom Force Data in chunks of kSamplesPerDataReport at increasing
// offsets before Set Custom Force, PID's "infinite" for endless durations and loops, the
// envelope only when the effect has one.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/effect_reports.hpp"
#include "support/valid_effects.hpp"

namespace feel::protocol {
namespace {

TEST(EffectReports, SetEffectCarriesTheEffectStructure) {
    EffectParams p = feel::test::valid_effect(EffectType::sine);
    p.duration_us = kInfiniteUs;
    p.iterations = kInfiniteIterations;
    p.start_delay_us = 2500;
    p.gain = 7000;
    p.trigger = {TriggerKind::hat, 1};
    p.trigger_repeat_interval_us = 300'000;
    const SetEffectReport r = set_effect_report(p, 7);
    EXPECT_EQ(r.block, 7);
    EXPECT_EQ(r.type, EffectType::sine);
    EXPECT_EQ(r.duration_us, kWireInfinite);
    EXPECT_EQ(r.iterations, kLoopInfinite);
    EXPECT_EQ(r.start_delay_us, 2500u);
    EXPECT_EQ(r.gain, 7000);
    EXPECT_EQ(r.trigger_kind, TriggerKind::hat);
    EXPECT_EQ(r.trigger_index, 1);
    EXPECT_EQ(r.trigger_repeat_interval_us, 300'000u);
    EXPECT_EQ(r.axis_count, 1);
    p.duration_us = 40'000;
    p.iterations = 3;
    EXPECT_EQ(set_effect_report(p, 7).duration_us, 40'000u);
    EXPECT_EQ(set_effect_report(p, 7).iterations, 3);
}

TEST(EffectReports, OneConditionBlockPerAxis) {
    const EffectParams p = feel::test::valid_effect(EffectType::spring);  // x and y
    const auto reports = parameter_block_reports(p, {}, 2, true, true);
    ASSERT_EQ(reports.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        const auto& c = std::get<SetConditionReport>(reports[i]);
        EXPECT_EQ(c.block, 2);
        EXPECT_EQ(c.axis_index, i);
        EXPECT_EQ(c.pos_coefficient, 1000);  // §7.5's spring
        EXPECT_EQ(c.pos_saturation, 10000);
    }
}

TEST(EffectReports, AConditionWithADirectionSendsItsOneBlock) {
    // §3.1: one block applied along the direction, so one Set Condition (axis 0).
    EffectParams p = feel::test::valid_effect(EffectType::friction);  // x and y
    p.direction = {DirectionKind::polar, {4500, 0, 0}};
    p.conditions[1] = {};
    const auto reports = parameter_block_reports(p, {}, 3, true, true);
    ASSERT_EQ(reports.size(), 1u);
    const auto& c = std::get<SetConditionReport>(reports[0]);
    EXPECT_EQ(c.axis_index, 0);
    EXPECT_EQ(c.pos_coefficient, 1000);
    EXPECT_EQ(set_effect_report(p, 3).direction_kind, DirectionKind::polar);
}

TEST(EffectReports, ForceProfileSamplesGoInChunksBeforeSetCustomForce) {
    EffectParams p;
    p.type = EffectType::force_profile;
    p.duration_us = 70'000;
    p.custom = {1, 1000, 70};
    std::vector<int16_t> samples(70);
    std::iota(samples.begin(), samples.end(), int16_t{-35});
    const auto reports = parameter_block_reports(p, samples, 1, true, true);
    // ceil(70 / 24) = 3 data reports: 24 + 24 + 22, then the block.
    ASSERT_EQ(reports.size(), 4u);
    int expected_offset = 0;
    for (int i = 0; i < 3; ++i) {
        const auto& d = std::get<CustomForceDataReport>(reports[i]);
        EXPECT_EQ(d.offset, expected_offset);
        EXPECT_EQ(d.count, i < 2 ? 24 : 22);
        EXPECT_EQ(d.samples[0], samples[static_cast<std::size_t>(expected_offset)]);
        expected_offset += d.count;
    }
    const auto& c = std::get<SetCustomForceReport>(reports[3]);
    EXPECT_EQ(c.sample_count, 70);
    EXPECT_EQ(c.sample_period_us, 1000u);
    EXPECT_EQ(create_new_effect_report(p, samples).sample_count, 70);
    EXPECT_EQ(create_new_effect_report(feel::test::valid_effect(EffectType::sine), {}).sample_count, 0);
}

TEST(EffectReports, EnvelopeOnlyWhenTheEffectHasOneAndWhenAsked) {
    EffectParams p = feel::test::valid_effect(EffectType::square);
    p.has_envelope = true;
    p.envelope = {8000, 30'000, 0, 0};
    auto reports = parameter_block_reports(p, {}, 1, true, true);
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_EQ(std::get<SetEnvelopeReport>(reports[0]).impulse_level, 8000);
    EXPECT_EQ(std::get<SetEnvelopeReport>(reports[0]).settle_time_us, 30'000u);
    EXPECT_TRUE(std::holds_alternative<SetPeriodicReport>(reports[1]));
    // Only the envelope (a set_parameters with kEnvelope).
    reports = parameter_block_reports(p, {}, 1, true, false);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<SetEnvelopeReport>(reports[0]));
    p.has_envelope = false;
    EXPECT_TRUE(parameter_block_reports(p, {}, 1, true, false).empty());
}

TEST(EffectReports, SweepsSendPeriodicAndSweepBlocks) {
    EffectParams p = feel::test::valid_effect(EffectType::sweep_sine);
    p.periodic.sweep_start_angle = 0;
    p.periodic.sweep_end_angle = 9000;
    p.periodic.sweep_sense = SweepSense::counterclockwise;
    const auto reports = parameter_block_reports(p, {}, 1, false, true);
    ASSERT_EQ(reports.size(), 2u);
    const auto& s = std::get<SetSweepReport>(reports[1]);
    EXPECT_EQ(s.end_angle, 9000);
    EXPECT_EQ(s.sense, SweepSense::counterclockwise);
}

TEST(EffectReports, ControlLawDynamicsSendOneLawPerAxis) {
    EffectParams p;
    p.type = EffectType::dynamic_control_law;
    p.axis_count = 2;
    p.dynamic.control_law[0].mass = 100;
    p.dynamic.control_law[1].mass = 200;
    const auto reports = parameter_block_reports(p, {}, 5, false, true);
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<SetDynamicReport>(reports[0]));
    EXPECT_EQ(std::get<SetControlLawReport>(reports[1]).law.mass, 100);
    EXPECT_EQ(std::get<SetControlLawReport>(reports[2]).axis_index, 1);
    EXPECT_EQ(std::get<SetControlLawReport>(reports[2]).law.mass, 200);
}

TEST(EffectReports, EveryValidEffectEncodes) {
    // Every report built for a valid effect of each type is within its wire ranges.
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        EffectParams p = feel::test::valid_effect(t);
        const std::span<const int16_t> samples =
            t == EffectType::force_profile ? std::span<const int16_t>(feel::test::kFourSamples) : std::span<const int16_t>();
        EXPECT_NO_THROW((void)encode(set_effect_report(p, 1))) << effect_type_name(t);
        EXPECT_NO_THROW((void)encode(create_new_effect_report(p, samples))) << effect_type_name(t);
        for (const auto& r : parameter_block_reports(p, samples, 1, true, true)) {
            EXPECT_NO_THROW((void)encode(r)) << effect_type_name(t);
        }
    }
}

}  // namespace
}  // namespace feel::protocol
