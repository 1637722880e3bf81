// The Peripheral: the device runtime on its own loop thread and a service thread speaking
// the protocol over a transport. One host at a time; a host that leaves gets the device
// reset behind it.
#include "feel/peripheral/peripheral.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "peripheral_host.hpp"
#include "session_rig.hpp"

namespace feel::peripheral::test {
namespace {

using namespace std::chrono_literals;
using protocol::ReportId;


TEST(Peripheral, InProcessDeviceAnswersAndPlays) {
    Host host(open_in_process(quick_options()));
    const auto info = host.get<protocol::DeviceInfoReport>(ReportId::device_info);
    EXPECT_STREQ(info.device, "iforce2");
    EXPECT_EQ(info.effect_slots, 32);
    const uint16_t block = host.play_spring(1);
    EXPECT_EQ(block, 1);
    host.listen_for(100ms);
    ASSERT_TRUE(host.last_status.has_value());
    ASSERT_TRUE(host.last_effects.has_value());
    EXPECT_EQ(host.last_effects->resident_effects, 1);
    EXPECT_EQ(host.last_status->loop_rate_hz, 1000);
    EXPECT_EQ(host.last_effects->effect_block[0], block);
}

TEST(Peripheral, DeviceStatusCarriesTheMeasuredLoopRate) {
    PeripheralOptions o = quick_options();
    o.loop_rate_hz = 500;
    Host host(open_in_process(o));
    host.listen_for(1300ms);  // the rate is measured over windows of a second
    ASSERT_TRUE(host.last_status.has_value());
    EXPECT_EQ(host.last_status->loop_rate_hz, 500);
    // Ticks per second over the last second: 500 Hz, less what overruns on a busy machine
    // skipped, never more (to the window's edge tick).
    EXPECT_GT(host.last_status->measured_rate_millihz, 250'000u);
    EXPECT_LT(host.last_status->measured_rate_millihz, 505'000u);
    EXPECT_EQ(host.get<protocol::DeviceInfoReport>(ReportId::device_info).loop_rate_hz, 500);
}

TEST(Peripheral, RejectsBadOptionsByName) {
    PeripheralOptions o = quick_options("nosuch");
    try {
        Peripheral p(o);
        FAIL() << "an unknown profile was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("iforce2"), std::string::npos) << e.what();  // lists the known ones
    }
    o = quick_options();
    o.hand = "claw";
    EXPECT_THROW(Peripheral{o}, std::invalid_argument);
    o = quick_options("iforce1");
    o.loop_rate_hz = 2000;  // an I-FORCE 1.x-class loop runs at 1 kHz at most
    try {
        Peripheral p(o);
        FAIL() << "a loop rate beyond the profile's was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("100..1000"), std::string::npos) << e.what();
    }
    o = quick_options();
    o.service_fifo_priority = -1;
    try {
        Peripheral p(o);
        FAIL() << "a service thread priority of -1 was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("service_fifo_priority = -1 is out of range (allowed 1..99"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Peripheral, SecondHostGetsBusyAndIsClosed) {
    Peripheral device(quick_options());
    transport::ConnectionPair first = transport::in_process_pair("first");
    transport::ConnectionPair second = transport::in_process_pair("second");
    device.attach(std::move(first.device));
    ASSERT_TRUE(device.host_attached());
    device.attach(std::move(second.device));
    const std::optional<Frame> f = second.host->receive(2s);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, FrameKind::busy);
    EXPECT_THROW((void)second.host->receive(1s), transport::TransportError);
    // The first host is still served.
    Host host(std::move(first.host));
    EXPECT_EQ(host.get<protocol::DeviceInfoReport>(ReportId::device_info).effect_slots, 32);
    EXPECT_EQ(device.stats().hosts_served, 1u);
}

TEST(Peripheral, HostDisconnectResetsTheDevice) {
    Peripheral device(quick_options());
    {
        transport::ConnectionPair pair = transport::in_process_pair("first");
        device.attach(std::move(pair.device));
        Host host(std::move(pair.host));
        host.play_spring(1);
        host.play_spring(10);
        const auto pool = host.get<protocol::PidPoolReport>(ReportId::pid_pool);
        EXPECT_EQ(pool.free_effects, 30);
        host.connection().close();
    }
    ASSERT_TRUE(wait_until([&] { return !device.host_attached(); }));
    EXPECT_EQ(device.stats().runtime.pipeline.commands_refused, 0);

    transport::ConnectionPair pair = transport::in_process_pair("second");
    device.attach(std::move(pair.device));
    Host host(std::move(pair.host));
    const auto pool = host.get<protocol::PidPoolReport>(ReportId::pid_pool);
    EXPECT_EQ(pool.free_effects, 32);
    EXPECT_EQ(pool.ram_pool_available, pool.ram_pool_size);
    host.listen_for(50ms);
    ASSERT_TRUE(host.last_effects.has_value());
    EXPECT_EQ(host.last_effects->resident_effects, 0);
    EXPECT_EQ(host.last_effects->playing_effects, 0);
    // The new host starts at block 1 again.
    EXPECT_EQ(host.play_spring(1), 1);
    EXPECT_EQ(device.stats().hosts_served, 2u);
}

TEST(Peripheral, ServesHostsOnAUnixSocket) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("feel-peripheral-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    transport::Address address;
    address.kind = transport::Address::Kind::unix_socket;
    address.path = (dir / "dev.sock").string();
    {
        Peripheral device(quick_options("iforce1"));
        device.serve(transport::listen(address));
        EXPECT_EQ(device.address(), address);
        Host host(transport::connect(address, 2s));
        EXPECT_STREQ(host.get<protocol::DeviceInfoReport>(ReportId::device_info).device, "iforce1");
        EXPECT_EQ(host.play_spring(1), 1);
        // A second host on the socket is turned away while the first is attached.
        auto second = transport::connect(address, 2s);
        const std::optional<Frame> f = second->receive(2s);
        ASSERT_TRUE(f.has_value());
        EXPECT_EQ(f->kind, FrameKind::busy);
        device.stop();
        EXPECT_FALSE(device.host_attached());
    }
    EXPECT_FALSE(std::filesystem::exists(address.path));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace feel::peripheral::test
