// The descriptor-driven PID mapping (feel/protocol/pid_layout.hpp, pid_effect_reports.hpp)
// on real devices' descriptors (tests/protocol/pid_descriptors/README.md says where each
// comes from) and on feel's own.
//
// The truth: the PID 1.0 specification's usages and their meaning, and what each descriptor
// declares, read item by item by hand (the report IDs, sizes and logical ranges below are
// from the devices' published descriptors, not from this code). For feel's descriptor, feel's
// own codec (an independent table-driven decoder) decodes what the generic writer wrote.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../support/valid_effects.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/pid_effect_reports.hpp"
#include "feel/protocol/pid_layout.hpp"

namespace {

using namespace feel;
using namespace feel::protocol::pid;

std::vector<uint8_t> load(const std::string& name) {
    std::ifstream in(std::string(FEEL_SOURCE_DIR) + "/tests/protocol/pid_descriptors/" + name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

PidLayout map_or_fail(const std::vector<uint8_t>& bytes) {
    std::string error;
    std::optional<PidLayout> layout = PidLayout::from_bytes(bytes, error);
    EXPECT_TRUE(layout.has_value()) << error;
    return layout ? *layout : PidLayout{};
}

uint64_t bits(std::initializer_list<EffectType> types) {
    uint64_t out = 0;
    for (EffectType t : types) out |= effect_type_bit(t);
    return out;
}

const uint64_t kPidEleven =
    bits({EffectType::constant, EffectType::ramp, EffectType::square, EffectType::sine, EffectType::triangle,
          EffectType::saw_up, EffectType::saw_down, EffectType::spring, EffectType::damper, EffectType::inertia,
          EffectType::friction});

EffectParams constant(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::constant;
    p.constant.magnitude = magnitude;
    p.duration_us = 500'000;
    return p;
}

// --- Microsoft SideWinder Force Feedback 2 (a real device's descriptor) ------------------

TEST(PidLayoutSidewinderFf2, FindsEachReportUnderItsOwnId) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    // The IDs the FF2 descriptor gives its reports (its Report ID items).
    EXPECT_EQ(l.report(PidReport::set_effect).id, 1);
    EXPECT_EQ(l.report(PidReport::set_envelope).id, 2);
    EXPECT_EQ(l.report(PidReport::set_condition).id, 3);
    EXPECT_EQ(l.report(PidReport::set_periodic).id, 4);
    EXPECT_EQ(l.report(PidReport::set_constant_force).id, 5);
    EXPECT_EQ(l.report(PidReport::set_ramp_force).id, 6);
    EXPECT_EQ(l.report(PidReport::effect_operation).id, 10);
    EXPECT_EQ(l.report(PidReport::block_free).id, 11);
    EXPECT_EQ(l.report(PidReport::device_control).id, 12);
    EXPECT_EQ(l.report(PidReport::device_gain).id, 13);
    EXPECT_EQ(l.report(PidReport::state).id, 2);
    EXPECT_EQ(l.report(PidReport::state).kind, protocol::hid::MainItemKind::input);
    EXPECT_EQ(l.report(PidReport::create_new_effect).kind, protocol::hid::MainItemKind::feature);
    EXPECT_TRUE(l.report(PidReport::block_load).present);
    EXPECT_TRUE(l.report(PidReport::pool).present);
    EXPECT_EQ(l.max_block_index(), 40);  // Effect Block Index: Logical Maximum 40
}

TEST(PidLayoutSidewinderFf2, EnumeratesAndPlaysItsTwelveTypes) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    ASSERT_EQ(l.effect_types().size(), 12u);  // ET Constant .. ET Friction, ET Custom Force Data
    EXPECT_EQ(l.supported_types(), kPidEleven | bits({EffectType::force_profile}));
    const EffectTypeEntry& custom = l.effect_types().back();
    EXPECT_EQ(custom.usage, 0x000F0028u);
    EXPECT_TRUE(custom.usable) << custom.why_not;
    EXPECT_EQ(custom.type, EffectType::force_profile);
    // Its custom force reports: Set Custom Force (ID 14), Custom Force Data (ID 7), and
    // Download Force Sample (ID 8), whose X and Y are the format of one sample.
    EXPECT_EQ(l.report(PidReport::set_custom_force).id, 14);
    EXPECT_EQ(l.report(PidReport::custom_force_data).id, 7);
    EXPECT_EQ(l.report(PidReport::download_force_sample).id, 8);
    EXPECT_EQ(l.sample_axes(), (std::vector<Axis>{Axis::x, Axis::y}));
    ASSERT_EQ(l.axes().size(), 2u);
    EXPECT_EQ(l.axes()[0], Axis::x);
    EXPECT_EQ(l.axes()[1], Axis::y);
}

TEST(PidLayoutSidewinderFf2, ScalesLevelsIntoItsSmallFields) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    std::string error;
    // Set Constant Force: ID 5, Effect Block Index 8 bits, Magnitude 16 bits -255..255.
    std::vector<OutgoingReport> r = effect_reports(l, 3, constant(-10000), error);
    ASSERT_FALSE(r.empty()) << error;
    ASSERT_EQ(r.front().report, PidReport::set_constant_force);
    const std::vector<uint8_t> expected = {5, 3, 0x01, 0xFF};  // -255 little-endian
    EXPECT_EQ(r.front().bytes, expected);
    r = effect_reports(l, 3, constant(5000), error);
    ASSERT_FALSE(r.empty()) << error;
    EXPECT_EQ(r.front().bytes[2], 128);  // 5000/10000 of 255 = 127.5, rounded

    // Set Periodic: ID 4; Magnitude 0..255 (8 bits), Offset -128..127, Phase 0..255 (a
    // turn), Period 16 bits in ms (Unit 0x1003 = seconds, Unit Exponent -3).
    EffectParams sine;
    sine.type = EffectType::sine;
    sine.periodic = {10000, -10000, 250000, 18000};
    sine.duration_us = kInfiniteUs;
    r = effect_reports(l, 7, sine, error);
    ASSERT_FALSE(r.empty()) << error;
    const std::vector<uint8_t>& periodic = r.front().bytes;
    ASSERT_EQ(r.front().report, PidReport::set_periodic);
    EXPECT_EQ(periodic[0], 4);
    EXPECT_EQ(periodic[1], 7);
    EXPECT_EQ(periodic[2], 255);             // magnitude: full scale is the logical maximum
    EXPECT_EQ(periodic[3], 0x80);            // offset -10000: the logical minimum, -128
    EXPECT_EQ(periodic[4], 128);             // phase 180°: half of 0..255, 127.5 rounded
    EXPECT_EQ(periodic[5] | periodic[6] << 8, 250);  // 250 ms
    // Set Effect comes last, after the envelope (Set Envelope, ID 2).
    ASSERT_GE(r.size(), 3u);
    EXPECT_EQ(r[1].report, PidReport::set_envelope);
    EXPECT_EQ(r.back().report, PidReport::set_effect);
    const std::vector<uint8_t>& set_effect = r.back().bytes;
    EXPECT_EQ(set_effect[0], 1);
    EXPECT_EQ(set_effect[1], 7);
    EXPECT_EQ(set_effect[2], 4);  // Effect Type: ET Sine is the 4th usage, Logical Minimum 1
    EXPECT_EQ(set_effect[3] | set_effect[4] << 8, 0xFFFF);  // infinite: the 16-bit null
}

TEST(PidLayoutSidewinderFf2, RefusesWhatItsFieldsCannotHold) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    std::string error;
    EffectParams p = constant(1000);
    p.duration_us = 40'000'000;  // 40000 ms: Duration holds 0..32767 ms
    EXPECT_TRUE(effect_reports(l, 1, p, error).empty());
    EXPECT_NE(error.find("0..32767"), std::string::npos) << error;
    // A wall is feel's; PID has no usage for it.
    EffectParams wall;
    wall.type = EffectType::axis_wall;
    EXPECT_TRUE(effect_reports(l, 1, wall, error).empty());
    EXPECT_NE(error.find("does not play axis_wall"), std::string::npos) << error;
    EXPECT_FALSE(create_new_effect(l, EffectType::axis_wall, error).has_value());
    // Loop Count is 8 bits 0..255: 255 means "until stopped", so 255 plays cannot be asked.
    EXPECT_FALSE(effect_operation(l, 1, Operation::start, 255, error).has_value());
    std::optional<std::vector<uint8_t>> forever = effect_operation(l, 1, Operation::start, kInfiniteIterations, error);
    ASSERT_TRUE(forever.has_value()) << error;
    const std::vector<uint8_t> expected_forever = {10, 1, 1, 255};  // ID 10, block, Op Effect Start (1), 255
    EXPECT_EQ(*forever, expected_forever);
    std::optional<std::vector<uint8_t>> stop = effect_operation(l, 2, Operation::stop, 1, error);
    ASSERT_TRUE(stop.has_value()) << error;
    EXPECT_EQ((*stop)[2], 3);  // Op Effect Stop, the 3rd usage
}

TEST(PidLayoutSidewinderFf2, DirectionIsAFractionOfItsTurn) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    std::string error;
    EffectParams p = constant(4000);
    p.axis_count = 2;
    p.direction = Direction{DirectionKind::polar, {9000, 0, 0}};
    const std::vector<OutgoingReport> r = effect_reports(l, 1, p, error);
    ASSERT_FALSE(r.empty()) << error;
    // Set Effect (ID 1): block 8, Effect Type 8, Duration/Trigger Repeat/Sample Period 3x16,
    // Gain 8, Trigger Button 8, Axes Enable 2 bits, Direction Enable 1 bit, 5 padding,
    // Direction 2x8 (90° of 0..255 is 63.75, rounded), Start Delay 16.
    const std::vector<uint8_t>& b = r.back().bytes;
    ASSERT_EQ(b.size(), 16u);
    EXPECT_EQ(b[9], 255);         // gain 10000: the logical maximum
    EXPECT_EQ(b[11], 0b111);      // X, Y, Direction Enable
    EXPECT_EQ(b[12], 64);
}

TEST(PidLayoutSidewinderFf2, WritesACustomForceInItsSampleFormat) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    std::string error;
    // 7 frames of (x, y): 14 values of its Custom Force Data (8 bits, -127..127, 12 a
    // report), so two reports, the second at offset 12.
    const std::vector<int16_t> samples = {10000, -10000, 5000, 0, 0, 0, 0, 0, 0, 0, 0, 0, -2500, 7500};
    const EffectParams p = test::profile_on_xy(7, 5'000);
    const std::vector<OutgoingReport> r = effect_reports(l, 3, p, error, {samples, false});
    ASSERT_GE(r.size(), 4u) << error;
    ASSERT_EQ(r[0].report, PidReport::custom_force_data);
    // ID 7, block 3, Offset 0 (16 bits), then x0 y0 x1 y1 ...: 10000 -> 127, -10000 -> -127
    // (0x81), 5000 -> 63.5 -> 64.
    const std::vector<uint8_t> first = {7, 3, 0, 0, 127, 0x81, 64, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(r[0].bytes, first);
    ASSERT_EQ(r[1].report, PidReport::custom_force_data);
    // Offset 12: the last frame, -2500 -> -31.75 -> -32 (0xE0), 7500 -> 95.25 -> 95.
    const std::vector<uint8_t> second = {7, 3, 12, 0, 0xE0, 95, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(r[1].bytes, second);
    // Set Custom Force (ID 14): block, Sample Count 7 (frames), Sample Period 5 ms (16 bits).
    ASSERT_EQ(r[2].report, PidReport::set_custom_force);
    const std::vector<uint8_t> set_custom = {14, 3, 7, 5, 0};
    EXPECT_EQ(r[2].bytes, set_custom);
    // Set Effect: ET Custom Force Data is its Effect Type's 12th usage; Sample Period (the
    // third 16-bit time, bytes 7..8) says 5 ms too.
    const std::vector<uint8_t>& effect = r.back().bytes;
    ASSERT_EQ(r.back().report, PidReport::set_effect);
    EXPECT_EQ(effect[2], 12);
    EXPECT_EQ(effect[7] | effect[8] << 8, 5);
    // Create New Effect's Byte Count (10 bits after the 8-bit Effect Type): 14 bytes.
    const std::optional<int64_t> bytes = custom_force_bytes(l, p, {samples, false}, error);
    ASSERT_TRUE(bytes.has_value()) << error;
    EXPECT_EQ(*bytes, 14);
    const std::optional<std::vector<uint8_t>> create = create_new_effect(l, EffectType::force_profile, error, *bytes);
    ASSERT_TRUE(create.has_value()) << error;
    EXPECT_EQ((*create)[1], 12);  // ET Custom Force Data
    EXPECT_EQ((*create)[2] | ((*create)[3] & 0x03) << 8, 14);

    // One channel on x alone: y's slot of each sample is 0.
    EffectParams x_only = p;
    x_only.axis_count = 1;
    x_only.custom = {1, 5'000, 2};
    const std::vector<int16_t> two = {10000, -5000};
    const std::vector<OutgoingReport> rx = effect_reports(l, 2, x_only, error, {two, false});
    ASSERT_FALSE(rx.empty()) << error;
    const std::vector<uint8_t> x_stream = {7, 2, 0, 0, 127, 0, 0xC0, 0, 0, 0, 0, 0, 0, 0, 0, 0};  // -63.5 -> -64
    EXPECT_EQ(rx[0].bytes, x_stream);
    EXPECT_EQ(rx[1].bytes[2], 2);  // 2 samples
}

TEST(PidLayoutSidewinderFf2, RefusesACustomForceItsFieldsCannotHold) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    std::string error;
    // 300 frames: Sample Count holds 0..255.
    std::vector<int16_t> many(600, 100);
    EXPECT_TRUE(effect_reports(l, 1, test::profile_on_xy(300, 1'000), error, {many, false}).empty());
    EXPECT_NE(error.find("custom.sample_count"), std::string::npos) << error;
    EXPECT_NE(error.find("0..255"), std::string::npos) << error;
    // 256 frames of 2 bytes: 512 bytes, and Byte Count holds 0..511.
    std::vector<int16_t> bytes512(512, 100);
    EXPECT_FALSE(custom_force_bytes(l, test::profile_on_xy(256, 1'000), {bytes512, false}, error).has_value());
    EXPECT_NE(error.find("Byte Count holds 0..511"), std::string::npos) << error;
    // Sample Period counts milliseconds: 400 µs is below it.
    const std::vector<int16_t> four(4, 100);
    EXPECT_TRUE(effect_reports(l, 1, test::profile_on_xy(2, 400), error, {four, false}).empty());
    EXPECT_NE(error.find("custom.sample_period_us"), std::string::npos) << error;
    // One channel along a direction on two axes: a sample holds one value per axis.
    EffectParams along = test::profile_on_xy(4, 1'000);
    along.custom = {1, 1'000, 4};
    along.direction = Direction{DirectionKind::polar, {9000, 0, 0}};
    EXPECT_TRUE(effect_reports(l, 1, along, error, {four, false}).empty());
    EXPECT_NE(error.find("custom.channels"), std::string::npos) << error;
    // Offset holds 0..10000 elements: 5002 frames of 2 would reach 10004 (and Sample Count
    // refuses them first), so the offset's range is met only past Sample Count's.
}

TEST(PidLayoutSidewinderFf2, MapsTriggerButtonAndRepeatInterval) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    std::string error;
    EffectParams p = constant(5000);
    p.trigger = {TriggerKind::button, 3};
    p.trigger_repeat_interval_us = 250'000;
    EXPECT_TRUE(device_runs_trigger(l, p.trigger));
    const std::vector<OutgoingReport> r = effect_reports(l, 2, p, error);
    ASSERT_FALSE(r.empty()) << error;
    // Set Effect (ID 1): block, type, Duration, Trigger Repeat Interval, Sample Period (3 x
    // 16 bits, ms), Gain 8, Trigger Button 8 (1..8).
    const std::vector<uint8_t>& b = r.back().bytes;
    EXPECT_EQ(b[5] | b[6] << 8, 250);  // ms
    EXPECT_EQ(b[10], 3);
    // No trigger: Trigger Button 0, its null (out of 1..8).
    const std::vector<OutgoingReport> none = effect_reports(l, 2, constant(5000), error);
    ASSERT_FALSE(none.empty()) << error;
    EXPECT_EQ(none.back().bytes[10], 0);
    // Button 9: past its 1..8.
    p.trigger.index = 9;
    EXPECT_TRUE(effect_reports(l, 2, p, error).empty());
    EXPECT_NE(error.find("trigger.index"), std::string::npos) << error;
    EXPECT_NE(error.find("1..8"), std::string::npos) << error;
    // 40 s of repeat interval: its field holds 0..32767 ms.
    p.trigger.index = 1;
    p.trigger_repeat_interval_us = 40'000'000;
    EXPECT_TRUE(effect_reports(l, 2, p, error).empty());
    EXPECT_NE(error.find("trigger_repeat_interval_us"), std::string::npos) << error;
    EXPECT_NE(error.find("0..32767"), std::string::npos) << error;
    // A hat: PID names buttons only; the host runs it.
    EXPECT_FALSE(device_runs_trigger(l, Trigger{TriggerKind::hat, 1}));
}

// --- Open FFBoard (open-source wheel firmware) ---------------------------------------

TEST(PidLayoutOpenFfboard, MapsItsLayout) {
    const PidLayout l = map_or_fail(load("openffboard_2axis.bin"));
    // Its Effect Type lists no ET Custom Force Data (and it declares no custom force report):
    // a force profile is the host's to render there.
    EXPECT_EQ(l.supported_types(), kPidEleven);
    EXPECT_FALSE(l.report(PidReport::custom_force_data).present);
    EXPECT_TRUE(l.report(PidReport::device_gain).present);
    std::string error;
    // Its Set Constant Force: Magnitude 16 bits, Logical -32767..32767 (usb_hid_ffb_desc.h):
    // -7500/10000 of 32767 is -24575.25.
    std::vector<OutgoingReport> r = effect_reports(l, 2, constant(-7500), error);
    ASSERT_FALSE(r.empty()) << error;
    const std::vector<uint8_t>& b = r.front().bytes;
    ASSERT_EQ(b.size(), 4u);
    EXPECT_EQ(b[0], l.report(PidReport::set_constant_force).id);
    EXPECT_EQ(static_cast<int16_t>(b[2] | b[3] << 8), -24575);
}

// --- feel's own descriptor: feel's codec reads what the generic writer wrote -------------

TEST(PidLayoutFeel, FeelsCodecDecodesTheGenericReports) {
    const std::span<const uint8_t> descriptor = protocol::report_descriptor();
    std::string error;
    const std::optional<PidLayout> l = PidLayout::from_bytes(descriptor, error);
    ASSERT_TRUE(l.has_value()) << error;
    EXPECT_EQ(l->supported_types() & kPidEleven, kPidEleven);
    EffectParams p;
    p.type = EffectType::square;
    p.periodic = {6000, -2000, 40000, 9000};
    p.duration_us = 1'500'000;
    p.start_delay_us = 20'000;
    p.gain = 7000;
    p.axis_count = 2;
    p.direction = Direction{DirectionKind::polar, {27000, 0, 0}};
    const std::vector<OutgoingReport> r = effect_reports(*l, 4, p, error);
    ASSERT_FALSE(r.empty()) << error;
    bool saw_periodic = false, saw_effect = false;
    for (const OutgoingReport& o : r) {
        protocol::AnyReport decoded;
        ASSERT_FALSE(protocol::decode(o.bytes, decoded)) << pid_report_name(o.report);
        if (const auto* s = std::get_if<protocol::SetPeriodicReport>(&decoded)) {
            saw_periodic = true;
            EXPECT_EQ(s->block, 4);
            EXPECT_EQ(s->magnitude, 6000);
            EXPECT_EQ(s->offset, -2000);
            EXPECT_EQ(s->period_us, 40000u);
            EXPECT_EQ(s->phase, 9000);
        }
        if (const auto* s = std::get_if<protocol::SetEffectReport>(&decoded)) {
            saw_effect = true;
            EXPECT_EQ(s->block, 4);
            EXPECT_EQ(s->type, EffectType::square);
            EXPECT_EQ(s->duration_us, 1'500'000u);
            EXPECT_EQ(s->start_delay_us, 20'000u);
            EXPECT_EQ(s->gain, 7000);
            EXPECT_EQ(s->direction_kind, DirectionKind::polar);
            EXPECT_EQ(s->direction[0], 27000);
            EXPECT_EQ(s->axes_enable, 0b11);
        }
    }
    EXPECT_TRUE(saw_periodic);
    EXPECT_TRUE(saw_effect);
}

TEST(PidLayoutFeel, FeelsCodecDecodesAGenericCustomForce) {
    const std::span<const uint8_t> descriptor = protocol::report_descriptor();
    std::string error;
    const std::optional<PidLayout> l = PidLayout::from_bytes(descriptor, error);
    ASSERT_TRUE(l.has_value()) << error;
    ASSERT_TRUE(l->supports(EffectType::force_profile));
    // 30 values on 2 channels: feel's Custom Force Data carries 24 a report.
    std::vector<int16_t> samples;
    for (int i = 0; i < 30; ++i) samples.push_back(static_cast<int16_t>(i % 2 == 0 ? 300 * i : -200 * i));
    const EffectParams p = test::profile_on_xy(15, 2'000);
    const std::vector<OutgoingReport> r = effect_reports(*l, 5, p, error, {samples, true});
    ASSERT_FALSE(r.empty()) << error;
    std::vector<int16_t> received;
    bool saw_set_custom = false;
    for (const OutgoingReport& o : r) {
        protocol::AnyReport decoded;
        ASSERT_FALSE(protocol::decode(o.bytes, decoded)) << pid_report_name(o.report);
        if (const auto* d = std::get_if<protocol::CustomForceDataReport>(&decoded)) {
            EXPECT_EQ(d->block, 5);
            EXPECT_EQ(d->offset, received.size());
            received.insert(received.end(), d->samples, d->samples + d->count);
        }
        if (const auto* c = std::get_if<protocol::SetCustomForceReport>(&decoded)) {
            saw_set_custom = true;
            EXPECT_EQ(c->channels, 2);
            EXPECT_EQ(c->sample_count, 30);
            EXPECT_EQ(c->sample_period_us, 2'000u);
        }
    }
    EXPECT_TRUE(saw_set_custom);
    EXPECT_EQ(received, samples);
}

TEST(PidLayout, RefusesADeviceWithoutPid) {
    // A plain joystick: Generic Desktop X, Y, 8 bits each (HID 1.11 appendix E style).
    const std::vector<uint8_t> joystick = {0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, 0x09, 0x30, 0x09, 0x31, 0x15, 0x81,
                                           0x25, 0x7F, 0x75, 0x08, 0x95, 0x02, 0x81, 0x02, 0xC0};
    std::string error;
    EXPECT_FALSE(PidLayout::from_bytes(joystick, error).has_value());
    EXPECT_NE(error.find("no usage of the PID page"), std::string::npos) << error;
    EXPECT_FALSE(PidLayout::from_bytes(std::vector<uint8_t>{0x05}, error).has_value());
    EXPECT_NE(error.find("does not parse"), std::string::npos) << error;
}

}  // namespace
