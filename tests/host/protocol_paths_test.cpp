// The host's handling of what a device answers, against a scripted device: refusals become
// the right ErrorKind with the device's field and range, a failed create frees its block,
// silence is a timeout, `busy` and a vanished device are disconnections, and a device
// with another report descriptor is refused as a protocol error.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "fake_device.hpp"
#include "feel/host/device.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

using namespace std::chrono_literals;

EffectParams sine(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::sine;
    p.duration_us = 1'000'000;
    p.periodic.magnitude = magnitude;
    p.periodic.period_us = 20'000;
    return p;
}

protocol::CommandAnswer refusal(ErrorCode code, const char* field, int64_t value, int64_t lo, int64_t hi) {
    protocol::CommandAnswer s;
    s.code = code;
    std::strncpy(s.field, field, sizeof s.field - 1);
    s.has_range = true;
    s.value = value;
    s.allowed_min = lo;
    s.allowed_max = hi;
    return s;
}

protocol::CommandAnswer refusal_rule(ErrorCode code, const char* field, const char* rule) {
    protocol::CommandAnswer s;
    s.code = code;
    std::strncpy(s.field, field, sizeof s.field - 1);
    std::strncpy(s.rule, rule, sizeof s.rule - 1);
    return s;
}

TEST(HostProtocolPaths, ADeviceOfAnotherVendorRevisionIsRefusedNamingBoth) {
    // docs/protocol.md, "Versioning": the vendor layouts hold within one revision only.
    for (const int revision : {1, 3}) {
        FakeDevice fake;
        fake.device_info.vendor_revision = static_cast<uint8_t>(revision);
        Result<Device> dev = Device::attach(fake.host_end(), "fake");
        ASSERT_FALSE(dev);
        EXPECT_EQ(dev.status().kind, ErrorKind::protocol);
        const std::string& m = dev.status().message;
        EXPECT_NE(m.find("feel vendor revision " + std::to_string(revision)), std::string::npos) << m;
        EXPECT_NE(m.find("this host speaks revision 2"), std::string::npos) << m;
    }
}

TEST(HostProtocolPaths, OpensAFakeDeviceAndReadsItsCapabilities) {
    FakeDevice fake;
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    const DeviceCaps& caps = dev->capabilities();
    EXPECT_EQ(caps.device, "fake");
    EXPECT_EQ(caps.axis_count, 2);
    EXPECT_DOUBLE_EQ(caps.axes[0].half_travel, 0.05);  // 50000 µm
    EXPECT_DOUBLE_EQ(caps.axes[0].max_force, 4.45);    // 4450 mN
    EXPECT_EQ(caps.effect_slots, 4);
    EXPECT_EQ(caps.class_name, "I-FORCE 2.0");
    EXPECT_EQ(dev->address(), "fake");
}

TEST(HostProtocolPaths, DeviceSideRangeRefusalNamesTheFieldAndRangeAndFreesTheBlock) {
    FakeDevice fake;
    fake.block_load.block = 3;
    // The device's engine allows less than the host's validator: its verdict is final.
    fake.answer = [](const protocol::AnyReport& r) -> std::optional<protocol::CommandAnswer> {
        if (std::holds_alternative<protocol::SetEffectReport>(r)) {
            return refusal(ErrorCode::invalid_parameter, "periodic.magnitude", 9000, 0, 8000);
        }
        return std::nullopt;
    };
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    Result<Effect> e = dev->create_effect(sine(9000));
    ASSERT_FALSE(e);
    EXPECT_EQ(e.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(e.status().message.find("periodic.magnitude = 9000 is out of range (allowed 0..8000)"),
              std::string::npos)
        << e.status().message;
    EXPECT_STREQ(e.status().detail.field, "periodic.magnitude");
    EXPECT_EQ(e.status().detail.allowed.max, 8000);
    // The failed create gave its block back.
    ASSERT_TRUE(wait_until([&] { return fake.count<protocol::BlockFreeReport>() == 1; }));
    for (const auto& r : fake.received()) {
        if (const auto* f = std::get_if<protocol::BlockFreeReport>(&r)) {
            EXPECT_EQ(f->block, 3);
        }
    }
}

TEST(HostProtocolPaths, EachDeviceErrorCodeMapsToItsKind) {
    struct Case {
        ErrorCode code;
        ErrorKind kind;
    };
    for (const Case c : {Case{ErrorCode::device_full, ErrorKind::device_full},
                         Case{ErrorCode::not_supported, ErrorKind::not_supported},
                         Case{ErrorCode::invalid_handle, ErrorKind::invalid_handle},
                         Case{ErrorCode::invalid_parameter, ErrorKind::invalid_parameter}}) {
        FakeDevice fake;
        fake.answer = [c](const protocol::AnyReport& r) -> std::optional<protocol::CommandAnswer> {
            if (std::holds_alternative<protocol::SetPeriodicReport>(r)) {
                return refusal_rule(c.code, "periodic", "refused by the test device");
            }
            return std::nullopt;
        };
        Result<Device> dev = Device::attach(fake.host_end(), "fake");
        ASSERT_TRUE(dev) << dev.status().message;
        Result<Effect> e = dev->create_effect(sine(1000));
        ASSERT_FALSE(e);
        EXPECT_EQ(e.status().kind, c.kind) << e.status().message;
        EXPECT_NE(e.status().message.find("periodic: refused by the test device"), std::string::npos)
            << e.status().message;
        EXPECT_EQ(e.status().message.rfind("create sine", 0), 0u) << e.status().message;
    }
}

TEST(HostProtocolPaths, BlockLoadFullIsDeviceFull) {
    FakeDevice fake;
    fake.block_load = {0, protocol::BlockLoadStatus::full, 12};
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    Result<Effect> e = dev->create_effect(sine(1000));
    ASSERT_FALSE(e);
    EXPECT_EQ(e.status().kind, ErrorKind::device_full);
    EXPECT_NE(e.status().message.find("12 bytes"), std::string::npos) << e.status().message;
    // Nothing was allocated, so nothing is freed and no block was sent.
    EXPECT_EQ(fake.count<protocol::BlockFreeReport>(), 0);
    EXPECT_EQ(fake.count<protocol::SetPeriodicReport>(), 0);
}

TEST(HostProtocolPaths, ASilentDeviceIsATimeout) {
    FakeDevice fake;
    fake.silent = true;
    OpenOptions options;
    options.timeout = 150ms;
    const auto t0 = std::chrono::steady_clock::now();
    Result<Device> dev = Device::attach(fake.host_end(), "fake", options);
    const auto waited = std::chrono::steady_clock::now() - t0;
    ASSERT_FALSE(dev);
    EXPECT_EQ(dev.status().kind, ErrorKind::timeout);
    EXPECT_NE(dev.status().message.find("150 ms"), std::string::npos) << dev.status().message;
    EXPECT_GE(waited, 150ms);
    EXPECT_LT(waited, 2000ms);
}

TEST(HostProtocolPaths, NobodyAtTheOtherEndOfARawPairIsATimeout) {
    transport::ConnectionPair pair = transport::in_process_pair("raw");
    OpenOptions options;
    options.timeout = 100ms;
    Result<Device> dev = Device::attach(std::move(pair.host), "raw", options);
    ASSERT_FALSE(dev);
    EXPECT_EQ(dev.status().kind, ErrorKind::timeout);
    EXPECT_EQ(dev.status().message, "open raw: get the report descriptor: the device at raw did not answer within 100 ms");
}

TEST(HostProtocolPaths, ADeviceThatStopsAnsweringTimesOutButStaysConnected) {
    FakeDevice fake;
    OpenOptions options;
    options.timeout = 100ms;
    Result<Device> dev = Device::attach(fake.host_end(), "fake", options);
    ASSERT_TRUE(dev) << dev.status().message;
    fake.silent = true;
    Result<Effect> e = dev->create_effect(sine(1000));
    ASSERT_FALSE(e);
    EXPECT_EQ(e.status().kind, ErrorKind::timeout);
    EXPECT_NE(e.status().message.find("did not answer within 100 ms"), std::string::npos) << e.status().message;
    EXPECT_TRUE(dev->connected());
    EXPECT_EQ(dev->set_gain(100).kind, ErrorKind::timeout);
}

TEST(HostProtocolPaths, ABusyDeviceIsDisconnectedNamingTheOtherHost) {
    FakeDevice fake;
    fake.busy = true;
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_FALSE(dev);
    EXPECT_EQ(dev.status().kind, ErrorKind::disconnected);
    EXPECT_NE(dev.status().message.find("in use by another host"), std::string::npos) << dev.status().message;
}

TEST(HostProtocolPaths, ADeviceWithAnotherDescriptorIsAProtocolError) {
    FakeDevice fake;
    const auto d = protocol::report_descriptor();
    // Drop the last quarter: reports go missing or change size.
    fake.descriptor = std::vector<uint8_t>(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() * 3 / 4));
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_FALSE(dev);
    EXPECT_EQ(dev.status().kind, ErrorKind::protocol);
    EXPECT_NE(dev.status().message.find("another version of the protocol"), std::string::npos)
        << dev.status().message;
}

TEST(HostProtocolPaths, ADeviceThatVanishesMidCreateIsDisconnected) {
    FakeDevice fake;
    fake.close_on_set_effect = true;
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    Result<Effect> e = dev->create_effect(sine(1000));
    ASSERT_FALSE(e);
    EXPECT_EQ(e.status().kind, ErrorKind::disconnected) << e.status().message;
    EXPECT_FALSE(dev->connected());
    EXPECT_EQ(dev->set_gain(5000).kind, ErrorKind::disconnected);
    EXPECT_EQ(dev->wait_input(50ms).status().kind, ErrorKind::disconnected);
}

TEST(HostProtocolPaths, AnIdleHostSendsKeepAlivesWellInsideTheWatchdog) {
    FakeDevice fake;
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    // 100 ms of silence per keep-alive: 3 or more in 450 ms; the device's watchdog (1 s,
    // SafetyConfig::host_timeout_us) never sees a gap near its limit.
    std::this_thread::sleep_for(450ms);
    EXPECT_GE(fake.count<protocol::KeepAliveReport>(), 3);
    EXPECT_LE(fake.count<protocol::KeepAliveReport>(), 6);
}

}  // namespace
}  // namespace feel::host::test
