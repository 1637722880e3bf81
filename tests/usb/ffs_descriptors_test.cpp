// The FunctionFS blobs against linux/usb/functionfs.h's layout and USB 2.0 / HID 1.11's
// descriptor formats, read back byte by byte.
#include <gtest/gtest.h>

#include "ffs_descriptors.hpp"
#include "report_assembler.hpp"
#include "feel/protocol/codec.hpp"

namespace feel::usb::detail {
namespace {

uint32_t le32(const std::vector<uint8_t>& b, std::size_t at) {
    return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (static_cast<uint32_t>(b[at + 3]) << 24);
}

TEST(FfsDescriptors, V2HeaderThenFullAndHighSpeedSets) {
    const auto d = function_descriptors(300);
    ASSERT_GE(d.size(), 20u);
    EXPECT_EQ(le32(d, 0), 3u);         // FUNCTIONFS_DESCRIPTORS_MAGIC_V2
    EXPECT_EQ(le32(d, 4), d.size());   // length
    EXPECT_EQ(le32(d, 8), 1u | 2u);    // HAS_FS_DESC | HAS_HS_DESC
    EXPECT_EQ(le32(d, 12), 4u);        // fs_count
    EXPECT_EQ(le32(d, 16), 4u);        // hs_count
    // interface 9 + HID 9 + two endpoints of 7, per speed
    ASSERT_EQ(d.size(), 20u + 2 * (9 + 9 + 7 + 7));
    for (int speed = 0; speed < 2; ++speed) {
        const std::size_t at = 20 + static_cast<std::size_t>(speed) * 32;
        EXPECT_EQ(d[at + 1], 4);       // INTERFACE
        EXPECT_EQ(d[at + 4], 2);       // two endpoints
        EXPECT_EQ(d[at + 5], 3);       // HID class
        EXPECT_EQ(d[at + 9], 9);       // the HID descriptor, 9 bytes, right after
        EXPECT_EQ(d[at + 10], 0x21);
        EXPECT_EQ(d[at + 15], 0x22);   // one Report descriptor
        EXPECT_EQ(d[at + 16] | (d[at + 17] << 8), 300);
        const std::size_t ep_in = at + 18, ep_out = at + 25;
        EXPECT_EQ(d[ep_in + 1], 5);
        EXPECT_EQ(d[ep_in + 2], 0x81);  // IN, endpoint 1
        EXPECT_EQ(d[ep_in + 3], 3);     // interrupt
        EXPECT_EQ(d[ep_out + 2], 0x02); // OUT, endpoint 2
        const int packet = d[ep_in + 4] | (d[ep_in + 5] << 8);
        EXPECT_EQ(packet, speed == 0 ? 64 : 1024);
        // 1 ms either way: full speed counts 1 ms frames, high speed 2^(n-1) x 125 us.
        EXPECT_EQ(d[ep_in + 6], speed == 0 ? 1 : 4);
    }
    EXPECT_THROW((void)function_descriptors(70000), std::invalid_argument);
}

TEST(FfsDescriptors, StringsBlob) {
    const auto s = function_strings("abc");
    EXPECT_EQ(le32(s, 0), 2u);  // FUNCTIONFS_STRINGS_MAGIC
    EXPECT_EQ(le32(s, 4), s.size());
    EXPECT_EQ(le32(s, 8), 1u);
    EXPECT_EQ(le32(s, 12), 1u);
    EXPECT_EQ(s[16] | (s[17] << 8), 0x0409);
    EXPECT_EQ(std::string(s.begin() + 18, s.end()), std::string("abc\0", 4));
}

TEST(ReportAssembler, JoinsFullPacketsUntilTheReportsSize) {
    // The largest output report, sent in 64-byte packets as a full-speed host does.
    uint8_t id = 0;
    for (int i = 1; i < 256; ++i) {
        const auto kind = protocol::report_kind(static_cast<uint8_t>(i));
        if (kind == protocol::ReportKind::output && protocol::report_size(static_cast<uint8_t>(i)) > 64 &&
            protocol::report_size(static_cast<uint8_t>(i)) % 64 != 0) {
            id = static_cast<uint8_t>(i);
            break;
        }
    }
    if (id == 0) GTEST_SKIP() << "no output report spans packets";
    const std::size_t size = protocol::report_size(id);
    std::vector<uint8_t> report(size, 0xAB);
    report[0] = id;
    ReportAssembler a(64);
    std::size_t sent = 0;
    bool done = false;
    while (sent < size) {
        const std::size_t n = std::min<std::size_t>(64, size - sent);
        done = a.add({report.data() + sent, n});
        sent += n;
        EXPECT_EQ(done, sent == size);
    }
    EXPECT_EQ(a.take(), report);
}

TEST(ReportAssembler, AShortPacketOrAnUnknownIdEndsTheReportAsItCame) {
    ReportAssembler a(64);
    const uint8_t unknown[] = {0xEE, 1, 2};
    EXPECT_TRUE(a.add(unknown));
    EXPECT_EQ(a.take().size(), 3u);
    const uint8_t truncated[] = {0x01, 0};  // Set Effect cut short: the session refuses its length
    EXPECT_TRUE(a.add(truncated));
    EXPECT_EQ(a.take().size(), 2u);
}

}  // namespace
}  // namespace feel::usb::detail
