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

TEST(PidLayoutSidewinderFf2, EnumeratesItsTwelveTypesAndPlaysTheElevenItHasBlocksFor) {
    const PidLayout l = map_or_fail(load("sidewinder_ff2.bin"));
    ASSERT_EQ(l.effect_types().size(), 12u);  // ET Constant .. ET Friction, ET Custom Force Data
    EXPECT_EQ(l.supported_types(), kPidEleven);
    const EffectTypeEntry& custom = l.effect_types().back();
    EXPECT_EQ(custom.usage, 0x000F0028u);
    EXPECT_FALSE(custom.usable);
    EXPECT_NE(custom.why_not.find("Custom Force Data"), std::string::npos);
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
    EXPECT_FALSE(create_new_effect(l, EffectType::force_profile, error).has_value());
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

// --- Open FFBoard (open-source wheel firmware) ---------------------------------------

TEST(PidLayoutOpenFfboard, MapsItsLayout) {
    const PidLayout l = map_or_fail(load("openffboard_2axis.bin"));
    EXPECT_EQ(l.supported_types(), kPidEleven);
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
