// PidDevice (feel/host/pid_device.hpp) drives feel's simulated device as a standard PID
// device: every report it sends is read back by feel's own codec (an independent,
// table-driven decoder: the device's view) on a relay between host and device, and must
// say what the host was asked for. The device's answers come from the simulated device's
// profile ("iforce2": 32 effects, 16 KiB, its description says).
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include "feel/host/pid_device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/transport/hidraw.hpp"
#include "pid_relay.hpp"
#include "support/valid_effects.hpp"

namespace feel::host {
namespace {

using Relay = test::PidRelay;

template <class R>
std::vector<R> all_of(const std::vector<protocol::AnyReport>& reports) {
    std::vector<R> out;
    for (const protocol::AnyReport& r : reports)
        if (const auto* x = std::get_if<R>(&r)) out.push_back(*x);
    return out;
}

constexpr EffectType kPidTypes[] = {EffectType::constant, EffectType::ramp,     EffectType::square,
                                    EffectType::sine,     EffectType::triangle, EffectType::saw_up,
                                    EffectType::saw_down, EffectType::spring,   EffectType::damper,
                                    EffectType::inertia,  EffectType::friction};

TEST(PidDevice, ReadsWhatAFeelDeviceSupportsFromItsDescriptorAndPool) {
    Relay relay;
    Result<PidDevice> device = PidDevice::attach(relay.host_end(), "sim:iforce2");
    ASSERT_TRUE(device) << device.status().message;
    const PidCaps& caps = device->capabilities();
    EXPECT_TRUE(caps.feel_device);
    for (EffectType t : kPidTypes) EXPECT_TRUE(caps.supports(t)) << effect_type_name(t);
    EXPECT_FALSE(caps.supports(EffectType::axis_wall));  // feel's, no PID usage
    EXPECT_TRUE(caps.has_pool_report);
    EXPECT_EQ(caps.max_effects, 32);     // iforce2: 32 effects
    EXPECT_EQ(caps.pool_bytes, 16384);   // 16 KiB
    device->close();
}

TEST(PidDevice, PlaysEveryPidTypeWithTheValuesAsked) {
    Relay relay;
    Result<PidDevice> device = PidDevice::attach(relay.host_end(), "sim:iforce2");
    ASSERT_TRUE(device) << device.status().message;
    for (EffectType t : kPidTypes) {
        SCOPED_TRACE(std::string(effect_type_name(t)));
        relay.clear();
        EffectParams p = test::valid_effect(t);
        p.gain = 8000;
        Result<uint16_t> block = device->create_effect(p);
        ASSERT_TRUE(block) << block.status().message;
        ASSERT_TRUE(device->start(*block, 2).ok());
        ASSERT_TRUE(device->stop(*block).ok());
        ASSERT_TRUE(device->free_effect(*block).ok());
        // The in-process pair delivers in order; wait until the relay has them all.
        for (int i = 0; i < 200 && all_of<protocol::BlockFreeReport>(relay.sent()).empty(); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        const std::vector<protocol::AnyReport> sent = relay.sent();
        const auto creates = all_of<protocol::CreateNewEffectReport>(sent);
        ASSERT_EQ(creates.size(), 1u);
        EXPECT_EQ(creates[0].type, t);
        const auto effects = all_of<protocol::SetEffectReport>(sent);
        ASSERT_EQ(effects.size(), 1u);
        EXPECT_EQ(effects[0].block, *block);
        EXPECT_EQ(effects[0].type, t);
        EXPECT_EQ(effects[0].gain, 8000);
        EXPECT_EQ(effects[0].duration_us, p.duration_us == kInfiniteUs ? protocol::kWireInfinite
                                                                      : static_cast<uint32_t>(p.duration_us));
        if (is_periodic(t)) {
            const auto periodic = all_of<protocol::SetPeriodicReport>(sent);
            ASSERT_EQ(periodic.size(), 1u);
            EXPECT_EQ(periodic[0].magnitude, p.periodic.magnitude);
            EXPECT_EQ(periodic[0].period_us, static_cast<uint32_t>(p.periodic.period_us));
        } else if (t == EffectType::constant) {
            const auto constant = all_of<protocol::SetConstantForceReport>(sent);
            ASSERT_EQ(constant.size(), 1u);
            EXPECT_EQ(constant[0].magnitude, p.constant.magnitude);
        } else if (t == EffectType::ramp) {
            const auto ramp = all_of<protocol::SetRampForceReport>(sent);
            ASSERT_EQ(ramp.size(), 1u);
            EXPECT_EQ(ramp[0].start, p.ramp.start);
            EXPECT_EQ(ramp[0].end, p.ramp.end);
        } else {
            const auto conditions = all_of<protocol::SetConditionReport>(sent);
            ASSERT_EQ(conditions.size(), static_cast<std::size_t>(p.axis_count));
            for (std::size_t i = 0; i < conditions.size(); ++i) {
                EXPECT_EQ(conditions[i].axis_index, i);
                EXPECT_EQ(conditions[i].pos_coefficient, p.conditions[i].pos_coefficient);
                EXPECT_EQ(conditions[i].center_offset, p.conditions[i].offset);
            }
        }
        const auto ops = all_of<protocol::EffectOperationReport>(sent);
        ASSERT_EQ(ops.size(), 2u);
        EXPECT_EQ(ops[0].operation, protocol::EffectOperation::start);
        EXPECT_EQ(ops[0].loop_count, 2);
        EXPECT_EQ(ops[1].operation, protocol::EffectOperation::stop);
    }
    device->close();
}

TEST(PidDevice, RefusesWhatTheDeviceCannotPlayBeforeSendingAnything) {
    Relay relay;
    Result<PidDevice> device = PidDevice::attach(relay.host_end(), "sim:iforce2");
    ASSERT_TRUE(device) << device.status().message;
    relay.clear();
    EffectParams bad = test::valid_effect(EffectType::constant);
    bad.constant.magnitude = 20000;
    Result<uint16_t> refused = device->create_effect(bad);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(refused.status().message.find("constant.magnitude"), std::string::npos) << refused.status().message;
    EXPECT_FALSE(device->start(7).ok());  // no effect there
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_TRUE(relay.sent().empty());
    device->close();
}

// --- hidraw nodes from a fake sysfs -----------------------------------------------------

class FakeSysfs : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = std::filesystem::temp_directory_path() / ("feel-sysfs-" + std::to_string(::getpid()));
        std::filesystem::remove_all(root_);
    }
    void TearDown() override { std::filesystem::remove_all(root_); }
    void add(const std::string& node, const std::string& uevent, const std::vector<uint8_t>& descriptor) {
        const auto dir = root_ / "sys/class/hidraw" / node / "device";
        std::filesystem::create_directories(dir);
        std::ofstream(dir / "uevent") << uevent;
        std::ofstream out(dir / "report_descriptor", std::ios::binary);
        out.write(reinterpret_cast<const char*>(descriptor.data()), static_cast<std::streamsize>(descriptor.size()));
    }
    transport::HidrawRoots roots() const { return {(root_ / "sys").string(), (root_ / "dev").string()}; }
    std::filesystem::path root_;
};

std::vector<uint8_t> load_ff2() {
    std::ifstream in(std::string(FEEL_SOURCE_DIR) + "/tests/protocol/pid_descriptors/sidewinder_ff2.bin", std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(FakeSysfs, ListsOnlyPidDevicesWithTheirAddresses) {
    const std::vector<uint8_t> keyboard = {0x05, 0x01, 0x09, 0x06, 0xA1, 0x01, 0x05, 0x07, 0x19, 0xE0, 0x29, 0xE7,
                                           0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x08, 0x81, 0x02, 0xC0};
    add("hidraw0", "HID_ID=0003:0000046D:0000C31C\nHID_NAME=Some Keyboard\nHID_UNIQ=\n", keyboard);
    add("hidraw2", "HID_ID=0003:0000045E:0000001B\nHID_NAME=SideWinder Force Feedback 2 Joystick\nHID_UNIQ=\n", load_ff2());
    const std::vector<uint8_t> feel(protocol::report_descriptor().begin(), protocol::report_descriptor().end());
    add("hidraw10", "HID_ID=0003:00001D6B:00000104\nHID_NAME=feel iforce2\nHID_UNIQ=0001\n", feel);

    const std::vector<PidDeviceInfo> devices = enumerate_pid_devices(roots());
    ASSERT_EQ(devices.size(), 2u);
    EXPECT_EQ(devices[0].address, "hidraw:" + (root_ / "dev/hidraw2").string());
    EXPECT_EQ(devices[0].usb_address, "usb:045e:001b");
    EXPECT_EQ(devices[0].name, "SideWinder Force Feedback 2 Joystick");
    EXPECT_FALSE(devices[0].feel_device);
    EXPECT_TRUE(devices[0].problem.empty()) << devices[0].problem;
    EXPECT_EQ(devices[1].usb_address, "usb:1d6b:0104:0001");
    EXPECT_TRUE(devices[1].feel_device);

    transport::Address usb = transport::Address::parse("usb:045e:001b");
    EXPECT_EQ(transport::find_usb_node(usb, roots()), (root_ / "dev/hidraw2").string());
    usb = transport::Address::parse("usb:1d6b:0104:0002");  // another serial
    try {
        (void)transport::find_usb_node(usb, roots());
        ADD_FAILURE() << "found a device with another serial";
    } catch (const transport::TransportError& e) {
        EXPECT_NE(std::string(e.what()).find("1d6b:0104:0001"), std::string::npos) << e.what();
    }
}

TEST(PidDeviceOpen, SaysWhatIsWrongWithTheNode) {
    Result<PidDevice> absent = PidDevice::open("hidraw:/dev/feel-no-such-hidraw");
    ASSERT_FALSE(absent);
    EXPECT_EQ(absent.status().kind, ErrorKind::disconnected);
    EXPECT_NE(absent.status().message.find("no such device"), std::string::npos) << absent.status().message;
    Result<PidDevice> not_hidraw = PidDevice::open("hidraw:/dev/null");
    ASSERT_FALSE(not_hidraw);
    EXPECT_NE(not_hidraw.status().message.find("not a hidraw device"), std::string::npos) << not_hidraw.status().message;
    Result<PidDevice> bad = PidDevice::open("usb:45e:1b");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(bad.status().message.find("4 hex digits"), std::string::npos) << bad.status().message;
    EXPECT_NE(transport::hidraw_udev_rule(0x045e, 0x001b).find("ATTRS{idVendor}==\"045e\""), std::string::npos);
}

}  // namespace
}  // namespace feel::host
