// A dynamic's report with more than four axes comes in two Dynamic Reports (docs/protocol.md,
// "Which pipe": each input report fits one 64-byte interrupt packet): the host joins them
// into one event, and a later part without its first is never delivered.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "fake_device.hpp"
#include "feel/host/device.hpp"

namespace feel::host::test {
namespace {

using namespace std::chrono_literals;

protocol::DynamicReportReport part(uint8_t first_axis, uint64_t t_us) {
    protocol::DynamicReportReport r;
    r.block = 1;
    r.final_report = 1;
    r.t_us = t_us;
    r.axis_count = 6;
    r.first_axis = first_axis;
    for (int slot = 0; slot < protocol::kDynamicAxesPerReport; ++slot) {
        const int axis = first_axis + slot;
        r.position_centi[slot] = (axis + 1) * 100;          // axis a at a + 1 position units
        r.velocity_centi[slot] = -(axis + 1) * 100;
        r.handle_velocity_centi[slot] = (axis + 1) * 1000;  // 10 (a + 1) units/s
    }
    return r;
}

TEST(HostDynamicParts, TwoPartsMakeOneEventWithSixAxes) {
    FakeDevice fake;
    Result<Device> dev = Device::attach(fake.host_end(), "fake");
    ASSERT_TRUE(dev) << dev.status().message;
    std::mutex mu;
    std::vector<DynamicEvent> events;
    Subscription every = dev->subscribe([&](const DynamicEvent& ev) {
        std::lock_guard lock(mu);
        events.push_back(ev);
    });
    fake.push(part(4, 5000));  // a later part without its first: dropped
    fake.push(part(0, 7000));
    fake.push(part(4, 7000));
    for (int i = 0; i < 200; ++i) {
        {
            std::lock_guard lock(mu);
            if (!events.empty()) break;
        }
        std::this_thread::sleep_for(10ms);
    }
    std::this_thread::sleep_for(50ms);
    std::lock_guard lock(mu);
    ASSERT_EQ(events.size(), 1u);
    const DynamicEvent& ev = events[0];
    EXPECT_EQ(ev.t_us, 7000);
    EXPECT_EQ(ev.kind, DynamicReport::Kind::final);
    ASSERT_EQ(ev.axis_count, 6);
    for (int a = 0; a < 6; ++a) {
        EXPECT_FLOAT_EQ(ev.position[a], static_cast<float>(a + 1)) << a;
        EXPECT_FLOAT_EQ(ev.velocity[a], -static_cast<float>(a + 1)) << a;
        EXPECT_FLOAT_EQ(ev.handle_velocity[a], 10.0f * static_cast<float>(a + 1)) << a;
    }
}

}  // namespace
}  // namespace feel::host::test
