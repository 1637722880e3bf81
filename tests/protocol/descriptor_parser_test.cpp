// The HID report descriptor parser on hand-written descriptors: what it reads (bit
// layouts, usages, global state with Push/Pop, the conventions of descriptor_parser.hpp)
// and what it refuses, with the byte offset of the item at fault.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"

namespace feel::protocol::hid {
namespace {

DescriptorParse parse(const std::vector<uint8_t>& bytes) { return parse_report_descriptor(bytes); }

// HID 1.11 Appendix E.10's boot-protocol mouse: 3 one-bit buttons, 5 bits of padding,
// 8-bit relative X and Y. No Report IDs.
const std::vector<uint8_t> kMouse = {
    0x05, 0x01,  // Usage Page (Generic Desktop)
    0x09, 0x02,  // Usage (Mouse)
    0xA1, 0x01,  // Collection (Application)
    0x09, 0x01,  //   Usage (Pointer)
    0xA1, 0x00,  //   Collection (Physical)
    0x05, 0x09,  //     Usage Page (Button)
    0x19, 0x01,  //     Usage Minimum (1)
    0x29, 0x03,  //     Usage Maximum (3)
    0x15, 0x00,  //     Logical Minimum (0)
    0x25, 0x01,  //     Logical Maximum (1)
    0x95, 0x03,  //     Report Count (3)
    0x75, 0x01,  //     Report Size (1)
    0x81, 0x02,  //     Input (Data, Var, Abs)
    0x95, 0x01,  //     Report Count (1)
    0x75, 0x05,  //     Report Size (5)
    0x81, 0x01,  //     Input (Constant)
    0x05, 0x01,  //     Usage Page (Generic Desktop)
    0x09, 0x30,  //     Usage (X)
    0x09, 0x31,  //     Usage (Y)
    0x15, 0x81,  //     Logical Minimum (-127)
    0x25, 0x7F,  //     Logical Maximum (127)
    0x75, 0x08,  //     Report Size (8)
    0x95, 0x02,  //     Report Count (2)
    0x81, 0x06,  //     Input (Data, Var, Rel)
    0xC0,        //   End Collection
    0xC0,        // End Collection
};

TEST(DescriptorParser, ReadsTheBootMouse) {
    const DescriptorParse p = parse(kMouse);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_FALSE(p.descriptor.uses_report_ids);
    ASSERT_EQ(p.descriptor.reports.size(), 1u);
    const DescriptorReport& r = p.descriptor.reports[0];
    EXPECT_EQ(r.kind, MainItemKind::input);
    EXPECT_EQ(r.id, 0);
    EXPECT_EQ(r.bit_length, 24u);
    ASSERT_EQ(r.fields.size(), 3u);
    const std::vector<uint32_t> buttons = {0x00090001, 0x00090002, 0x00090003};
    EXPECT_EQ(r.fields[0].usages, buttons);
    EXPECT_EQ(r.fields[0].bit_offset, 0u);
    EXPECT_TRUE(r.fields[0].is_variable());
    EXPECT_TRUE(r.fields[1].is_constant());
    EXPECT_EQ(r.fields[1].bit_offset, 3u);
    EXPECT_EQ(r.fields[2].bit_offset, 8u);
    EXPECT_EQ(r.fields[2].logical_min, -127);
    EXPECT_EQ(r.fields[2].logical_max, 127);
    EXPECT_EQ(r.fields[2].flags & kFlagRelative, kFlagRelative);
    EXPECT_EQ(r.fields[2].usage_of(1), 0x00010031u);
    EXPECT_EQ(r.fields[2].usage_of(5), 0x00010031u) << "the last usage repeats";
    const std::vector<uint32_t> nesting = {0x00010002, 0x00010001};
    EXPECT_EQ(r.fields[2].collections, nesting);
    EXPECT_EQ(r.fields[2].physical_min, -127) << "physical defaults to logical";
}

TEST(DescriptorParser, ReportIdsSeparateReportsByKindAndId) {
    const std::vector<uint8_t> d = {
        0x06, 0x00, 0xFF,  // Usage Page (vendor 0xFF00)
        0x09, 0x01, 0xA1, 0x01,
        0x85, 0x02, 0x09, 0x10, 0x15, 0x00, 0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x04, 0x91, 0x02,
        0x85, 0x02, 0x09, 0x11, 0x95, 0x02, 0xB1, 0x02,   // feature 2: same id, other kind
        0x85, 0x05, 0x09, 0x12, 0x75, 0x10, 0x95, 0x01, 0x91, 0x02,
        0x85, 0x02, 0x09, 0x13, 0x75, 0x08, 0x95, 0x01, 0x91, 0x02,  // output 2 continues
        0xC0,
    };
    const DescriptorParse p = parse(d);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_TRUE(p.descriptor.uses_report_ids);
    ASSERT_EQ(p.descriptor.reports.size(), 3u);
    const DescriptorReport* out2 = p.descriptor.find(MainItemKind::output, 2);
    ASSERT_NE(out2, nullptr);
    EXPECT_EQ(out2->bit_length, 40u);
    EXPECT_EQ(out2->fields[1].bit_offset, 32u);
    EXPECT_EQ(out2->fields[1].usages.front(), 0xFF000013u);
    EXPECT_EQ(p.descriptor.find(MainItemKind::feature, 2)->bit_length, 16u);
    EXPECT_EQ(p.descriptor.find(MainItemKind::output, 5)->bit_length, 16u);
    EXPECT_EQ(p.descriptor.find(MainItemKind::input, 2), nullptr);
}

TEST(DescriptorParser, PushPopRestoresGlobalState) {
    const std::vector<uint8_t> d = {
        0x05, 0x01, 0x15, 0x00, 0x25, 0x0A, 0x75, 0x08, 0x95, 0x01,
        0xA4,                          // Push
        0x05, 0x09, 0x15, 0x80, 0x25, 0x7F, 0x75, 0x04, 0x95, 0x02,
        0x09, 0x01, 0x81, 0x02,        // uses the pushed-over state: 2 x 4 bits
        0xB4,                          // Pop
        0x09, 0x30, 0x81, 0x02,        // back to 8 bits, 0..10, Generic Desktop
    };
    const DescriptorParse p = parse(d);
    ASSERT_TRUE(p.ok()) << p.error;
    const DescriptorReport& r = p.descriptor.reports.at(0);
    ASSERT_EQ(r.fields.size(), 2u);
    EXPECT_EQ(r.fields[0].report_size, 4u);
    EXPECT_EQ(r.fields[0].logical_min, -128);
    EXPECT_EQ(r.fields[0].usages.front(), 0x00090001u);
    EXPECT_EQ(r.fields[1].report_size, 8u);
    EXPECT_EQ(r.fields[1].logical_min, 0);
    EXPECT_EQ(r.fields[1].logical_max, 10);
    EXPECT_EQ(r.fields[1].usages.front(), 0x00010030u);
    EXPECT_EQ(r.bit_length, 16u);
}

TEST(DescriptorParser, ConventionsForUnsignedMaximaUnitsAndExtendedUsages) {
    const std::vector<uint8_t> d = {
        0x15, 0x00,                          // Logical Minimum 0
        0x27, 0xFF, 0xFF, 0xFF, 0xFF,        // Logical Maximum 0xFFFFFFFF: unsigned as min >= 0
        0x66, 0x01, 0x10,                    // Unit 0x1001 (SI linear seconds)
        0x55, 0x0A,                          // Unit Exponent nibble 0xA = -6
        0x75, 0x20, 0x95, 0x01,
        0x0B, 0x50, 0x00, 0x0F, 0x00,        // Usage, extended: PID (0x0F) Duration (0x50)
        0x91, 0x42,                          // Output (Data, Var, Abs, Null State)
        0x15, 0xFF, 0x25, 0xFF,              // min -1, max 0xFF read signed: -1
        0x75, 0x08, 0x09, 0x01, 0x91, 0x03,  // constant: inverted range allowed
    };
    const DescriptorParse p = parse(d);
    ASSERT_TRUE(p.ok()) << p.error;
    const DescriptorField& f = p.descriptor.reports.at(0).fields.at(0);
    EXPECT_EQ(f.logical_min, 0);
    EXPECT_EQ(f.logical_max, 0xFFFFFFFFLL);
    EXPECT_EQ(f.unit, 0x1001u);
    EXPECT_EQ(f.unit_exponent, -6);
    EXPECT_EQ(f.usages.front(), 0x000F0050u);
    EXPECT_TRUE(f.has_null_state());
    EXPECT_EQ(p.descriptor.reports.at(0).fields.at(1).logical_max, -1);
}

TEST(DescriptorParser, DelimiterSetsKeepTheirFirstUsage) {
    const std::vector<uint8_t> d = {
        0x05, 0x01, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x08,
        0xA9, 0x01, 0x09, 0x30, 0x09, 0x31, 0xA9, 0x00,  // Delimiter {X | Y}
        0x09, 0x32, 0x81, 0x02,
    };
    const DescriptorParse p = parse(d);
    ASSERT_TRUE(p.ok()) << p.error;
    const std::vector<uint32_t> usages = {0x00010030, 0x00010032};
    EXPECT_EQ(p.descriptor.reports.at(0).fields.at(0).usages, usages);
}

struct Malformed {
    const char* what;
    std::vector<uint8_t> bytes;
    const char* message;     // a part of the error
    std::size_t offset;      // the item at fault
};

TEST(DescriptorParser, RefusesMalformedDescriptors) {
    const std::vector<uint8_t> field = {0x75, 0x08, 0x95, 0x01};  // size 8, count 1
    auto with_field = [&](std::vector<uint8_t> tail) {
        std::vector<uint8_t> d = field;
        d.insert(d.end(), tail.begin(), tail.end());
        return d;
    };
    const Malformed cases[] = {
        {"truncated 2-byte item", {0x05, 0x01, 0x26, 0xFF}, "truncated item 0x26", 2},
        {"truncated 4-byte item", {0x27, 0x01, 0x02}, "needs 4 data byte(s), 2 left", 0},
        {"long item", {0x05, 0x01, 0xFE, 0x02, 0x10, 0x00, 0x00}, "long item", 2},
        {"reserved item type", {0x0C}, "reserved item type", 0},
        {"reserved main tag", {0xD0}, "reserved main item tag", 0},
        {"reserved global tag", {0xC4}, "reserved global item tag", 0},
        {"reserved local tag", {0xB8}, "reserved local item tag", 0},
        {"end collection without collection", {0xC0}, "End Collection without", 0},
        {"collection left open", {0x09, 0x01, 0xA1, 0x01}, "1 collection(s) left open", 4},
        {"reserved collection type", {0xA1, 0x20, 0xC0}, "reserved collection type", 0},
        {"report size 0", {0x75, 0x00, 0x95, 0x01, 0x81, 0x02}, "Report Size 0", 4},
        {"report size never set", {0x95, 0x01, 0x81, 0x02}, "Report Size 0", 2},
        {"report count 0", {0x75, 0x08, 0x95, 0x00, 0x81, 0x02}, "Report Count 0", 4},
        {"report size too big", {0x76, 0x01, 0x02, 0x95, 0x01, 0x81, 0x02}, "exceeds 256 bits", 5},
        {"report id 0", {0x85, 0x00}, "Report ID 0 is reserved", 0},
        {"report id wider than a byte", {0x86, 0x00, 0x01}, "wider than a byte", 0},
        {"report id after unnumbered items", with_field({0x81, 0x02, 0x85, 0x01}),
         "Report ID after main items that had none", 6},
        {"pop without push", {0xB4}, "Pop without a Push", 0},
        {"push left at the end", {0xA4}, "Push(es) without a Pop", 1},
        {"inverted logical range", with_field({0x15, 0x05, 0x25, 0x01, 0x81, 0x02}),
         "Logical Minimum 5 is greater than Logical Maximum 1", 8},
        {"usage minimum alone", with_field({0x19, 0x01, 0x81, 0x02}), "Usage Minimum without Usage Maximum", 6},
        {"usage maximum alone", with_field({0x29, 0x01, 0x81, 0x02}), "Usage Maximum without Usage Minimum", 6},
        {"usage range inverted", with_field({0x19, 0x05, 0x29, 0x01}), "greater than Usage Maximum", 6},
        {"usage page too wide", {0x07, 0x00, 0x00, 0x01, 0x00}, "wider than 16 bits", 0},
        {"delimiter close without open", {0xA9, 0x00}, "Delimiter close without", 0},
        {"delimiter left open", {0xA9, 0x01}, "Delimiter set left open", 2},
    };
    for (const Malformed& c : cases) {
        SCOPED_TRACE(c.what);
        const DescriptorParse p = parse(c.bytes);
        ASSERT_FALSE(p.ok());
        EXPECT_NE(p.error.find(c.message), std::string::npos) << p.error;
        EXPECT_EQ(p.error_offset, c.offset) << p.error;
        EXPECT_EQ(p.error.rfind("byte " + std::to_string(c.offset) + ": ", 0), 0u) << p.error;
    }
}

TEST(DescriptorParser, RefusesAMainItemWithoutIdOnceIdsAreUsed) {
    const std::vector<uint8_t> d = {0x85, 0x01, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02,
                                    0xA4, 0x85, 0x02, 0xB4};
    EXPECT_TRUE(parse(d).ok()) << "Push/Pop of a Report ID keeps it non-zero";
}

TEST(DescriptorParser, RefusesNestingBeyondItsLimits) {
    std::vector<uint8_t> deep;
    for (int k = 0; k <= kMaxCollectionDepth; ++k) deep.insert(deep.end(), {0xA1, 0x02});
    EXPECT_NE(parse(deep).error.find("nested deeper than 32"), std::string::npos);
    std::vector<uint8_t> pushes(static_cast<std::size_t>(kMaxPushDepth) + 1, 0xA4);
    EXPECT_NE(parse(pushes).error.find("Push nested deeper than 16"), std::string::npos);
    // A report beyond 16 KiB: 256-bit elements, 65535 of them.
    const std::vector<uint8_t> huge = {0x76, 0x00, 0x01, 0x96, 0xFF, 0xFF, 0x81, 0x02};
    EXPECT_NE(parse(huge).error.find("grows beyond 16384 bytes"), std::string::npos);
    // Usage ranges are expanded, within a budget.
    std::vector<uint8_t> many = {0x75, 0x01, 0x95, 0x01};
    for (int k = 0; k < 20; ++k) many.insert(many.end(), {0x19, 0x00, 0x2A, 0xFF, 0xFF, 0x81, 0x02});
    EXPECT_NE(parse(many).error.find("usages in the descriptor"), std::string::npos);
}

TEST(DescriptorParser, EveryTruncationOfFeelsDescriptorIsRefusedCleanly) {
    const std::span<const uint8_t> full = report_descriptor();
    for (std::size_t len = 0; len < full.size(); ++len) {
        const DescriptorParse p = parse_report_descriptor(full.first(len));
        if (len <= 4) {
            // Before Collection (Application) opens: whole items declaring no report, or a
            // cut item.
            if (p.ok()) {
                EXPECT_TRUE(p.descriptor.reports.empty());
            }
            continue;
        }
        ASSERT_FALSE(p.ok()) << "prefix of " << len << " bytes accepted";
        EXPECT_LE(p.error_offset, len);
    }
}

}  // namespace
}  // namespace feel::protocol::hid
