// The doorbell (doorbell.hpp): a ring is never lost, a ring from another thread wakes a
// sleeping waiter, and the in-process connection rings its reader's bell for a frame and
// for a close.
#include "feel/transport/doorbell.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

#include "feel/transport/transport.hpp"
#include "frame_of.hpp"

namespace feel::transport {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// Far longer than any wake-up: a wait that returns well before it was woken, not timed out.
constexpr auto kLong = 20s;

TEST(Doorbell, ARingBeforeTheWaitIsNotLost) {
    Doorbell bell;
    const uint32_t seen = bell.rings();
    bell.ring();
    EXPECT_NE(bell.rings(), seen);
    const auto t0 = Clock::now();
    bell.wait(seen, kLong);  // the count moved on: returns at once
    EXPECT_LT(Clock::now() - t0, kLong / 2);
}

TEST(Doorbell, ARingFromAnotherThreadWakesTheWaiter) {
    Doorbell bell;
    for (int round = 0; round < 20; ++round) {
        const uint32_t seen = bell.rings();
        std::thread ringer([&] {
            std::this_thread::sleep_for(2ms);  // most rounds: the waiter is asleep by now
            bell.ring();
        });
        const auto t0 = Clock::now();
        while (bell.rings() == seen && Clock::now() - t0 < kLong) bell.wait(seen, kLong);
        EXPECT_LT(Clock::now() - t0, kLong / 2) << "round " << round;
        ringer.join();
    }
}

TEST(Doorbell, WithoutARingTheWaitEndsAtItsTimeout) {
    Doorbell bell;
    const uint32_t seen = bell.rings();
    const auto t0 = Clock::now();
    bell.wait(seen, 5ms);
    EXPECT_GE(Clock::now() - t0, 4ms);  // it slept (a spurious early return is allowed, not expected here)
    EXPECT_EQ(bell.rings(), seen);
}

TEST(Doorbell, TheInProcessConnectionRingsItsReaderForAFrameAndForAClose) {
    ConnectionPair pair = in_process_pair("sim:iforce2");
    auto* device = dynamic_cast<BellOnArrival*>(pair.device.get());
    ASSERT_NE(device, nullptr);
    auto bell = std::make_shared<Doorbell>();
    uint32_t seen = bell->rings();
    device->ring_on_arrival(bell);
    EXPECT_NE(bell->rings(), seen) << "registering rings once, for a frame already waiting";

    seen = bell->rings();
    pair.device->send(frame_of(FrameKind::input_report, {1}));  // to the host: not this reader's
    EXPECT_EQ(bell->rings(), seen);
    pair.host->send(frame_of(FrameKind::output_report, {7}));
    EXPECT_NE(bell->rings(), seen);
    const auto f = pair.device->receive(0ms);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(*f, frame_of(FrameKind::output_report, {7}));

    seen = bell->rings();
    pair.host->close();
    EXPECT_NE(bell->rings(), seen);

    device->ring_on_arrival(nullptr);  // no more: the bell may go
    seen = bell->rings();
    pair.device->close();
    EXPECT_EQ(bell->rings(), seen);
}

}  // namespace
}  // namespace feel::transport
