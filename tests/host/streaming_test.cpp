// Force streaming (§2.4) and the dynamics' interim reports (§5.2) through the host API.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>
#include <vector>

#include "feel/host/device.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

TEST(HostStreaming, StreamedForceReachesTheMotorsAndIsHeld) {
    OpenOptions options;
    options.report_rate_hz = 1000;
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:0", options);
    Device& dev = *rig.host;
    ASSERT_TRUE(wait_for_full_force(dev));
    const int32_t sample[2] = {3000, -2000};
    for (int i = 0; i < 150; ++i) {  // 150 ms at about 1 kHz
        ASSERT_TRUE(dev.stream_force(sample).ok());
        std::this_thread::sleep_for(1ms);
    }
    EXPECT_TRUE(wait_until([&] {
        const InputState in = dev.input();
        return std::fabs(in.force[0] - 3000) <= 2 && std::fabs(in.force[1] + 2000) <= 2;
    }));
    // The stream stopped: the device holds its last value (§2.4).
    std::this_thread::sleep_for(200ms);
    EXPECT_NEAR(dev.input().force[0], 3000, 2);
    EXPECT_NEAR(dev.input().force[1], -2000, 2);
}

TEST(HostStreaming, StreamedSamplesAreCheckedFirst) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    const int32_t three[3] = {0, 0, 0};
    const Status count = dev.stream_force(three);
    EXPECT_EQ(count.kind, ErrorKind::invalid_parameter);
    EXPECT_NE(count.message.find("3 forces for a 2-axis device"), std::string::npos) << count.message;
    const int32_t big[2] = {0, 12000};
    EXPECT_EQ(dev.stream_force(big).message,
              "stream_force: force[1] = 12000 is out of range (allowed -10000..10000)");
}

TEST(HostStreaming, InterimReportsArriveAtTheDevicesRate) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    EffectParams p;
    p.type = EffectType::dynamic_control_law;
    p.duration_us = kInfiniteUs;
    p.dynamic.interim_reporting = true;
    p.dynamic.control_law[0] = ControlLawBlock{5000, 5000, 5000, 2000, 0, 2000, 0, 0, 0, 0};
    Result<Effect> e = dev.create_effect(p);
    ASSERT_TRUE(e) << e.status().message;

    std::mutex mu;
    std::vector<DynamicEvent> mine;
    std::atomic<int> all{0};
    Subscription one = e->subscribe([&](const DynamicEvent& ev) {
        std::lock_guard lock(mu);
        mine.push_back(ev);
    });
    Subscription every = dev.subscribe([&](const DynamicEvent&) { ++all; });
    ASSERT_TRUE(one.active());
    ASSERT_TRUE(e->start().ok());
    std::this_thread::sleep_for(700ms);
    ASSERT_TRUE(e->stop().ok());
    one.reset();
    EXPECT_FALSE(one.active());

    std::lock_guard lock(mu);
    ASSERT_GE(mine.size(), 20u);
    int interim = 0;
    for (const DynamicEvent& ev : mine) {
        if (ev.kind != DynamicReport::Kind::interim) continue;
        ++interim;
        EXPECT_EQ(ev.axis_count, 1);
        EXPECT_TRUE(std::isfinite(ev.position[0]));
    }
    // The rate over device time: (n - 1) reports between the first and the last.
    const double span_s = static_cast<double>(mine.back().t_us - mine.front().t_us) / 1e6;
    const double rate = static_cast<double>(mine.size() - 1) / span_s;
    const double expected = 60.0;  // §5.2: the engine "reports data back to the host at 60hz"
    EXPECT_NEAR(rate, expected, 0.1 * expected);
    EXPECT_GE(all.load(), interim);     // the device-wide subscriber saw them too
}

}  // namespace
}  // namespace feel::host::test
