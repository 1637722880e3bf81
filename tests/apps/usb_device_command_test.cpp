// `feel device --sim --usb`'s flags: every refusal names the flag and what is allowed, before
// anything touches configfs. (The gadget itself is tested against the kernel: tests/linux.)
#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "usb_device_command.hpp"

namespace feel::cli::testing {
namespace {

class UsbDevice : public CliTest {};

TEST_F(UsbDevice, UsbIdsAreHexOrDecimalUpTo0xFFFF) {
    EXPECT_EQ(parse_usb_id("--vid", "0x1209"), 0x1209);
    EXPECT_EQ(parse_usb_id("--vid", "4617"), 4617);
    EXPECT_EQ(parse_usb_id("--pid", "0xffff"), 0xFFFF);
    for (const char* bad : {"", "0x10000", "-1", "+5", "12ab", "0x", "70000"}) {
        try {
            (void)parse_usb_id("--pid", bad);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const UsageError& e) {
            EXPECT_NE(std::string(e.what()).find("--pid"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("0x0000..0xFFFF"), std::string::npos) << e.what();
        }
    }
}

TEST_F(UsbDevice, ConflictingFlagsExitTwoNamingThem) {
    Result r = run_cli({"device", "--sim", "--usb", "--udc", "dummy_udc.0", "--ffs", "/tmp/x"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--udc and --ffs"), std::string::npos) << r.err;
    r = run_cli({"device", "--sim", "--usb", "--listen", "unix:/tmp/x.sock"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--listen and --usb"), std::string::npos) << r.err;
    r = run_cli({"device", "--sim", "--usb", "--vid", "0x12345"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--vid"), std::string::npos) << r.err;
    r = run_cli({"device", "--usb"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--sim"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace feel::cli::testing
