// feel's descriptor through the hid-pidff model (pidff_acceptance.hpp): Linux's PID driver
// would initialise force feedback on it. The model itself is checked on descriptors it must
// refuse, made by changing one thing in feel's: each names the rule hid-pidff applies.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "pidff_acceptance.hpp"

namespace feel::protocol {
namespace {

test::PidffVerdict verdict_of(std::span<const uint8_t> bytes) {
    const hid::DescriptorParse parse = hid::parse_report_descriptor(bytes);
    EXPECT_TRUE(parse.ok()) << parse.error;
    return test::pidff_check(parse.descriptor);
}

std::string problems_of(const test::PidffVerdict& v) {
    std::string all;
    for (const std::string& p : v.problems) all += p + "\n";
    return all;
}

TEST(PidffAcceptance, FeelsDescriptorInitialisesForceFeedback) {
    const test::PidffVerdict v = verdict_of(report_descriptor());
    EXPECT_TRUE(v.accepted()) << problems_of(v);
    EXPECT_TRUE(v.gain);
    // All eleven effect types hid-pidff knows are offered (FF_CONSTANT .. FF_FRICTION).
    EXPECT_EQ(v.ff_effects.size(), 11u);
    // Blocks start at 1; hid-pidff offers at most 64 effects.
    EXPECT_EQ(v.first_block, 1);
    EXPECT_EQ(v.max_effects, 64);
}

// feel's descriptor, parsed, for a test to change one thing in it.
hid::ParsedDescriptor feels() {
    return hid::parse_report_descriptor(report_descriptor()).descriptor;
}

// The fields of every report that carry `usage` (PID page).
template <class Change>
void change_fields(hid::ParsedDescriptor& d, uint32_t usage, Change change) {
    for (hid::DescriptorReport& r : d.reports) {
        for (hid::DescriptorField& f : r.fields) {
            if (std::find(f.usages.begin(), f.usages.end(), usage) != f.usages.end()) change(f);
        }
    }
}

TEST(PidffAcceptance, RefusesASetEffectWithoutDirectionEnable) {
    hid::ParsedDescriptor d = feels();
    change_fields(d, 0x000F0056u, [](hid::DescriptorField& f) {
        for (uint32_t& u : f.usages) u = u == 0x000F0056u ? 0xFF000056u : u;
    });
    const test::PidffVerdict v = test::pidff_check(d);
    EXPECT_FALSE(v.accepted());
    EXPECT_NE(problems_of(v).find("unknown set_effect report layout: missing 0x56"), std::string::npos)
        << problems_of(v);
}

TEST(PidffAcceptance, RefusesAnEffectTypeListStartingAtZero) {
    hid::ParsedDescriptor d = feels();
    change_fields(d, 0x000F0026u, [](hid::DescriptorField& f) { f.logical_min = 0; });
    const test::PidffVerdict v = test::pidff_check(d);
    EXPECT_FALSE(v.accepted());
    EXPECT_NE(problems_of(v).find("logical_minimum is not 1"), std::string::npos) << problems_of(v);
}

TEST(PidffAcceptance, RefusesDeviceControlWhoseFirstFieldIsNotTheList) {
    // Swap Device Control's two fields: the sequence first, as feel's other reports have it.
    hid::ParsedDescriptor d = feels();
    for (hid::DescriptorReport& r : d.reports) {
        if (r.kind == hid::MainItemKind::output && !r.fields.empty() && !r.fields.front().is_variable() &&
            r.fields.front().usages.front() == 0x000F0097u) {
            std::swap(r.fields[0], r.fields[1]);
        }
    }
    const test::PidffVerdict v = test::pidff_check(d);
    EXPECT_FALSE(v.accepted());
    EXPECT_NE(problems_of(v).find("report 0x96 not found"), std::string::npos) << problems_of(v);
}

TEST(PidffAcceptance, RefusesADirectionOutsideALogicalCollection) {
    hid::ParsedDescriptor d = feels();
    change_fields(d, 0x000A0001u, [](hid::DescriptorField& f) {
        f.collections.pop_back();
        f.collection_types.pop_back();
    });
    const test::PidffVerdict v = test::pidff_check(d);
    EXPECT_FALSE(v.accepted());
    EXPECT_NE(problems_of(v).find("no field in a Logical collection 0x57"), std::string::npos)
        << problems_of(v);
}

TEST(PidffAcceptance, RefusesADescriptorWithoutPidReports) {
    // A joystick with no output report at all.
    const std::vector<uint8_t> joystick = {0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, 0x85, 0x01,
                                           0x09, 0x30, 0x15, 0x00, 0x25, 0x7F, 0x75, 0x08,
                                           0x95, 0x01, 0x81, 0x02, 0xC0};
    const test::PidffVerdict v = verdict_of(joystick);
    EXPECT_FALSE(v.accepted());
    EXPECT_NE(problems_of(v).find("not a PID device"), std::string::npos) << problems_of(v);
}

}  // namespace
}  // namespace feel::protocol
