// The host's check of a device's report descriptor: the codec's own descriptor passes, a
// descriptor whose report sizes differ from the codec's is refused naming the report.
#include <gtest/gtest.h>

#include <vector>

#include "descriptor_check.hpp"
#include "feel/protocol/codec.hpp"

namespace feel::host {
namespace {

using protocol::report_descriptor;

TEST(HostDescriptorCheck, TheCodecsDescriptorMatchesTheCodecsSizes) {
    EXPECT_EQ(check_report_descriptor(report_descriptor()), "");
}

TEST(HostDescriptorCheck, AChangedReportSizeIsNamed) {
    std::vector<uint8_t> d(report_descriptor().begin(), report_descriptor().end());
    // Make the first one-byte Report Size item (prefix 0x75) one bit wider: the report it
    // belongs to grows.
    bool changed = false;
    for (std::size_t i = 0; i + 1 < d.size(); ++i) {
        if (d[i] == 0x75) {
            ++d[i + 1];
            changed = true;
            break;
        }
    }
    ASSERT_TRUE(changed);
    const std::string problem = check_report_descriptor(d);
    EXPECT_NE(problem, "");
    EXPECT_NE(problem.find("report 0x"), std::string::npos) << problem;
    EXPECT_NE(check_report_descriptor({}), "");
}

}  // namespace
}  // namespace feel::host
