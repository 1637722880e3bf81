// A frame whose first byte names no report is answered like every refusal, and blamed on
// nothing it is not: docs/protocol.md promises the decoder's error "report.id" with the
// byte in `value`, and Command Status's `command` is kNoReportId (0, which HID reserves),
// never a real report such as Keep Alive that the host did not send.
#include <gtest/gtest.h>

#include <string>

#include "session_rig.hpp"

namespace feel::peripheral::test {
namespace {

using protocol::ReportId;

// Offers one raw frame and returns the one CommandStatus it got.
protocol::CommandAnswer answer_to(SessionRig& rig, Frame f) {
    const std::size_t seen = rig.statuses.size();
    rig.offer(std::move(f));
    rig.run(3);
    EXPECT_EQ(rig.statuses.size(), seen + 1) << "one frame, one answer";
    return rig.statuses.size() > seen ? rig.statuses[seen] : protocol::CommandAnswer{};
}

TEST(UnknownReport, EveryIdThatNamesNoReportIsQuotedInValueAndBlamedOnNoReport) {
    SessionRig rig;
    int unknown = 0;
    for (int id = 0; id <= 0xFF; ++id) {
        const auto byte = static_cast<uint8_t>(id);
        if (protocol::report_kind(byte).has_value()) continue;
        ++unknown;
        for (const FrameKind kind : {FrameKind::output_report, FrameKind::set_feature}) {
            const auto s = answer_to(rig, Frame{kind, {byte, 0x2A, 0x00, 0x00, 0x00, 0x01}});
            SCOPED_TRACE("id " + std::to_string(id) + (kind == FrameKind::set_feature ? " (set_feature)" : ""));
            EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
            EXPECT_STREQ(s.field, "report.id");
            EXPECT_EQ(s.value, id);
            EXPECT_FALSE(s.has_range);
            EXPECT_EQ(s.command, protocol::kNoReportId);
            EXPECT_NE(s.command, ReportId::keep_alive);
            EXPECT_EQ(s.sequence, 0u) << "an unknown report has no sequence to read";
        }
    }
    EXPECT_GT(unknown, 150);  // 256 byte values, a few dozen reports
}

TEST(UnknownReport, ReportId0IsReservedByHidAndNamesNoReport) {
    // HID 1.11 §6.2.2.7: "Report ID zero is reserved and should not be used."
    EXPECT_FALSE(protocol::report_kind(0).has_value());
    EXPECT_EQ(static_cast<int>(protocol::kNoReportId), 0);
}

TEST(UnknownReport, AKnownReportWithBadBytesIsStillBlamedOnItself) {
    SessionRig rig;
    const auto s = answer_to(rig, Frame{FrameKind::output_report, {0x0D, 0x07, 0x00, 0x00, 0x00}});
    EXPECT_EQ(s.command, ReportId::device_gain);
    EXPECT_EQ(s.sequence, 7u);
    EXPECT_STREQ(s.field, "report.length");
}

}  // namespace
}  // namespace feel::peripheral::test
