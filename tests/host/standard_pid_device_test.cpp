// A feel device as a plain PID device (PeripheralOptions::standard_pid_only) driven by
// PidDevice, feel's host for any PID device: a relay between them keeps every frame the
// device sent, so the test sees what a standard PID host sees.
//
// Truth: the descriptor the device answers with, read by the independent parser and the
// generic PID mapping (no vendor usage, PID's eleven types), and every frame the device sent
// belonging to that descriptor (a report it declares, at the size it declares). The
// emulated sensations' forces against the device-side rendering are the lockstep test's
// (pid_emulation_test.cpp) and the VM's (tests/linux/check_pid_emulation.cpp).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "emulation/emulated_loop.hpp"
#include "feel/host/pid_device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "feel/protocol/pid_layout.hpp"
#include "pid_relay.hpp"
#include "support/valid_effects.hpp"

namespace feel::host {
namespace {

using transport::Frame;
using transport::FrameKind;

// The device as a plain PID device.
peripheral::PeripheralOptions standard_options() {
    peripheral::PeripheralOptions po;
    po.standard_pid_only = true;
    return po;
}

TEST(StandardPidDevice, IsAPlainPidDeviceToItsHost) {
    test::PidRelay relay(standard_options());
    Result<PidDevice> device = PidDevice::attach(relay.host_end(), "sim:iforce2");
    ASSERT_TRUE(device) << device.status().message;
    const PidCaps& caps = device->capabilities();
    EXPECT_FALSE(caps.feel_device);
    int usable = 0;
    for (const auto& e : caps.effect_types) usable += e.usable ? 1 : 0;
    EXPECT_EQ(usable, 11);
    EXPECT_EQ(caps.max_effects, 32);    // iforce2's, from PID Pool
    EXPECT_EQ(caps.pool_bytes, 16384);
    EXPECT_TRUE(caps.emulation_problem.empty()) << caps.emulation_problem;
    for (EffectType t : {EffectType::axis_wall, EffectType::texture, EffectType::dynamic_recoil})
        EXPECT_NE(caps.emulated_types & effect_type_bit(t), 0u) << effect_type_name(t);

    // A native constant force and an emulated wall, played and freed.
    Result<uint16_t> constant = device->create_effect(test::valid_effect(EffectType::constant));
    ASSERT_TRUE(constant) << constant.status().message;
    EXPECT_FALSE(device->emulated(*constant));
    EXPECT_TRUE(device->start(*constant).ok());
    Result<uint16_t> wall = device->create_effect(emulation::wall_on_x(2000));
    ASSERT_TRUE(wall) << wall.status().message;
    EXPECT_TRUE(device->emulated(*wall));
    EXPECT_TRUE(device->start(*wall).ok());
    EXPECT_EQ(device->status(*wall)->state, runtime::ReportedEffectState::emulated);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const PidEmulationStats stats = device->emulation_stats();
    EXPECT_TRUE(stats.active);
    EXPECT_GT(stats.updates, 10);  // renders on the device's Input reports
    EXPECT_TRUE(device->stop(*constant).ok());
    EXPECT_TRUE(device->free_effect(*constant).ok());
    EXPECT_TRUE(device->free_effect(*wall).ok());
    device->close();

    // Every frame the device sent belongs to the standard descriptor it answered with.
    const std::vector<Frame> frames = relay.received();
    std::vector<uint8_t> descriptor;
    for (const Frame& f : frames)
        if (f.kind == FrameKind::descriptor_reply) descriptor = f.payload;
    ASSERT_FALSE(descriptor.empty());
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(descriptor);
    ASSERT_TRUE(parse.ok()) << parse.error;
    for (const auto& r : parse.descriptor.reports)
        for (const auto& field : r.fields)
            for (uint32_t u : field.usages) EXPECT_LT(u >> 16, 0xFF00u) << "a vendor usage in report " << int(r.id);
    int inputs = 0, replies = 0;
    for (const Frame& f : frames) {
        if (f.kind != FrameKind::input_report && f.kind != FrameKind::feature_reply) continue;
        ASSERT_FALSE(f.payload.empty());
        const auto kind = f.kind == FrameKind::input_report ? protocol::hid::MainItemKind::input
                                                             : protocol::hid::MainItemKind::feature;
        const protocol::hid::DescriptorReport* declared = parse.descriptor.find(kind, f.payload[0]);
        ASSERT_NE(declared, nullptr) << "the device sent report id " << int(f.payload[0])
                                     << ", which its descriptor does not declare";
        EXPECT_EQ(f.payload.size(), 1 + declared->bit_length / 8) << "report id " << int(f.payload[0]);
        (f.kind == FrameKind::input_report ? inputs : replies) += 1;
    }
    EXPECT_GT(inputs, 50);   // Joystick Input at the report rate
    EXPECT_GE(replies, 3);   // PID Pool and two Block Loads
}

}  // namespace
}  // namespace feel::host
