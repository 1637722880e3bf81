// A state round is one tick's state: the device sends Joystick Input, Device Status, then
// the Effect States pages with that status's report number (docs/protocol.md), and the
// host publishes a round only when all three came in that order. The truth is the frames
// the scripted device sends: each round's time, position and force are its own, never a
// status of one tick paired with the joystick of the next.
//
// The case it guards: before the host knows the device's joystick layout (from the
// descriptor it asks for at attach) a joystick does not decode, but the status and the
// states after it do. The host used to keep "the status came" across rounds, so the first
// decoded joystick completed a round with the last tick's status at once, and from then on
// every round went out with its status one round late: a whole report period later in
// every run where a round arrived before the layout (docs/studio.md, "Ninth pass").
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "fake_device.hpp"
#include "feel/host/device.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

using namespace std::chrono_literals;

protocol::JoystickInputReport joystick_at(int16_t x) {
    protocol::JoystickInputReport r;
    r.position[0] = x;
    return r;
}

protocol::DeviceStatusReport status_of_round(uint32_t number, int16_t force) {
    protocol::DeviceStatusReport r;
    r.t_us = uint64_t{number} * 1000;
    r.report_number = number;
    r.force[0] = force;
    r.loop_rate_hz = 1000;
    return r;
}

protocol::EffectStatesReport states_of_round(uint32_t number) {
    protocol::EffectStatesReport r;
    r.report_number = number;
    return r;
}

// Rounds until one with device time `t_us` came (or a second passed).
std::vector<InputState> rounds_through(InputSubscription& sub, int64_t t_us) {
    std::vector<InputState> all;
    const auto give_up = std::chrono::steady_clock::now() + 1s;
    while ((all.empty() || all.back().t_us < t_us) && std::chrono::steady_clock::now() < give_up) {
        Result<InputBatch> b = sub.wait(100ms);
        if (b) all.insert(all.end(), b->reports.begin(), b->reports.end());
    }
    return all;
}

TEST(HostInputRounds, ARoundIsOneTicksJoystickStatusAndStatesInThatOrder) {
    FakeDevice fake;
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    Result<InputSubscription> sub = dev->subscribe_input(64);
    ASSERT_TRUE(sub) << sub.status().message;

    // Round 1 without its joystick (lost, or not decodable yet), then a whole round 2: the
    // round published is round 2's own, as soon as its last page came (no round 3 yet).
    fake.push(status_of_round(1, 111));
    fake.push(states_of_round(1));
    fake.push(joystick_at(200));
    fake.push(status_of_round(2, 222));
    fake.push(states_of_round(2));
    std::vector<InputState> got = rounds_through(*sub, 2000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].t_us, 2000);
    EXPECT_FLOAT_EQ(got[0].position[0], 200.0f);
    EXPECT_FLOAT_EQ(got[0].force[0], 222.0f);

    // Round 3 lost its status, round 4's states are another round's: neither is a round.
    fake.push(joystick_at(300));
    fake.push(states_of_round(3));
    fake.push(joystick_at(400));
    fake.push(status_of_round(4, 444));
    fake.push(states_of_round(5));
    fake.push(joystick_at(600));
    fake.push(status_of_round(6, 666));
    fake.push(states_of_round(6));
    got = rounds_through(*sub, 6000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].t_us, 6000);
    EXPECT_FLOAT_EQ(got[0].position[0], 600.0f);
    EXPECT_FLOAT_EQ(got[0].force[0], 666.0f);
}

// The same on the simulated device, from its attach on, against its own clock: a kinematic
// hand puts the handle on a new target at the tick after the one that took it (the step
// to a tick's sense() is the physics since the previous tick), so the round of the taking
// tick still shows the old position and the next round the new one. A round carrying the
// next tick's joystick would show the new position a tick early.
TEST(HostInputRounds, ASimulatedRoundShowsItsOwnTicksPosition) {
    OpenOptions every_tick;
    every_tick.report_rate_hz = 1000;
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:0", every_tick);
    ASSERT_TRUE(rig.host);
    ASSERT_EQ(rig.host->capabilities().loop_rate_hz, 1000);
    Result<InputSubscription> sub = rig.host->subscribe_input(256);
    ASSERT_TRUE(sub) << sub.status().message;
    ASSERT_TRUE(rig.device->set_hand_target(5000, 0, 0));
    int64_t taken_us = -1;
    for (int i = 0; i < 200 && taken_us < 0; ++i) {
        std::this_thread::sleep_for(5ms);
        taken_us = rig.device->hand_target_taken_us();
    }
    ASSERT_GE(taken_us, 0) << "the loop never took the target";
    const std::vector<InputState> got = rounds_through(*sub, taken_us + 1000);
    const InputState* taking = nullptr;
    const InputState* next = nullptr;  // the next tick's round (a loaded machine may skip a tick)
    for (const InputState& s : got) {
        if (s.t_us == taken_us) taking = &s;
        if (s.t_us > taken_us && next == nullptr) next = &s;
    }
    ASSERT_NE(taking, nullptr) << "no round of the taking tick " << taken_us;
    ASSERT_NE(next, nullptr) << "no round of a tick after it";
    constexpr float kCount = 20000.0f / 4096;  // the sensor's step, position units
    EXPECT_NEAR(taking->position[0], 0.0f, kCount);
    EXPECT_NEAR(next->position[0], 5000.0f, kCount);
}

}  // namespace
}  // namespace feel::host::test
