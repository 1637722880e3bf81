// feel's device as a plain PID device (feel/protocol/standard_pid.hpp): its descriptor and
// the translation of its reports.
//
// The truths: the descriptor read back by the independent HID parser has no usage, field
// or collection off the standard pages (PID 0x0F, Generic Desktop, Button, Ordinal); the
// hid-pidff model (pidff_acceptance.hpp, written from hid-pidff.c) accepts it with PID's
// eleven types; the generic PID mapping (pid_layout.hpp, which knows nothing of feel's
// layout) finds every report a host needs in it; what that generic writer writes from the
// descriptor alone, translated, is what feel's codec (an independent table-driven decoder)
// reads with the values asked for; and feel's replies, translated, read back through the
// generic reader with the values the device put in.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "feel/protocol/pid_effect_reports.hpp"
#include "feel/protocol/pid_layout.hpp"
#include "feel/protocol/standard_pid.hpp"
#include "pidff_acceptance.hpp"
#include "standard_pid_table.hpp"

namespace feel::protocol {
namespace {

using namespace feel::protocol::pid;

// A two-axis joystick with 4 buttons and a hat, as iforce2 presents itself.
JoystickLayout stick() {
    JoystickLayout l;
    l.axis_count = 2;
    l.button_count = 4;
    l.hat_count = 1;
    return l;
}

bool standard_page(uint32_t usage) {
    const uint32_t page = usage >> 16;
    return page == 0x01 || page == 0x09 || page == 0x0A || page == 0x0F;
}

TEST(StandardPidDescriptor, HasOnlyStandardUsages) {
    const std::vector<uint8_t> bytes = standard_pid_descriptor(stick());
    const hid::DescriptorParse parse = hid::parse_report_descriptor(bytes);
    ASSERT_TRUE(parse.ok()) << parse.error;
    int fields = 0;
    for (const hid::DescriptorReport& r : parse.descriptor.reports) {
        for (const hid::DescriptorField& f : r.fields) {
            ++fields;
            for (uint32_t u : f.usages) EXPECT_TRUE(standard_page(u)) << "report " << int(r.id) << " usage " << std::hex << u;
            for (uint32_t c : f.collections) EXPECT_TRUE(standard_page(c)) << "report " << int(r.id) << " collection " << std::hex << c;
        }
    }
    EXPECT_GT(fields, 30);
    // feel's own descriptor has vendor usages: the test can tell the two apart.
    const hid::DescriptorParse feels = hid::parse_report_descriptor(report_descriptor(stick()));
    bool vendor = false;
    for (const hid::DescriptorReport& r : feels.descriptor.reports)
        for (const hid::DescriptorField& f : r.fields)
            for (uint32_t u : f.usages) vendor = vendor || !standard_page(u);
    EXPECT_TRUE(vendor);
}

TEST(StandardPidDescriptor, HidPidffWouldInitialiseIt) {
    const std::vector<uint8_t> bytes = standard_pid_descriptor(stick());
    const hid::DescriptorParse parse = hid::parse_report_descriptor(bytes);
    ASSERT_TRUE(parse.ok()) << parse.error;
    const test::PidffVerdict v = test::pidff_check(parse.descriptor);
    std::string problems;
    for (const std::string& p : v.problems) problems += p + "\n";
    EXPECT_TRUE(v.accepted()) << problems;
    EXPECT_TRUE(v.gain);
    EXPECT_EQ(v.ff_effects.size(), 11u);
    EXPECT_EQ(v.first_block, 1);
}

TEST(StandardPidDescriptor, TheGenericMappingFindsEveryReport) {
    std::string error;
    const std::optional<PidLayout> l = PidLayout::from_bytes(standard_pid_descriptor(stick()), error);
    ASSERT_TRUE(l.has_value()) << error;
    for (PidReport r : {PidReport::set_effect, PidReport::set_envelope, PidReport::set_condition, PidReport::set_periodic,
                        PidReport::set_constant_force, PidReport::set_ramp_force, PidReport::effect_operation,
                        PidReport::block_free, PidReport::device_control, PidReport::device_gain,
                        PidReport::create_new_effect, PidReport::block_load, PidReport::pool, PidReport::state}) {
        EXPECT_TRUE(l->report(r).present) << pid_report_name(r);
    }
    // PID's eleven, each usable; Custom Force listed last, not played (its feel form needs
    // vendor fields).
    int usable = 0;
    for (const EffectTypeEntry& e : l->effect_types()) usable += e.usable ? 1 : 0;
    EXPECT_EQ(usable, 11);
    ASSERT_EQ(l->effect_types().size(), 12u);
    EXPECT_EQ(l->effect_types().back().usage, 0x000F0028u);  // ET Custom Force Data
    EXPECT_EQ(l->supported_types(), standard_pid_effect_type_bits());
    EXPECT_FALSE(l->supports(EffectType::force_profile));
    EXPECT_FALSE(l->supports(EffectType::axis_wall));
    // The joystick's positions: X and Y, as the layout has them.
    EXPECT_EQ(l->input_axes(), (std::vector<Axis>{Axis::x, Axis::y}));
    // Every report's size as the descriptor declares it is what the translation takes.
    for (PidReport r : {PidReport::set_effect, PidReport::set_condition, PidReport::effect_operation,
                        PidReport::device_control, PidReport::create_new_effect}) {
        const ReportLayout& rl = l->report(r);
        std::vector<uint8_t> zeros(rl.bytes, 0), feel;
        zeros[0] = rl.id;
        const Error e = standard_pid_to_feel(zeros, feel);
        // An all-zero report is the right length; Effect Type 0 (no type) and Device
        // Control 0 are refused by value, never by length.
        if (e) {
            EXPECT_STRNE(e.field, "report.length") << pid_report_name(r) << ": " << e.message();
        }
    }
}

TEST(StandardPidTable, EveryReportIsWholeBytesAndKeepsFeelsIdAndPidFields) {
    ASSERT_EQ(detail::standard_reports().size(), 14u);
    for (const detail::StandardReport& r : detail::standard_reports()) {
        std::size_t bits = 0;
        for (const detail::StandardField& f : r.fields) {
            bits += f.spec.total_bits();
            EXPECT_FALSE(detail::is_vendor_field(f.spec)) << r.feel->name;
        }
        EXPECT_EQ(bits % 8, 0u) << r.feel->name;
        EXPECT_EQ(r.bytes, 1 + bits / 8) << r.feel->name;
        EXPECT_LE(r.bytes, r.feel->size()) << r.feel->name;
    }
}

TEST(StandardPidTranslation, FeelsCodecReadsWhatTheGenericWriterWrote) {
    std::string error;
    const std::optional<PidLayout> l = PidLayout::from_bytes(standard_pid_descriptor(stick()), error);
    ASSERT_TRUE(l.has_value()) << error;
    EffectParams p;
    p.type = EffectType::triangle;
    p.periodic = {6000, -2000, 40000, 9000};
    p.duration_us = 1'500'000;
    p.start_delay_us = 20'000;
    p.gain = 7000;
    p.axis_count = 2;
    p.direction = Direction{DirectionKind::polar, {27000, 0, 0}};
    p.has_envelope = true;
    p.envelope = Envelope{3000, 100'000, 2000, 200'000};
    const std::vector<OutgoingReport> reports = effect_reports(*l, 5, p, error);
    ASSERT_FALSE(reports.empty()) << error;
    bool periodic = false, effect = false, envelope = false;
    for (const OutgoingReport& o : reports) {
        std::vector<uint8_t> feel;
        ASSERT_FALSE(standard_pid_to_feel(o.bytes, feel)) << pid_report_name(o.report);
        AnyReport decoded;
        const Error e = decode(feel, decoded);
        ASSERT_FALSE(e) << pid_report_name(o.report) << ": " << e.message();
        if (const auto* s = std::get_if<SetPeriodicReport>(&decoded)) {
            periodic = true;
            EXPECT_EQ(s->block, 5);
            EXPECT_EQ(s->magnitude, 6000);
            EXPECT_EQ(s->offset, -2000);
            EXPECT_EQ(s->period_us, 40000u);
            EXPECT_EQ(s->phase, 9000);
            EXPECT_EQ(s->sequence, 0u);
        }
        if (const auto* s = std::get_if<SetEnvelopeReport>(&decoded)) {
            envelope = true;
            EXPECT_EQ(s->impulse_level, 3000);
            EXPECT_EQ(s->settle_time_us, 100'000u);
            EXPECT_EQ(s->fade_level, 2000);
            EXPECT_EQ(s->fade_time_us, 200'000u);
        }
        if (const auto* s = std::get_if<SetEffectReport>(&decoded)) {
            effect = true;
            EXPECT_EQ(s->block, 5);
            EXPECT_EQ(s->type, EffectType::triangle);
            EXPECT_EQ(s->duration_us, 1'500'000u);
            EXPECT_EQ(s->start_delay_us, 20'000u);
            EXPECT_EQ(s->gain, 7000);
            EXPECT_EQ(s->direction_kind, DirectionKind::polar);
            EXPECT_EQ(s->direction[0], 27000);
            EXPECT_EQ(s->axes_enable, 0b11);
            // feel's vendor fields as a standard host leaves them: "not given".
            EXPECT_EQ(s->axis_count, 0);
            EXPECT_EQ(s->iterations, 0);
        }
    }
    EXPECT_TRUE(periodic && effect && envelope);
    // Create New Effect names the type by PID's list: every one of the eleven arrives as itself.
    for (const EffectType t : standard_pid_effect_types()) {
        const std::optional<std::vector<uint8_t>> create = create_new_effect(*l, t, error);
        ASSERT_TRUE(create.has_value()) << error;
        std::vector<uint8_t> feel;
        ASSERT_FALSE(standard_pid_to_feel(*create, feel));
        AnyReport decoded;
        ASSERT_FALSE(decode(feel, decoded));
        EXPECT_EQ(std::get<CreateNewEffectReport>(decoded).type, t) << effect_type_name(t);
    }
}

TEST(StandardPidTranslation, TheHostReadsTheDevicesRepliesThroughTheGenericReader) {
    std::string error;
    const std::optional<PidLayout> l = PidLayout::from_bytes(standard_pid_descriptor(stick()), error);
    ASSERT_TRUE(l.has_value()) << error;
    PidPoolReport pool;
    pool.ram_pool_size = 16384;
    pool.simultaneous_effects_max = 32;
    pool.device_managed_pool = true;
    pool.free_effects = 30;  // vendor: not in the standard report
    std::vector<uint8_t> out;
    ASSERT_TRUE(feel_to_standard_pid(encode(AnyReport{pool}), out));
    EXPECT_EQ(out.size(), l->report(PidReport::pool).bytes);
    const Pool read = read_pool(*l, out);
    EXPECT_EQ(read.ram_pool_size, 16384);
    EXPECT_EQ(read.simultaneous_effects_max, 32);
    EXPECT_EQ(read.device_managed_pool, true);

    BlockLoadReport load;
    load.block = 7;
    load.status = BlockLoadStatus::success;
    load.ram_pool_available = 1000;
    ASSERT_TRUE(feel_to_standard_pid(encode(AnyReport{load}), out));
    const std::optional<BlockLoad> bl = read_block_load(*l, out);
    ASSERT_TRUE(bl.has_value());
    EXPECT_EQ(bl->block, 7);
    EXPECT_EQ(bl->status, BlockLoad::Status::success);

    JoystickInputReport joy;
    joy.position[0] = -1234;
    joy.position[1] = 4321;
    joy.buttons = 0b0101;
    ASSERT_TRUE(feel_to_standard_pid(encode(joy, stick()), out));
    JoystickReading reading;
    ASSERT_TRUE(read_joystick(*l, out, reading));
    EXPECT_NEAR(reading.position[0], -1234.0f, 1.0f);
    EXPECT_NEAR(reading.position[1], 4321.0f, 1.0f);
    EXPECT_EQ(reading.buttons, 0b0101u);

    // Vendor reports have no standard form: the device keeps them.
    CommandStatusReport status;
    EXPECT_FALSE(feel_to_standard_pid(encode(AnyReport{status}), out));
    DeviceStatusReport device_status;
    EXPECT_FALSE(feel_to_standard_pid(encode(AnyReport{device_status}), out));
}

TEST(StandardPidTranslation, RefusesWhatAStandardDeviceLacks) {
    std::vector<uint8_t> feel;
    // Device Info (feel's vendor feature report) is no report of the standard device.
    Error e = standard_pid_to_feel(std::vector<uint8_t>{0x30, 0, 0}, feel);
    ASSERT_TRUE(e);
    EXPECT_STREQ(e.field, "report.id");
    EXPECT_FALSE(is_standard_pid_report(0x30));
    EXPECT_FALSE(is_standard_pid_report(static_cast<uint8_t>(ReportId::download_force_sample)));
    EXPECT_TRUE(is_standard_pid_report(static_cast<uint8_t>(ReportId::set_effect)));
    // feel's own Set Constant Force (with its sequence) is too long for the standard one.
    SetConstantForceReport c;
    e = standard_pid_to_feel(encode(AnyReport{c}), feel);
    ASSERT_TRUE(e);
    EXPECT_STREQ(e.field, "report.length");
    // Effect Type 13 names nothing in the list of twelve.
    std::string error;
    const std::optional<PidLayout> l = PidLayout::from_bytes(standard_pid_descriptor(stick()), error);
    ASSERT_TRUE(l.has_value());
    std::optional<std::vector<uint8_t>> create = create_new_effect(*l, EffectType::sine, error);
    ASSERT_TRUE(create.has_value());
    const FieldPlace type = l->find(PidReport::create_new_effect, 0x000F0031);  // ET Sine, in the Effect Type array
    ASSERT_TRUE(type);
    (*create)[1 + type.field->bit_offset / 8] = 13;
    e = standard_pid_to_feel(*create, feel);
    ASSERT_TRUE(e);
    EXPECT_STREQ(e.field, "create_new_effect.type");
    EXPECT_EQ(e.allowed.max, 12);
}

}  // namespace
}  // namespace feel::protocol
