// feel bridge --log: the wire log records what the feel device receives, in the form of the
// USB device log (docs/usb-device.md), so the VM's checker can read either.
#include "wire_log.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "bridge_effects.hpp"
#include "feel/bridge/bridge.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/transport/transport.hpp"

namespace feel::bridge {
namespace {

TEST(WireLog, RecordsTheReportsOfAnUploadAndItsRefusals) {
    std::stringstream log;
    {
        host::Result<host::Device> device = open_device("sim:iforce2", &log);
        ASSERT_TRUE(device) << device.status().message;
        BridgeEffects effects(*device, [](const std::string&) {});
        ff_effect e{};
        e.type = FF_CONSTANT;
        e.id = 0;
        e.u.constant.level = 16384;
        ASSERT_EQ(effects.upload(e), 0);
        effects.play(0, 1);
        effects.set_gain(0xffff);
    }
    const std::string text = log.str();
    EXPECT_NE(text.find(" set_feature create_new_effect "), std::string::npos) << text;
    EXPECT_NE(text.find(" feature_reply block_load "), std::string::npos) << text;
    EXPECT_NE(text.find(" output_report set_constant_force "), std::string::npos) << text;
    EXPECT_NE(text.find("magnitude=5000"), std::string::npos) << text;  // 16384 of 32767
    EXPECT_NE(text.find(" output_report effect_operation "), std::string::npos) << text;
    EXPECT_NE(text.find(" output_report device_gain "), std::string::npos) << text;
}

TEST(WireLog, ADeviceInAnotherProcessOverAUnixSocket) {
    const std::string socket = ::testing::TempDir() + "feel_bridge_wire_log.sock";
    peripheral::Peripheral device(peripheral::PeripheralOptions{});
    device.serve(transport::listen(transport::Address::parse("unix:" + socket)));
    std::stringstream log;
    {
        host::Result<host::Device> host = open_device("unix:" + socket, &log);
        ASSERT_TRUE(host) << host.status().message;
        BridgeEffects effects(*host, [](const std::string&) {});
        ff_effect e{};
        e.type = FF_RAMP;
        e.id = 0;
        e.replay.length = 500;
        e.u.ramp.start_level = -32768;
        e.u.ramp.end_level = 32767;
        ASSERT_EQ(effects.upload(e), 0);
    }
    device.stop();
    EXPECT_NE(log.str().find(" output_report set_ramp_force "), std::string::npos) << log.str();
    EXPECT_NE(log.str().find("-10000"), std::string::npos) << log.str();
}

TEST(WireLog, NothingListeningIsDisconnected) {
    std::stringstream log;
    host::Result<host::Device> host = open_device("unix:" + ::testing::TempDir() + "feel_bridge_nobody.sock", &log);
    ASSERT_FALSE(host);
    EXPECT_EQ(host.status().kind, host::ErrorKind::disconnected);
}

TEST(WireLog, AnAddressThatIsNoneIsInvalidArgument) {
    std::stringstream log;
    EXPECT_THROW((void)open_device("tcp:nowhere", &log), std::invalid_argument);
}

}  // namespace
}  // namespace feel::bridge
