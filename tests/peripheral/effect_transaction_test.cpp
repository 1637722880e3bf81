// The effect transaction of docs/peripheral.md, driven in encoded reports: Create New
// Effect, Block Load, the type blocks, Set Effect, Effect Operation, Block Free; and what
// the device then does physically.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "feel/protocol/descriptor_parser.hpp"
#include "session_rig.hpp"
#include "support/valid_effects.hpp"

namespace feel::peripheral::test {
namespace {

using protocol::EffectOperation;
using protocol::ReportId;

TEST(EffectTransaction, SpringOnXFeelsMinusKTimesX) {
    // A kinematic hand holds the handle at x = 5000 (half the travel to the right).
    SessionRig rig("iforce2", "hold:5000", sim::Grip::kinematic);
    const uint16_t block = rig.create(EffectType::spring);
    ASSERT_EQ(block, 1);

    constexpr int16_t k = 1000;  // 0.1 force units per position unit
    rig.ok(spring_axis(rig.next_sequence(), block, 0, k));
    protocol::SetEffectReport e = set_effect(rig.next_sequence(), block, EffectType::spring);
    e.axes[0] = Axis::x;
    const protocol::CommandAnswer committed = rig.ok(e);
    EXPECT_EQ(committed.command, ReportId::set_effect);
    EXPECT_EQ(committed.block, block);
    ASSERT_TRUE(rig.session().block(block)->committed);
    EXPECT_EQ(rig.pipeline().resident_effects(), 1);

    const auto start = rig.ok(operation(rig.next_sequence(), block, EffectOperation::start));
    EXPECT_EQ(start.effect_state, static_cast<uint8_t>(runtime::ReportedEffectState::playing));
    rig.run(20);

    // §3.3 and docs/conditions.md: F = -k·(x - offset)/10000, with x the sensed position
    // (5000 rounded to the sensor's step of 20000/4096 units).
    const double x = rig.pipeline().last_input().position[0];
    EXPECT_NEAR(x, 5000, 20000.0 / 4096);
    const double expected = -k * x / 10000.0;
    EXPECT_NEAR(rig.pipeline().motor_force()[0], expected, 1e-3);
    EXPECT_NEAR(rig.pipeline().motor_force()[0], -500, 0.3);
    EXPECT_NEAR(rig.pipeline().motor_force()[1], 0, 1e-6);  // the spring is on x only

    // The host sees the same force in its Device Status reports, and the effect playing.
    ASSERT_FALSE(rig.device_status.empty());
    const protocol::DeviceStatusReport& s = rig.device_status.back();
    EXPECT_NEAR(s.force[0], expected, 0.5);
    ASSERT_FALSE(rig.effect_states.empty());
    const protocol::EffectStatesReport& states = rig.effect_states.back();
    EXPECT_EQ(states.report_number, s.report_number);  // the Device Status it follows
    ASSERT_EQ(states.effect_count, 1);
    EXPECT_EQ(states.effect_block[0], block);
    EXPECT_EQ(states.effect_state[0], static_cast<uint8_t>(runtime::ReportedEffectState::playing));
    ASSERT_FALSE(rig.joystick.empty());
    EXPECT_NEAR(rig.joystick.back().position[0], 5000, 3);

    // PID State told the host once that block 1 plays.
    int playing_reports = 0;
    for (const protocol::PidStateReport& p : rig.pid_states) {
        if (p.block == block) {
            EXPECT_TRUE(p.effect_playing);
            ++playing_reports;
        }
    }
    EXPECT_EQ(playing_reports, 1);

    // Stop: no force; PID State says it stopped.
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::stop));
    rig.run(5);
    EXPECT_EQ(rig.pipeline().motor_force()[0], 0.0f);
    ASSERT_FALSE(rig.pid_states.empty());
    EXPECT_EQ(rig.pid_states.back().block, block);
    EXPECT_FALSE(rig.pid_states.back().effect_playing);

    // Block Free: the engine holds nothing, the block is free again.
    protocol::BlockFreeReport f;
    f.sequence = rig.next_sequence();
    f.block = block;
    rig.ok(f);
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
    EXPECT_EQ(rig.session().allocated_blocks(), 0);
    const auto pool = rig.get<protocol::PidPoolReport>(ReportId::pid_pool);
    EXPECT_EQ(pool.free_effects, rig.caps().effect_slots);
    EXPECT_EQ(pool.ram_pool_available, pool.ram_pool_size);
}

TEST(EffectTransaction, EveryAnswerCarriesItsSequenceInTheHostsOrder) {
    SessionRig rig;
    // Several reports at once, some judged by the session alone, some by the runtime.
    protocol::CreateNewEffectReport c;
    c.sequence = 7;
    c.type = EffectType::sine;
    rig.offer(set_feature(c));
    rig.offer(output(periodic(8, 1, 3000, 20'000)));
    rig.offer(output(set_effect(9, 1, EffectType::sine)));
    rig.offer(output(operation(10, 1, EffectOperation::start, 3)));
    protocol::KeepAliveReport k;
    k.sequence = 11;
    rig.offer(output(k));
    protocol::DeviceGainReport g;
    g.sequence = 12;
    g.gain = 5000;
    rig.offer(output(g));
    rig.run(10);
    ASSERT_EQ(rig.statuses.size(), 6u);
    for (uint32_t i = 0; i < 6; ++i) {
        EXPECT_EQ(rig.statuses[i].sequence, 7 + i);
        EXPECT_EQ(rig.statuses[i].code, ErrorCode::ok) << rig.statuses[i].field << ": " << rig.statuses[i].rule;
    }
    EXPECT_EQ(rig.statuses[3].iterations, 3);  // the loop count of this play
    EXPECT_EQ(rig.pipeline().engine().gain(), 5000);
}

TEST(EffectTransaction, LoopCountMapsToIterations) {
    SessionRig rig;
    const uint16_t block = rig.create(EffectType::square);
    rig.ok(periodic(rig.next_sequence(), block, 4000, 10'000));
    protocol::SetEffectReport e = set_effect(rig.next_sequence(), block, EffectType::square);
    e.duration_us = 50'000;
    e.iterations = 2;
    rig.ok(e);
    // 0: the effect's own count (2); 5: five; 255: 255 times (the 16-bit loop count of a
    // feel device); 0xFFFF, the field's null: infinite.
    EXPECT_EQ(rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 0)).iterations, 2);
    EXPECT_EQ(rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 5)).iterations, 5);
    EXPECT_EQ(rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 255)).iterations, 255);
    EXPECT_EQ(rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, 0xFFFF)).iterations, 0xFFFF);
}

TEST(EffectTransaction, StartSoloStopsTheOthers) {
    SessionRig rig;
    uint16_t blocks[2];
    for (uint16_t& b : blocks) {
        b = rig.create(EffectType::sine);
        rig.ok(periodic(rig.next_sequence(), b, 2000, 10'000));
        rig.ok(set_effect(rig.next_sequence(), b, EffectType::sine));
    }
    rig.ok(operation(rig.next_sequence(), blocks[0], EffectOperation::start, protocol::kLoopInfinite));
    rig.ok(operation(rig.next_sequence(), blocks[1], EffectOperation::start_solo, protocol::kLoopInfinite));
    rig.run(3);
    EXPECT_EQ(rig.pipeline().engine().state(rig.session().block(blocks[0])->effect), EffectState::stopped);
    EXPECT_NE(rig.pipeline().engine().state(rig.session().block(blocks[1])->effect), EffectState::stopped);
}

TEST(EffectTransaction, PartialUpdateOfAPlayingSineKeepsItPlaying) {
    SessionRig rig;
    const uint16_t block = rig.create(EffectType::sine);
    rig.ok(periodic(rig.next_sequence(), block, 2000, 20'000));
    rig.ok(set_effect(rig.next_sequence(), block, EffectType::sine));
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start, protocol::kLoopInfinite));
    rig.run(30);
    const EffectId id = rig.session().block(block)->effect;
    const int64_t elapsed_before = rig.pipeline().engine().status(id).elapsed_us;
    ASSERT_GT(elapsed_before, 0);

    // Only the magnitude changes: Set Periodic, then Set Effect with the same structure.
    rig.ok(periodic(rig.next_sequence(), block, 6000, 20'000));
    const auto s = rig.ok(set_effect(rig.next_sequence(), block, EffectType::sine));
    EXPECT_EQ(s.effect_state, static_cast<uint8_t>(runtime::ReportedEffectState::playing));

    EffectParams now;
    ASSERT_TRUE(rig.pipeline().engine().params(id, now).ok());
    EXPECT_EQ(now.periodic.magnitude, 6000);
    EXPECT_EQ(rig.session().block(block)->effect, id);  // updated, not recreated
    // Still playing on its own clock: the update did not restart it.
    EXPECT_EQ(rig.pipeline().engine().state(id), EffectState::playing);
    EXPECT_GE(rig.pipeline().engine().status(id).elapsed_us, elapsed_before);
    // A sine of magnitude 6000 reaches about 6000 within one period.
    float peak = 0;
    for (int i = 0; i < 25; ++i) {
        rig.run(1);
        peak = std::max(peak, std::abs(rig.pipeline().motor_force()[0]));
    }
    EXPECT_GT(peak, 5500);
    EXPECT_LE(peak, 6000.5);
}

TEST(EffectTransaction, SetEffectWithNothingChangedSendsNoCommand) {
    SessionRig rig;
    const uint16_t block = rig.create(EffectType::constant);
    protocol::SetConstantForceReport c;
    c.sequence = rig.next_sequence();
    c.block = block;
    c.magnitude = 3000;
    rig.ok(c);
    rig.ok(set_effect(rig.next_sequence(), block, EffectType::constant));
    const uint64_t commands = rig.session().counters().runtime_commands;
    rig.ok(set_effect(rig.next_sequence(), block, EffectType::constant));
    EXPECT_EQ(rig.session().counters().runtime_commands, commands);
}

TEST(EffectTransaction, ForceProfileSamplesArriveInDataReports) {
    SessionRig rig;
    constexpr uint16_t kSamples = 40;  // one full data report and one of 8
    const uint16_t block = rig.create(EffectType::force_profile, kSamples);
    ASSERT_NE(block, 0);
    for (uint16_t offset = 0; offset < kSamples; offset += protocol::kSamplesPerDataReport) {
        protocol::CustomForceDataReport d;
        d.sequence = rig.next_sequence();
        d.block = block;
        d.offset = offset;
        d.count = static_cast<uint8_t>(std::min<int>(protocol::kSamplesPerDataReport, kSamples - offset));
        for (int i = 0; i < d.count; ++i) d.samples[i] = static_cast<int16_t>(100 * (offset + i));
        rig.ok(d);
    }
    protocol::SetCustomForceReport cf;
    cf.sequence = rig.next_sequence();
    cf.block = block;
    cf.channels = 1;
    cf.sample_period_us = 1000;
    cf.sample_count = kSamples;
    rig.ok(cf);
    protocol::SetEffectReport e = set_effect(rig.next_sequence(), block, EffectType::force_profile);
    e.duration_us = 40'000;
    rig.ok(e);
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start));
    // Sample i is held for 1 ms from i ms on: its force is 100·i.
    rig.run(11);
    const float f = rig.pipeline().motor_force()[0];
    bool matches_a_sample = false;
    for (int i = 0; i < kSamples; ++i) matches_a_sample |= std::abs(f - 100.0f * static_cast<float>(i)) < 0.5f;
    EXPECT_TRUE(matches_a_sample) << f;
    EXPECT_GT(f, 500.0f);
    const auto pool = rig.get<protocol::PidPoolReport>(ReportId::pid_pool);
    EXPECT_EQ(pool.free_samples, pool.sample_memory - kSamples);
}

TEST(EffectTransaction, FeatureGetsAndDescriptor) {
    SessionRig rig("iforce1");
    const auto info = rig.get<protocol::DeviceInfoReport>(ReportId::device_info);
    EXPECT_STREQ(info.device, "iforce1");
    EXPECT_EQ(info.device_class, static_cast<uint8_t>(sim::DeviceClass::iforce1));
    EXPECT_EQ(info.axis_count, 2);
    EXPECT_EQ(info.effect_slots, 16);
    EXPECT_EQ(info.supported_types, rig.caps().supported_types);
    EXPECT_FALSE(info.local_reflexes);
    EXPECT_EQ(info.loop_rate_hz, 1000);
    EXPECT_EQ(info.report_rate_hz, runtime::kDefaultReportRateHz);
    // The joystick's axes: ±50 mm of travel, 4.45 N (docs/simulated-device.md).
    EXPECT_EQ(info.axes[0].half_travel_micro, 50'000u);
    EXPECT_EQ(info.axes[0].max_force_milli, 4450u);

    const auto pool = rig.get<protocol::PidPoolReport>(ReportId::pid_pool);
    EXPECT_EQ(pool.ram_pool_size, 4u * 1024u);
    EXPECT_EQ(pool.ram_pool_available, 4u * 1024u);
    EXPECT_EQ(pool.simultaneous_effects_max, 16);
    EXPECT_EQ(pool.free_effects, 16);
    EXPECT_TRUE(pool.device_managed_pool);

    rig.offer(Frame{FrameKind::get_descriptor, {}});
    rig.run(1);
    ASSERT_EQ(rig.descriptors.size(), 1u);
    // The device's own descriptor: its profile's inputs only (iforce1: X and Y, 4 buttons,
    // 2 hats, read with the independent parser), the PID and vendor reports as always.
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(rig.descriptors[0]);
    ASSERT_TRUE(parse.ok()) << parse.error;
    const protocol::hid::DescriptorReport* joy = parse.descriptor.find(
        protocol::hid::MainItemKind::input, static_cast<uint8_t>(ReportId::joystick_input));
    ASSERT_NE(joy, nullptr);
    std::vector<uint32_t> inputs;
    for (const protocol::hid::DescriptorField& f : joy->fields) {
        for (uint32_t k = 0; !f.is_constant() && k < f.report_count; ++k) inputs.push_back(f.usage_of(k));
    }
    EXPECT_EQ(inputs, (std::vector<uint32_t>{0x00010030u, 0x00010031u, 0x00090001u, 0x00090002u, 0x00090003u,
                                             0x00090004u, 0x00010039u, 0x00010039u}));
    const protocol::hid::DescriptorParse full = protocol::hid::parse_report_descriptor(protocol::report_descriptor());
    EXPECT_EQ(parse.descriptor.reports.size(), full.descriptor.reports.size());

    // The report rate the host sets is the one Device Info reports.
    protocol::ReportRateReport rate;
    rate.sequence = rig.next_sequence();
    rate.rate_hz = 500;
    rig.ok(rate);
    EXPECT_EQ(rig.get<protocol::DeviceInfoReport>(ReportId::device_info).report_rate_hz, 500);
}

TEST(EffectTransaction, EveryTypeArrivesInTheEngineExactlyAsSent) {
    // Each type's blocks, sent as reports, make the very EffectParams they came from: the
    // device translates every field and invents none.
    SessionRig rig;
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        SCOPED_TRACE(effect_type_name(t));
        EffectParams p = feel::test::valid_effect(t);
        std::span<const int16_t> samples;
        if (t == EffectType::force_profile) samples = feel::test::kFourSamples;
        if (supports_envelope(t)) {
            p.has_envelope = true;
            p.envelope = {6000, 20'000, 1000, 30'000};
        }
        p.gain = 8000;
        p.start_delay_us = 1000;
        const uint16_t block = download(rig, p, samples);
        ASSERT_NE(block, 0);
        const auto view = rig.session().block(block);
        ASSERT_TRUE(view && view->committed);
        EffectParams engine;
        ASSERT_TRUE(rig.pipeline().engine().params(view->effect, engine).ok());
        EXPECT_EQ(engine, p);
        EXPECT_EQ(view->committed_params, p);
        protocol::BlockFreeReport f;
        f.sequence = rig.next_sequence();
        f.block = block;
        rig.ok(f);
    }
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
}

TEST(EffectTransaction, TheNewFormsArriveExactlyAsSent) {
    // A condition with a direction (§3.1: one Set Condition, axis 0, and the direction) and
    // a barrier with a relative offset (§3.8) make the very EffectParams they came from.
    SessionRig rig;
    std::vector<EffectParams> forms;
    for (EffectType t : {EffectType::spring, EffectType::damper, EffectType::inertia, EffectType::friction}) {
        EffectParams p = feel::test::valid_effect(t);  // x and y
        p.direction = {DirectionKind::cartesian, {3, -4, 0}};
        p.conditions[1] = {};
        forms.push_back(p);
    }
    EffectParams barrier = feel::test::valid_effect(EffectType::angle_barrier);
    barrier.barrier.offset_mode = OffsetMode::relative;
    forms.push_back(barrier);
    for (const EffectParams& p : forms) {
        SCOPED_TRACE(effect_type_name(p.type));
        const uint16_t block = download(rig, p, {});
        ASSERT_NE(block, 0);
        const auto view = rig.session().block(block);
        ASSERT_TRUE(view && view->committed);
        EffectParams engine;
        ASSERT_TRUE(rig.pipeline().engine().params(view->effect, engine).ok());
        EXPECT_EQ(engine, p);
        protocol::BlockFreeReport f;
        f.sequence = rig.next_sequence();
        f.block = block;
        rig.ok(f);
    }
}

TEST(EffectTransaction, DynamicsReportTheirMassByBlock) {
    SessionRig rig;
    EffectParams p = feel::test::valid_effect(EffectType::dynamic_recoil);
    p.dynamic.interim_reporting = true;
    p.duration_us = kInfiniteUs;
    const uint16_t block = download(rig, p);
    ASSERT_EQ(block, 1);
    rig.ok(operation(rig.next_sequence(), block, EffectOperation::start));
    rig.run(500);  // half a second at 1 kHz
    // Interim reports at the device's interim report rate (Device Info), each naming block 1.
    const double hz = rig.caps().interim_report_hz;
    ASSERT_GT(hz, 0);
    int interim = 0;
    for (const protocol::DynamicReportReport& d : rig.dynamics) {
        EXPECT_EQ(d.block, block);
        EXPECT_EQ(d.axis_count, 2);
        if (d.final_report == 0) ++interim;
    }
    EXPECT_NEAR(interim, 0.5 * hz, 2);
}

}  // namespace
}  // namespace feel::peripheral::test
