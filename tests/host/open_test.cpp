// Opening devices, their capabilities and EnumEffects, and discovery. The expected
// capabilities come from each profile's data sheet (sim::DeviceProfile), not from the
// runtime that reports them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <unistd.h>

#include "feel/host/device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/transport/transport.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

namespace fs = std::filesystem;

// A fresh directory for sockets, removed at the end.
struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("feel-host-test-" + std::to_string(::getpid()) + "-" +
                                            std::to_string(reinterpret_cast<uintptr_t>(this)));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

peripheral::PeripheralOptions quiet(const std::string& profile) {
    peripheral::PeripheralOptions po;
    po.profile = profile;
    po.runtime.realtime_priority = false;
    po.runtime.lock_memory = false;
    return po;
}

TEST(HostOpen, CapabilitiesMatchEveryProfilesDataSheet) {
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        SCOPED_TRACE(std::string(p.name));
        Result<Device> dev = Device::open("sim:" + std::string(p.name));
        ASSERT_TRUE(dev) << dev.status().message;
        const DeviceCaps& c = dev->capabilities();
        EXPECT_EQ(c.device, p.name);
        EXPECT_EQ(c.description, p.description);  // the whole sentence crosses the wire
        EXPECT_EQ(c.device_class, p.device_class);
        EXPECT_EQ(c.class_name, p.device_class == sim::DeviceClass::iforce1 ? "I-FORCE 1.x" : "I-FORCE 2.0");
        EXPECT_EQ(c.axis_count, p.axis_count);
        for (int i = 0; i < p.axis_count; ++i) {
            EXPECT_EQ(c.axes[i].axis, p.axes[i].axis);
            EXPECT_EQ(c.axes[i].rotary, p.axes[i].kind == sim::AxisKind::rotary);
            // On the wire in µm and mN: equal to a micrometre and a millinewton.
            EXPECT_NEAR(c.axes[i].half_travel, p.axes[i].half_travel, 1e-6);
            EXPECT_NEAR(c.axes[i].max_force, p.axes[i].max_force, 1e-3);
            EXPECT_EQ(c.axes[i].sensor_counts, p.axes[i].sensor_counts);
        }
        EXPECT_EQ(c.button_count, p.button_count);
        EXPECT_EQ(c.hat_count, p.hat_count);
        EXPECT_EQ(c.dead_man_switch, p.dead_man_switch);
        EXPECT_EQ(c.supported_types, p.supported_types);
        EXPECT_EQ(c.effect_slots, p.effect_slots);
        EXPECT_EQ(c.pool_bytes, p.pool_bytes);
        EXPECT_EQ(c.sample_memory, p.sample_memory);
        EXPECT_EQ(c.local_reflexes, p.local_reflexes);
        EXPECT_EQ(c.loop_rate_hz, p.default_loop_rate_hz);
        EXPECT_EQ(c.max_loop_rate_hz, p.max_loop_rate_hz);
        EXPECT_EQ(c.firmware_version, p.firmware_version);
        EXPECT_TRUE(dev->connected());
    }
}

TEST(HostOpen, EnumEffectsListsWhatEachClassPlaysInPrimerOrder) {
    Result<Device> one = Device::open("sim:iforce1");
    Result<Device> two = Device::open("iforce2");  // a bare profile name is sim:PROFILE
    ASSERT_TRUE(one) << one.status().message;
    ASSERT_TRUE(two) << two.status().message;
    // §5.1: a 1.x core plays Conditions and Waves, no Dynamics; 2.0 plays the master set.
    // EnumEffects lists what the host can create: on the 1.x core its Dynamics too, which
    // the host renders (§1.2.c); the device's own set is its capabilities'.
    const auto all1 = one->effects();
    const auto all2 = two->effects();
    EXPECT_EQ(all2.size(), 33u);
    EXPECT_EQ(all1.size(), 33u);
    int device_played = 0;
    for (int i = 0; i < kEffectTypeCount; ++i) device_played += one->capabilities().supports(static_cast<EffectType>(i));
    EXPECT_EQ(device_played, 10 + 15);  // §6.4.a's ten conditions, §6.4.b's waves + constant
    EXPECT_EQ(one->effects(EffectClass::dynamic).size(), 8u);
    EXPECT_EQ(two->effects(EffectClass::dynamic).size(), 8u);
    EXPECT_EQ(two->effects(EffectClass::condition).size(), 10u);
    for (std::size_t i = 0; i < all2.size(); ++i) {
        EXPECT_EQ(all2[i].type, static_cast<EffectType>(i));  // §6.4's order
        EXPECT_EQ(all2[i].effect_class, effect_class(all2[i].type));
    }
    for (const EffectSupport& s : all1) {
        EXPECT_EQ(s.effect_class == EffectClass::dynamic, !one->capabilities().supports(s.type));
    }
}

TEST(HostOpen, BadAddressesAndOptionsAreInvalidParameters) {
    Result<Device> unknown = Device::open("sim:warp-drive");
    ASSERT_FALSE(unknown);
    EXPECT_EQ(unknown.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(unknown.status().message.find("warp-drive"), std::string::npos);
    for (const char* name : {"joystick", "wheel", "3axis", "iforce1", "iforce2"}) {
        EXPECT_NE(unknown.status().message.find(name), std::string::npos) << unknown.status().message;
    }
    Result<Device> no_port = Device::open("tcp:localhost");
    ASSERT_FALSE(no_port);
    EXPECT_EQ(no_port.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(no_port.status().message.find("port"), std::string::npos) << no_port.status().message;

    OpenOptions bad;
    bad.timeout = std::chrono::milliseconds(0);
    Result<Device> zero = Device::open("sim:iforce2", bad);
    ASSERT_FALSE(zero);
    EXPECT_EQ(zero.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(zero.status().message.find("timeout = 0 is out of range (allowed 1..60000)"), std::string::npos)
        << zero.status().message;

    OpenOptions priority;
    priority.io_fifo_priority = 100;
    Result<Device> p = Device::open("sim:iforce2", priority);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(p.status().message.find("io_fifo_priority = 100 is out of range (allowed 1..99"), std::string::npos)
        << p.status().message;

    OpenOptions hand;
    hand.sim_hand = "tentacle";
    Result<Device> h = Device::open("sim:iforce2", hand);
    ASSERT_FALSE(h);
    EXPECT_EQ(h.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(h.status().message.find("tentacle"), std::string::npos) << h.status().message;
}

TEST(HostOpen, NothingListeningIsDisconnected) {
    TempDir dir;
    Result<Device> dev = Device::open("unix:" + (dir.path / "nobody.sock").string());
    ASSERT_FALSE(dev);
    EXPECT_EQ(dev.status().kind, ErrorKind::disconnected);
    EXPECT_NE(dev.status().message.find("nobody.sock"), std::string::npos) << dev.status().message;
}

TEST(HostOpen, OverAUnixSocketOneHostAtATime) {
    TempDir dir;
    const std::string address = "unix:" + (dir.path / "dev.sock").string();
    peripheral::Peripheral device(quiet("iforce1"));
    device.serve(transport::listen(transport::Address::parse(address)));
    Result<Device> first = Device::open(address);
    ASSERT_TRUE(first) << first.status().message;
    EXPECT_EQ(first->capabilities().device, "iforce1");
    EXPECT_EQ(first->address(), address);
    OpenOptions briefly;
    briefly.busy_wait = std::chrono::milliseconds(200);
    Result<Device> second = Device::open(address, briefly);
    ASSERT_FALSE(second);
    EXPECT_EQ(second.status().kind, ErrorKind::disconnected);
    EXPECT_NE(second.status().message.find("in use by another host"), std::string::npos) << second.status().message;
    // The first host is unaffected.
    EXPECT_TRUE(first->set_gain(8000).ok());
    first->close();
    EXPECT_FALSE(first->connected());
    // Once it has gone, the device takes the next host.
    ASSERT_TRUE(wait_until([&] { return !device.host_attached(); }));
    Result<Device> third = Device::open(address);
    EXPECT_TRUE(third) << third.status().message;
}

TEST(HostOpen, ABusyDeviceIsAskedAgainUntilTheOtherHostLeaves) {
    TempDir dir;
    const std::string address = "unix:" + (dir.path / "dev.sock").string();
    peripheral::Peripheral device(quiet("iforce2"));
    device.serve(transport::listen(transport::Address::parse(address)));
    Result<Device> first = Device::open(address);
    ASSERT_TRUE(first) << first.status().message;
    // The first host leaves 300 ms from now; the second, asking meanwhile, gets the device.
    // (The time is taken before the leaving thread starts its 300 ms, so that however long
    // the machine's load delays this thread, the first host leaves 300 ms after it at least.)
    const auto asked = std::chrono::steady_clock::now();
    std::thread leaving([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        first->close();
    });
    Result<Device> second = Device::open(address);
    leaving.join();
    ASSERT_TRUE(second) << second.status().message;
    EXPECT_GE(std::chrono::steady_clock::now() - asked, std::chrono::milliseconds(250));
    // Back to back, with no pause between a close and the next open: never busy.
    second->close();
    for (int i = 0; i < 20; ++i) {
        OpenOptions once;
        once.busy_wait = std::chrono::milliseconds(0);
        Result<Device> next = Device::open(address, once);
        ASSERT_TRUE(next) << "session " << i << ": " << next.status().message;
        next->close();
    }
    OpenOptions bad;
    bad.busy_wait = std::chrono::milliseconds(-1);
    Result<Device> refused = Device::open(address, bad);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(refused.status().message.find("busy_wait"), std::string::npos) << refused.status().message;
}

TEST(HostOpen, OverTcpOnLoopback) {
    peripheral::Peripheral device(quiet("wheel"));
    transport::Address any_port;  // tcp:127.0.0.1 on a free port
    any_port.kind = transport::Address::Kind::tcp;
    any_port.host = "127.0.0.1";
    any_port.port = 0;
    device.serve(transport::listen(any_port));
    const std::string address = device.address().to_string();
    Result<Device> dev = Device::open(address);
    ASSERT_TRUE(dev) << dev.status().message;
    EXPECT_EQ(dev->capabilities().device, "wheel");
    EXPECT_EQ(dev->capabilities().axis_count, 1);
}

TEST(HostEnumerate, InProcessProfilesThenListeningSockets) {
    TempDir dir;
    peripheral::Peripheral device(quiet("3axis"));
    device.serve(transport::listen(transport::Address::parse("unix:" + (dir.path / "a.sock").string())));
    // Not devices: a plain file with the extension, and a socket nobody answers on.
    std::ofstream(dir.path / "stale.sock") << "not a socket";

    EnumerateOptions options;
    options.socket_dirs = {dir.path.string()};
    const std::vector<DeviceInfo> found = enumerate_devices(options);
    const auto profiles = sim::device_profiles();
    ASSERT_EQ(found.size(), profiles.size() + 1);
    for (std::size_t i = 0; i < profiles.size(); ++i) {
        EXPECT_EQ(found[i].address, "sim:" + std::string(profiles[i].name));
        EXPECT_EQ(found[i].device, profiles[i].name);
        EXPECT_TRUE(found[i].in_process);
    }
    const DeviceInfo& socket = found.back();
    EXPECT_EQ(socket.address, "unix:" + (dir.path / "a.sock").string());
    EXPECT_EQ(socket.device, "3axis");
    EXPECT_EQ(socket.class_name, "I-FORCE 2.0");
    EXPECT_FALSE(socket.in_process);

    options.in_process = false;
    options.socket_dirs = {(dir.path / "missing").string()};
    EXPECT_TRUE(enumerate_devices(options).empty());
}

}  // namespace
}  // namespace feel::host::test
