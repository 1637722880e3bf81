// encode() then decode() gives back every report, field for field; sizes and byte layout
// against hand-computed bytes (little-endian, packed, id first).
#include <gtest/gtest.h>

#include <set>

#include "feel/protocol/codec.hpp"
#include "sample_reports.hpp"

namespace feel::protocol {
namespace {

TEST(CodecRoundTrip, EveryReportComesBackUnchanged) {
    std::set<std::size_t> alternatives;
    for (const AnyReport& report : test::sample_reports()) {
        alternatives.insert(report.index());
        const std::vector<uint8_t> bytes = encode(report);
        const auto id = static_cast<uint8_t>(report_id_of(report));
        SCOPED_TRACE(std::string(report_name(report_id_of(report))));
        EXPECT_EQ(bytes.size(), report_size(id));
        EXPECT_EQ(bytes[0], id);
        AnyReport back;
        const Error e = decode(bytes, back);
        ASSERT_TRUE(e.ok()) << e.message();
        EXPECT_EQ(back.index(), report.index());
        EXPECT_TRUE(back == report);
        EXPECT_EQ(encode(back), bytes);
    }
    EXPECT_EQ(alternatives.size(), std::variant_size_v<AnyReport>) << "a report kind has no sample";
}

TEST(CodecRoundTrip, DefaultReportsThatAreValidRoundTrip) {
    // Defaults documented inside their ranges encode as they are.
    for (const AnyReport& report :
         {AnyReport{SetEffectReport{}}, AnyReport{SetConditionReport{}}, AnyReport{KeepAliveReport{}},
          AnyReport{EffectOperationReport{}}, AnyReport{DeviceGainReport{}}, AnyReport{PidStateReport{}},
          AnyReport{CommandStatusReport{}}, AnyReport{DeviceStatusReport{}}}) {
        AnyReport back;
        const Error e = decode(encode(report), back);
        ASSERT_TRUE(e.ok()) << e.message();
        EXPECT_TRUE(back == report);
    }
}

TEST(CodecLayout, DeviceGainIsIdThenLittleEndianFields) {
    // Device Gain: id 0x0D, sequence u32 LE, gain u16 LE (10000 = 0x2710).
    const std::vector<uint8_t> expected = {0x0D, 0x04, 0x03, 0x02, 0x01, 0x10, 0x27};
    EXPECT_EQ(encode(DeviceGainReport{0x01020304u, 10000}), expected);
}

TEST(CodecLayout, SetConstantForceNegativeMagnitudeIsTwosComplement) {
    // -10000 = 0xD8F0 as int16.
    const std::vector<uint8_t> expected = {0x05, 0x09, 0x00, 0x00, 0x00, 0x02, 0x01, 0xF0, 0xD8};
    EXPECT_EQ(encode(SetConstantForceReport{9, 0x0102, -10000}), expected);
}

TEST(CodecLayout, JoystickButtonsArePackedBitsAfterTheAxes) {
    JoystickInputReport joy;
    joy.position[0] = -1;  // 0xFFFF
    joy.buttons = 0x00000101u;  // buttons 1 and 9
    joy.hats = 0x05;  // hats 1 and 3 pushed
    const std::vector<uint8_t> bytes = encode(joy);
    // id, 6 x int16, 32 one-bit buttons (4 bytes), four 4-bit Hat Switches (HID: 0..7 a
    // direction, anything else, here 15, centred); a pushed hat says north (0).
    ASSERT_EQ(bytes.size(), 1u + 12u + 4u + 2u);
    EXPECT_EQ(bytes[1], 0xFF);
    EXPECT_EQ(bytes[2], 0xFF);
    EXPECT_EQ(bytes[13], 0x01);
    EXPECT_EQ(bytes[14], 0x01);
    EXPECT_EQ(bytes[15], 0x00);
    EXPECT_EQ(bytes[16], 0x00);
    EXPECT_EQ(bytes[17], 0xF0);  // hat 1 north (low nibble), hat 2 centred
    EXPECT_EQ(bytes[18], 0xF0);  // hat 3 north, hat 4 centred
}

TEST(CodecLayout, AProfilesJoystickCarriesOnlyItsInputs) {
    JoystickLayout two_axes;  // x and y, 10 buttons, one hat
    two_axes.axis_count = 2;
    two_axes.button_count = 10;
    two_axes.hat_count = 1;
    JoystickInputReport joy;
    joy.position[0] = 10000;
    joy.position[1] = -10000;
    joy.buttons = 0x201u;  // buttons 1 and 10
    joy.hats = 0x01;
    const std::vector<uint8_t> bytes = encode(joy, two_axes);
    // id, 2 x int16, 10 bits of buttons + 6 bits of padding, a hat nibble + 4 bits padding.
    ASSERT_EQ(bytes.size(), 1u + 4u + 2u + 1u);
    EXPECT_EQ(joystick_input_size(two_axes), bytes.size());
    EXPECT_EQ(bytes[1], 0x10);  // 10000 = 0x2710
    EXPECT_EQ(bytes[2], 0x27);
    EXPECT_EQ(bytes[3], 0xF0);  // -10000 = 0xD8F0
    EXPECT_EQ(bytes[4], 0xD8);
    EXPECT_EQ(bytes[5], 0x01);
    EXPECT_EQ(bytes[6], 0x02);
    EXPECT_EQ(bytes[7] & 0x0F, 0x00);  // hat 1 pushed: north
    JoystickInputReport back;
    ASSERT_TRUE(decode(bytes, two_axes, back).ok());
    EXPECT_EQ(back, joy);
    // A button beyond the layout does not travel.
    joy.buttons |= 1u << 20;
    EXPECT_EQ(encode(joy, two_axes), bytes);
    // The full layout's decoder refuses the profile's shorter report.
    AnyReport any;
    EXPECT_STREQ(decode(bytes, any).field, "report.length");
    // Bad layouts are refused by name.
    JoystickLayout twice = two_axes;
    twice.axes[1] = Axis::x;
    EXPECT_STREQ(check_layout(twice).field, "joystick_layout.axes");
    EXPECT_THROW((void)report_descriptor(twice), std::invalid_argument);
}

TEST(CodecLayout, InfiniteDurationIsPidsNull) {
    SetEffectReport effect;  // duration_us defaults to kWireInfinite
    const std::vector<uint8_t> bytes = encode(effect);
    // id(1) sequence(4) block(2) type(1), then PID's Duration in milliseconds (u16, the
    // null 0xFFFF for infinite) and the microseconds below them (0).
    EXPECT_EQ(bytes[8], 0xFF);
    EXPECT_EQ(bytes[9], 0xFF);
    EXPECT_EQ(bytes[10], 0x00);
    EXPECT_EQ(bytes[11], 0x00);
}

TEST(CodecInfo, KindsNamesAndSizes) {
    EXPECT_EQ(report_kind(0x01), ReportKind::output);
    EXPECT_EQ(report_kind(0x20), ReportKind::output);
    EXPECT_EQ(report_kind(0x11), ReportKind::feature);
    EXPECT_EQ(report_kind(0x30), ReportKind::feature);
    EXPECT_EQ(report_kind(0x42), ReportKind::input);
    EXPECT_EQ(report_kind(0x00), std::nullopt);
    EXPECT_EQ(report_kind(0xFF), std::nullopt);
    EXPECT_EQ(report_name(ReportId::set_effect), "Set Effect");
    EXPECT_EQ(report_name(ReportId::block_load), "PID Block Load");
    EXPECT_EQ(report_name(static_cast<ReportId>(0x7F)), "");
    EXPECT_EQ(report_size(0x00), 0u);
    // Sizes summed by hand from reports.hpp's field widths.
    EXPECT_EQ(report_size(0x0D), 1u + 4 + 2);            // Device Gain
    EXPECT_EQ(report_size(0x0B), 1u + 4 + 2);            // Block Free
    EXPECT_EQ(report_size(0x05), 1u + 4 + 2 + 2);        // Set Constant Force
    EXPECT_EQ(report_size(0x08), 1u + 4 + 2 + 2 + 1 + 48);  // Custom Force Data: 24 samples
    EXPECT_EQ(report_size(0x0A), 1u + 4 + 2 + 1 + 2);    // Effect Operation: 16-bit Loop Count
    EXPECT_EQ(report_size(0x0C), 1u + 1 + 4);            // Device Control: the list, then the sequence
    EXPECT_EQ(report_size(0x12), 1u + 2 + 1 + 4);        // Block Load
    std::size_t largest = 0;
    for (int id = 0; id < 256; ++id) largest = std::max(largest, report_size(static_cast<uint8_t>(id)));
    EXPECT_EQ(max_report_size(), largest);
}

}  // namespace
}  // namespace feel::protocol
