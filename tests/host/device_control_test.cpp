// Device commands (DirectInput's SendForceFeedbackCommand, §7) and losing the device.
#include <gtest/gtest.h>

#include <cmath>

#include "feel/host/device.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

EffectParams push_x(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = kInfiniteUs;
    p.constant.magnitude = magnitude;
    return p;
}

bool force_near(Device& dev, float expected, float tolerance) {
    return wait_until([&] { return std::fabs(dev.input().force[0] - expected) <= tolerance; });
}

TEST(HostDeviceControl, PauseResumeActuatorsAndStopAll) {
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:0", fast_reports());
    Device& dev = *rig.host;
    ASSERT_TRUE(wait_for_full_force(dev));
    Result<Effect> e = dev.create_effect(push_x(3000));
    ASSERT_TRUE(e) << e.status().message;
    ASSERT_TRUE(e->start().ok());
    EXPECT_TRUE(force_near(dev, 3000, 2));

    ASSERT_TRUE(dev.command(runtime::DeviceControl::pause).ok());
    EXPECT_TRUE(wait_until([&] { return dev.input().paused; }));
    EXPECT_TRUE(force_near(dev, 0, 0.5f));
    EXPECT_EQ(e->status()->state, runtime::ReportedEffectState::playing);  // paused, still started
    ASSERT_TRUE(dev.command(runtime::DeviceControl::resume).ok());
    EXPECT_TRUE(force_near(dev, 3000, 2));

    ASSERT_TRUE(dev.command(runtime::DeviceControl::actuators_off).ok());
    EXPECT_TRUE(wait_until([&] { return !dev.input().actuators_enabled; }));
    EXPECT_TRUE(force_near(dev, 0, 0.5f));
    ASSERT_TRUE(dev.command(runtime::DeviceControl::actuators_on).ok());
    EXPECT_TRUE(force_near(dev, 3000, 2));  // after the fade-in

    ASSERT_TRUE(dev.command(runtime::DeviceControl::stop_all).ok());
    const EffectStatusInfo st = e->status().value();
    EXPECT_EQ(st.state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(st.last_end, PlayEnd::stopped);
    EXPECT_TRUE(e->downloaded());  // stop-all keeps effects resident
    EXPECT_TRUE(force_near(dev, 0, 0.5f));
}

TEST(HostDeviceControl, ResetFreesEffectsThatThenDownloadAgain) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> e = dev.create_effect(push_x(1000));
    ASSERT_TRUE(e);
    ASSERT_TRUE(dev.set_gain(4000).ok());
    ASSERT_TRUE(dev.command(runtime::DeviceControl::reset).ok());
    EXPECT_FALSE(e->downloaded());
    EXPECT_TRUE(e->valid());
    const Status st = e->start();
    EXPECT_EQ(st.kind, ErrorKind::invalid_handle);
    EXPECT_NE(st.message.find("reset"), std::string::npos) << st.message;
    EXPECT_EQ(dev.pool()->free_effects, dev.capabilities().effect_slots);
    EXPECT_TRUE(wait_until([&] { return dev.input().gain == kFullScale; }));  // DISFFC_RESET: gain 10000
    ASSERT_TRUE(e->download().ok());
    EXPECT_TRUE(e->start().ok());
    EXPECT_EQ(e->status()->state, runtime::ReportedEffectState::playing);
}

TEST(HostDeviceControl, TheDeviceGoingAwayDisconnectsEverything) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> e = dev.create_effect(push_x(1000));
    ASSERT_TRUE(e);
    ASSERT_TRUE(dev.connected());
    rig.device.reset();  // the peripheral is gone: its end of the cable closes
    ASSERT_TRUE(wait_until([&] { return !dev.connected(); }));
    EXPECT_EQ(e->start().kind, ErrorKind::disconnected);
    EXPECT_EQ(e->status().status().kind, ErrorKind::disconnected);
    const Result<Effect> more = dev.create_effect(push_x(1));
    EXPECT_EQ(more.status().kind, ErrorKind::disconnected);
    EXPECT_EQ(dev.pool().status().kind, ErrorKind::disconnected);
    EXPECT_EQ(dev.wait_input(50ms).status().kind, ErrorKind::disconnected);
    dev.close();  // harmless
    dev.close();
}

TEST(HostDeviceControl, InputStateComesWithoutARoundTrip) {
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:-2500,4000");
    Device& dev = *rig.host;
    Result<InputState> in = dev.wait_input(1000ms);
    ASSERT_TRUE(in) << in.status().message;
    in = dev.wait_input(1000ms);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->axis_count, 2);
    EXPECT_NEAR(in->position[0], -2500, 5);  // the hand holds it there, to a sensor step
    EXPECT_NEAR(in->position[1], 4000, 5);
    EXPECT_EQ(in->loop_rate_hz, 1000);
    EXPECT_GT(in->reports_received, 0u);
    EXPECT_GT(in->t_us, 0);
    rig.set_buttons(0b1010);  // buttons 2 and 4
    EXPECT_TRUE(wait_until([&] { return dev.input().buttons == 0b1010u; }));
    // A zero wait times out unless a report lands in the instant it waits (reports come
    // every few ms; under ThreadSanitizer one did, in the first try): some try must time out.
    Result<InputState> none = dev.wait_input(std::chrono::milliseconds(0));
    for (int tries = 1; none && tries < 100; ++tries) none = dev.wait_input(std::chrono::milliseconds(0));
    EXPECT_FALSE(none);
    EXPECT_EQ(none.status().kind, ErrorKind::timeout);
}

}  // namespace
}  // namespace feel::host::test
