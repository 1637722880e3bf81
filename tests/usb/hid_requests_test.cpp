// classify_setup() against HID 1.11 §7.1-7.2's request codes and USB 2.0 §9.3's
// bmRequestType bits, written here as the numbers the specifications give.
#include <gtest/gtest.h>

#include "hid_requests.hpp"

namespace feel::usb::detail {
namespace {

using Kind = ControlAction::Kind;

SetupPacket setup(uint8_t type, uint8_t request, uint16_t value, uint16_t index, uint16_t length) {
    return SetupPacket{type, request, value, index, length};
}

TEST(HidRequests, GetReportDescriptorIsServed) {
    const ControlAction a = classify_setup(setup(0x81, 0x06, 0x2200, 0, 512));
    EXPECT_EQ(a.kind, Kind::report_descriptor);
    EXPECT_EQ(a.length, 512);
    EXPECT_EQ(classify_setup(setup(0x81, 0x06, 0x2100, 0, 9)).kind, Kind::hid_descriptor);
}

TEST(HidRequests, GetFeatureReportNamesItsIdAndKeepsTheHostsLength) {
    // usbhid asks with wLength rounded up to 64 (report id 0x12, Feature = 3).
    const ControlAction a = classify_setup(setup(0xA1, 0x01, 0x0312, 0, 64));
    EXPECT_EQ(a.kind, Kind::get_feature);
    EXPECT_EQ(a.report_id, 0x12);
    EXPECT_EQ(a.length, 64);
    EXPECT_TRUE(a.device_to_host);
}

TEST(HidRequests, SetReportOutputAndFeature) {
    EXPECT_EQ(classify_setup(setup(0x21, 0x09, 0x0201, 0, 20)).kind, Kind::set_output);
    const ControlAction f = classify_setup(setup(0x21, 0x09, 0x0311, 0, 8));
    EXPECT_EQ(f.kind, Kind::set_feature);
    EXPECT_EQ(f.report_id, 0x11);
    EXPECT_FALSE(f.device_to_host);
}

TEST(HidRequests, SetIdleIsAcknowledged) {
    EXPECT_EQ(classify_setup(setup(0x21, 0x0A, 0x0000, 0, 0)).kind, Kind::acknowledge);
}

TEST(HidRequests, EverythingElseIsStalledInTheRequestsOwnDirectionWithAReason) {
    struct Case {
        SetupPacket s;
        bool in;
        const char* says;
    };
    const Case cases[] = {
        {setup(0xA1, 0x01, 0x0140, 0, 64), true, "Input"},           // GET_REPORT(Input)
        {setup(0xA1, 0x02, 0x0000, 0, 1), true, "GET_IDLE"},         // GET_IDLE
        {setup(0xA1, 0x03, 0x0000, 0, 1), true, "boot"},             // GET_PROTOCOL
        {setup(0x21, 0x0B, 0x0000, 0, 0), false, "boot"},            // SET_PROTOCOL
        {setup(0x21, 0x09, 0x0101, 0, 4), false, "Input"},           // SET_REPORT(Input)
        {setup(0x21, 0x09, 0x0201, 0, 0), false, "wLength 0"},       // SET_REPORT without data
        {setup(0x21, 0x09, 0x0201, 0, 5000), false, "1..4096"},      // longer than any frame
        {setup(0x21, 0x09, 0x0201, 1, 4), false, "interface 1"},     // another interface
        {setup(0xC1, 0x01, 0x0000, 0, 4), true, "vendor"},           // vendor request
        {setup(0x82, 0x00, 0x0000, 0x81, 2), true, "recipient"},     // endpoint recipient
        {setup(0x81, 0x06, 0x2300, 0, 9), true, "0x23"},             // physical descriptor
        {setup(0x21, 0x0A, 0x0000, 0, 2), false, "no data"},         // SET_IDLE with data
        {setup(0x21, 0x77, 0x0000, 0, 0), false, "not a HID class"}, // unknown class request
    };
    for (const Case& c : cases) {
        const ControlAction a = classify_setup(c.s);
        EXPECT_EQ(a.kind, Kind::stall) << a.reason;
        EXPECT_EQ(a.device_to_host, c.in) << a.reason;
        EXPECT_NE(a.reason.find(c.says), std::string::npos) << a.reason;
    }
}

}  // namespace
}  // namespace feel::usb::detail
