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

// The device's own losses of interim reports over a window: a late tick of its loop (an
// overrun that skipped k ticks) posts one report for the periods it spanned and restarts the
// schedule from there (engine_impl.hpp, report_dynamic): at most (k + 1) / P reports lost,
// plus less than one period of phase, P being the period in ticks; the engine's report store
// and the link drop and count.
double interim_losses(const peripheral::PeripheralStats& before, const peripheral::PeripheralStats& after,
                      double period_ticks) {
    const auto skipped = static_cast<double>(after.runtime.loop.missed_ticks - before.runtime.loop.missed_ticks);
    const auto overruns = static_cast<double>(after.runtime.loop.overruns - before.runtime.loop.overruns);
    const auto dropped = static_cast<double>(after.runtime.pipeline.dropped_dynamic_reports -
                                             before.runtime.pipeline.dropped_dynamic_reports) +
                         static_cast<double>(after.reports_dropped - before.reports_dropped);
    return (skipped + overruns) / period_ticks + overruns + dropped;
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
    const peripheral::PeripheralStats before = rig.device->stats();
    ASSERT_TRUE(e->start().ok());
    // 42 reports, 0.7 s of the device's time (longer when the machine's load slows it).
    constexpr std::size_t kReports = 42;
    EXPECT_TRUE(wait_until(
        [&] {
            std::lock_guard lock(mu);
            return mine.size() >= kReports;
        },
        10s));
    ASSERT_TRUE(e->stop().ok());
    one.reset();
    EXPECT_FALSE(one.active());
    const peripheral::PeripheralStats after = rig.device->stats();

    std::lock_guard lock(mu);
    ASSERT_GE(mine.size(), kReports);
    int interim = 0;
    for (const DynamicEvent& ev : mine) {
        if (ev.kind != DynamicReport::Kind::interim) continue;
        ++interim;
        EXPECT_EQ(ev.axis_count, 1);
        EXPECT_TRUE(std::isfinite(ev.position[0]));
    }
    // The rate over device time (§5.2: the engine "reports data back to the host at 60hz").
    // Report k is due k periods after the first and goes out at the first 1 ms tick at or
    // after that, so the n reports between the first and the last span (n - 1) periods
    // within a tick (1/16.7 of a period): never more reports than that, and fewer only by
    // what the device itself lost.
    const double period_us = 1e6 / 60.0;
    const double periods = static_cast<double>(mine.back().t_us - mine.front().t_us) / period_us;
    const double arrived = static_cast<double>(mine.size() - 1);
    const double rate = arrived / periods * 60.0;
    EXPECT_LE(arrived, periods + 0.1) << "faster than 60 Hz: " << rate << " Hz";
    const double lost = interim_losses(before, after, period_us / 1000.0);
    EXPECT_LE(periods - arrived, lost + 0.1) << rate << " Hz: " << periods - arrived
                                              << " reports missing, the device lost at most " << lost;
    EXPECT_GE(all.load(), interim);     // the device-wide subscriber saw them too
}

}  // namespace
}  // namespace feel::host::test
