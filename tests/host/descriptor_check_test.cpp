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

TEST(HostDescriptorCheck, ReadsTheDevicesJoystickFromItsDescriptor) {
    protocol::JoystickLayout layout;  // Y and Rz, 5 buttons, 3 hats
    layout.axis_count = 2;
    layout.axes[0] = Axis::y;
    layout.axes[1] = Axis::rz;
    layout.button_count = 5;
    layout.hat_count = 3;
    protocol::JoystickLayout read;
    read.axis_count = 6;
    EXPECT_EQ(check_report_descriptor(protocol::report_descriptor(layout), &read), "");
    EXPECT_EQ(read, layout);
}

TEST(HostDescriptorCheck, AStandardPidLoopCountIsNamed) {
    // Loop Count (PID 0x7C) declared 8 bits wide, as a standard PID device has it.
    std::vector<uint8_t> d(report_descriptor().begin(), report_descriptor().end());
    std::size_t at = 0;
    while (at + 1 < d.size() && !(d[at] == 0x09 && d[at + 1] == 0x7C)) ++at;
    ASSERT_LT(at + 1, d.size());
    while (at + 1 < d.size() && !(d[at] == 0x75 && d[at + 1] == 16)) ++at;
    ASSERT_LT(at + 1, d.size());
    d[at + 1] = 8;
    const std::string problem = check_report_descriptor(d);
    EXPECT_NE(problem.find("Loop Count is 8 bits, as on a standard PID device"), std::string::npos) << problem;
}

}  // namespace
}  // namespace feel::host
