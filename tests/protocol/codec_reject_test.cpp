// decode() refuses what is not a well-formed report: unknown ids, wrong lengths (every
// truncation of every report), each field one past its logical range (the range read from
// the descriptor by the independent parser, so the decoder enforces exactly what the
// descriptor declares), and enum values that name nothing. encode() refuses the same
// values with std::invalid_argument.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "feel/units.hpp"
#include "sample_reports.hpp"

namespace feel::protocol {
namespace {

Error decode_bytes(const std::vector<uint8_t>& bytes) {
    AnyReport out;
    return decode(bytes, out);
}

// Writes `bits` bits of `value` at bit `offset` (LSB first), independently of the codec.
void poke(std::vector<uint8_t>& bytes, std::size_t offset, uint32_t bits, uint64_t value) {
    for (uint32_t k = 0; k < bits; ++k) {
        const std::size_t at = offset + k;
        const auto mask = static_cast<uint8_t>(1u << (at % 8));
        if ((value >> k) & 1u) {
            bytes[at / 8] = static_cast<uint8_t>(bytes[at / 8] | mask);
        } else {
            bytes[at / 8] = static_cast<uint8_t>(bytes[at / 8] & ~mask);
        }
    }
}

bool fits(int64_t v, uint32_t bits, bool is_signed) {
    if (bits >= 64) return true;
    if (is_signed) return v >= -(int64_t{1} << (bits - 1)) && v < (int64_t{1} << (bits - 1));
    return v >= 0 && v < (int64_t{1} << bits);
}

TEST(DecodeRejects, EmptyInput) {
    const Error e = decode_bytes({});
    EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(e.field, "report.length");
}

TEST(DecodeRejects, EveryUnknownId) {
    int known = 0;
    for (int id = 0; id < 256; ++id) {
        if (report_size(static_cast<uint8_t>(id)) != 0) {
            ++known;
            continue;
        }
        // Whatever the length: the id is checked first.
        for (std::size_t len : {std::size_t{1}, std::size_t{7}, max_report_size()}) {
            std::vector<uint8_t> bytes(len, 0);
            bytes[0] = static_cast<uint8_t>(id);
            const Error e = decode_bytes(bytes);
            EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
            EXPECT_STREQ(e.field, "report.id") << id;
            EXPECT_EQ(e.value, id);
        }
    }
    EXPECT_EQ(known, static_cast<int>(std::variant_size_v<AnyReport>));
}

TEST(DecodeRejects, EveryTruncationAndExtensionOfEveryReport) {
    for (const AnyReport& report : test::sample_reports()) {
        const std::vector<uint8_t> bytes = encode(report);
        SCOPED_TRACE(std::string(report_name(report_id_of(report))));
        for (std::size_t len = 1; len < bytes.size(); ++len) {
            const Error e = decode_bytes(std::vector<uint8_t>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(len)));
            ASSERT_EQ(e.code, ErrorCode::invalid_parameter) << len;
            EXPECT_STREQ(e.field, "report.length");
            EXPECT_TRUE(e.has_range);
            EXPECT_EQ(e.value, static_cast<int64_t>(len));
            EXPECT_EQ(e.allowed.min, static_cast<int64_t>(bytes.size()));
            EXPECT_EQ(e.allowed.max, static_cast<int64_t>(bytes.size()));
        }
        std::vector<uint8_t> longer = bytes;
        longer.push_back(0);
        EXPECT_STREQ(decode_bytes(longer).field, "report.length");
    }
}

// For every field element of every report: one past each end of the logical range the
// descriptor declares is refused, with the value and that range; the ends themselves pass.
TEST(DecodeRejects, EveryFieldOnePastTheDescriptorsRange) {
    const hid::DescriptorParse parse = hid::parse_report_descriptor(report_descriptor());
    ASSERT_TRUE(parse.ok()) << parse.error;
    int refused = 0;
    for (const AnyReport& report : test::sample_reports()) {
        const std::vector<uint8_t> valid = encode(report);
        const auto id = static_cast<uint8_t>(report_id_of(report));
        const hid::DescriptorReport* layout = nullptr;
        for (const hid::DescriptorReport& r : parse.descriptor.reports) {
            if (r.id == id) layout = &r;
        }
        ASSERT_NE(layout, nullptr);
        for (const hid::DescriptorField& f : layout->fields) {
            if (f.is_constant()) continue;  // padding: no value (written 0, refused otherwise)
            const bool is_signed = f.logical_min < 0;
            for (uint32_t i = 0; i < f.report_count; ++i) {
                const std::size_t offset = 8 + f.bit_offset + i * f.report_size;
                SCOPED_TRACE("report " + std::to_string(id) + " bit " + std::to_string(offset));
                for (int64_t v : {f.logical_min, f.logical_max}) {
                    std::vector<uint8_t> bytes = valid;
                    poke(bytes, offset, f.report_size, static_cast<uint64_t>(v));
                    const Error e = decode_bytes(bytes);
                    // In range is never a range error; a rule between fields may still
                    // refuse it (a direction slot its form does not use must be 0, a
                    // feel hat is north or centred).
                    EXPECT_TRUE(e.ok() || (!e.has_range && e.rule[0] != '\0')) << v << ": " << e.message();
                }
                for (int64_t v : {f.logical_min - 1, f.logical_max + 1}) {
                    if (!fits(v, f.report_size, is_signed)) continue;
                    std::vector<uint8_t> bytes = valid;
                    poke(bytes, offset, f.report_size, static_cast<uint64_t>(v));
                    const Error e = decode_bytes(bytes);
                    const bool all_ones = !is_signed && v == (int64_t{1} << f.report_size) - 1;
                    // feel's null values: all ones (infinite) or 0 (Block Load's "no block").
                    if (f.has_null_state() && (all_ones || v == 0)) {
                        EXPECT_TRUE(e.ok()) << "the null value (infinite, or no block) is accepted";
                        continue;
                    }
                    ++refused;
                    ASSERT_EQ(e.code, ErrorCode::invalid_parameter) << v;
                    EXPECT_TRUE(e.has_range);
                    EXPECT_EQ(e.value, v);
                    EXPECT_EQ(e.allowed.min, f.logical_min);
                    EXPECT_EQ(e.allowed.max, f.logical_max);
                    EXPECT_NE(std::strchr(e.field, '.'), nullptr) << e.field;
                }
            }
        }
    }
    EXPECT_GT(refused, 300);
}

SetEffectReport valid_effect() { return std::get<SetEffectReport>(test::sample_reports()[0]); }

template <class Report>
Error decode_with(Report report, std::size_t byte, uint8_t value) {
    std::vector<uint8_t> bytes = encode(report);
    bytes.at(byte) = value;
    return decode_bytes(bytes);
}

TEST(DecodeRejects, GainOnePastFullScaleNamesTheFieldAndRange) {
    std::vector<uint8_t> bytes = encode(valid_effect());
    // id(1) sequence(4) block(2) type(1), three times as milliseconds(2) and the
    // microseconds below them(2): gain at byte 20.
    bytes[20] = 10001 & 0xFF;
    bytes[21] = 10001 >> 8;
    const Error e = decode_bytes(bytes);
    EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(e.field, "set_effect.gain");
    EXPECT_EQ(e.value, 10001);
    EXPECT_EQ(e.allowed.min, range::kGain.min);
    EXPECT_EQ(e.allowed.max, range::kGain.max);
    EXPECT_EQ(e.message(), "set_effect.gain = 10001 is out of range (allowed 0..10000)");
}

TEST(DecodeRejects, ArrayElementsAreNamedWithTheirIndex) {
    CustomForceDataReport data;
    data.count = 4;
    std::vector<uint8_t> bytes = encode(data);
    // id(1) sequence(4) block(2) offset(2) count(1): samples[3] at byte 10 + 6.
    bytes[16] = static_cast<uint8_t>(static_cast<uint16_t>(-10001) & 0xFF);
    bytes[17] = static_cast<uint8_t>(static_cast<uint16_t>(-10001) >> 8);
    const Error e = decode_bytes(bytes);
    EXPECT_STREQ(e.field, "custom_force_data.samples[3]");
    EXPECT_EQ(e.value, -10001);
    EXPECT_EQ(e.allowed.min, range::kSample.min);
}

TEST(DecodeRejects, InvalidEnumValues) {
    // Effect Type is a 1-based list of 33: 0 and 34 name no type (set_effect.type at byte 7,
    // create_new_effect.type at byte 5).
    Error e = decode_with(valid_effect(), 7, kEffectTypeCount + 1);
    EXPECT_STREQ(e.field, "set_effect.type");
    EXPECT_EQ(e.allowed.min, 1);
    EXPECT_EQ(e.allowed.max, kEffectTypeCount);
    EXPECT_STREQ(decode_with(valid_effect(), 7, 0).field, "set_effect.type");
    e = decode_with(CreateNewEffectReport{}, 5, 0xFF);
    EXPECT_STREQ(e.field, "create_new_effect.type");
    // Effect Operation 0 and 4 (byte 7), Device Control 0 and 7 (byte 1: its list comes first).
    EXPECT_STREQ(decode_with(EffectOperationReport{}, 7, 0).field, "effect_operation.operation");
    EXPECT_STREQ(decode_with(EffectOperationReport{}, 7, 4).field, "effect_operation.operation");
    EXPECT_STREQ(decode_with(DeviceControlReport{}, 1, 0).field, "device_control.control");
    EXPECT_STREQ(decode_with(DeviceControlReport{}, 1, 7).field, "device_control.control");
    // Block Load status 0 and 4 (byte 3).
    EXPECT_STREQ(decode_with(BlockLoadReport{}, 3, 0).field, "block_load.status");
    EXPECT_STREQ(decode_with(BlockLoadReport{}, 3, 4).field, "block_load.status");
    // id(1) seq(4) block(2) type(1) 3 x time(12) gain(2) trigger_button(2) trigger_kind(24)
    // axes_enable(25, six bits and padding) direction_enable(26) direction_form(27) angles(4)
    // vector(6) iterations(2) axis_count(40) axes[0..5](41..46).
    EXPECT_STREQ(decode_with(valid_effect(), 27, 4).field, "set_effect.direction_form");
    EXPECT_STREQ(decode_with(valid_effect(), 24, 3).field, "set_effect.trigger_kind");
    EXPECT_STREQ(decode_with(valid_effect(), 42, 6).field, "set_effect.axes[1]");
    // A bool that is neither 0 nor 1.
    EXPECT_STREQ(decode_with(ReflexReport{}, 7, 2).field, "reflex.assign");
    // Command Status naming a report id that does not exist: inside 0x01..0x46 but a hole.
    CommandStatusReport status;
    e = decode_with(status, 5, 0x0E);
    EXPECT_STREQ(e.field, "command_status.command");
    EXPECT_FALSE(e.has_range);
    EXPECT_EQ(e.value, 0x0E);
    EXPECT_STREQ(e.rule, "is not a report id (nor 0, no report)");
}

TEST(DecodeAccepts, CommandStatusForAFrameThatNamedNoReport) {
    // command 0 (kNoReportId): the answer to a frame whose id byte names no report.
    CommandStatusReport status;
    status.command = kNoReportId;
    status.code = ErrorCode::invalid_parameter;
    status.value = 0xEE;
    AnyReport back;
    ASSERT_TRUE(decode(encode(status), back).ok());
    EXPECT_EQ(std::get<CommandStatusReport>(back), status);
}

TEST(DecodeRejects, FieldsThatContradictAnEarlierField) {
    // Decode loses nothing, so a value that an earlier field makes meaningless is refused
    // with a rule rather than dropped. Set Effect: byte 26 Direction Enable, 27 form,
    // 28..31 the Ordinal angles, 32..37 the vector; 8..9 Duration ms, 10..11 its µs.
    SetEffectReport polar = valid_effect();
    polar.direction_kind = DirectionKind::polar;
    polar.direction[0] = 9000;
    polar.direction[1] = polar.direction[2] = 0;
    Error e = decode_with(polar, 32, 1);  // a vector component on a polar direction
    EXPECT_STREQ(e.field, "set_effect.direction_vector[0]");
    EXPECT_FALSE(e.has_range);
    EXPECT_STREQ(e.rule, "must be 0: only cartesian and moment directions have a vector");
    EXPECT_STREQ(decode_with(polar, 30, 1).field, "set_effect.direction_angle[1]");  // polar has one angle
    SetEffectReport none = polar;
    none.direction_kind = DirectionKind::none;
    none.direction[0] = 0;
    EXPECT_STREQ(decode_with(none, 27, 2).field, "set_effect.direction_form");
    SetEffectReport endless = polar;
    endless.duration_us = kWireInfinite;
    EXPECT_STREQ(decode_with(endless, 10, 5).field, "set_effect.duration_fine_us");
    // A feel hat is north (0) or centred (15): hat 1 is byte 17's low nibble.
    JoystickInputReport joy;
    std::vector<uint8_t> bytes = encode(joy);
    bytes[17] = static_cast<uint8_t>((bytes[17] & 0xF0) | 3);
    e = decode_bytes(bytes);
    EXPECT_STREQ(e.field, "joystick_input.hats[0]");
    EXPECT_FALSE(e.has_range);
}

TEST(EncodeRejects, OutOfRangeValuesThrowNamingFieldAndRange) {
    SetEffectReport effect = valid_effect();
    effect.gain = 10001;
    try {
        (void)encode(effect);
        FAIL() << "encode accepted gain 10001";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("set_effect.gain = 10001 is out of range (allowed 0..10000)"),
                  std::string::npos)
            << e.what();
    }
    effect = valid_effect();
    effect.duration_us = 65'000'001;
    EXPECT_THROW((void)encode(effect), std::invalid_argument);
    effect.duration_us = kWireInfinite;
    EXPECT_NO_THROW((void)encode(effect));
    effect.start_delay_us = 65'000'001;  // every time, not only the duration
    EXPECT_THROW((void)encode(effect), std::invalid_argument);
    effect.start_delay_us = 0;
    effect.type = static_cast<EffectType>(kEffectTypeCount);
    EXPECT_THROW((void)encode(effect), std::invalid_argument);

    SetTextureReport texture;  // int32_t members wider than the wire: still range checked
    texture.texture.spacing = 70000;
    EXPECT_THROW((void)encode(texture), std::invalid_argument);
    texture.texture.spacing = 0;
    EXPECT_THROW((void)encode(texture), std::invalid_argument);

    CommandStatusReport status;
    status.command = static_cast<ReportId>(0x0E);
    EXPECT_THROW((void)encode(status), std::invalid_argument);

    DeviceInfoReport info;  // axis_count 0 is outside 1..6
    EXPECT_THROW((void)encode(info), std::invalid_argument);
}

}  // namespace
}  // namespace feel::protocol
