// Per-report input subscriptions (Device::subscribe_input): every state round in order,
// a bounded queue that drops the oldest and says how many, thread safety, disconnection.
//
// The truth is the device's own clock: at a report rate of 500 Hz the device sends a round
// every 2000 µs of its time, so the rounds between two reports are (t1 - t0) / 2000, less
// what the device itself could not send (the ticks its loop skipped and the reports it
// dropped, which it counts: Peripheral::stats()).
#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "feel/host/device.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

constexpr int32_t kRateHz = 500;
constexpr int64_t kPeriodUs = 1'000'000 / kRateHz;

OpenOptions reports_at_500() {
    OpenOptions o;
    o.report_rate_hz = kRateHz;
    return o;
}

// What the device owns up to losing (its own counters, read before and after a window):
// a tick its loop skipped (late, it skips every tick it missed, and a report due in one),
// a round its pipeline could not post, a report the link dropped. Each costs at most one
// round.
int64_t device_losses(const peripheral::PeripheralStats& before, const peripheral::PeripheralStats& after) {
    return (after.runtime.loop.missed_ticks - before.runtime.loop.missed_ticks) +
           (after.runtime.pipeline.dropped_state_reports - before.runtime.pipeline.dropped_state_reports) +
           static_cast<int64_t>(after.reports_dropped - before.reports_dropped);
}

// The rounds the device's clock says came from `first` to `last`, both included.
int64_t rounds_between(const InputState& first, const InputState& last) {
    return std::llround(static_cast<double>(last.t_us - first.t_us) / kPeriodUs) + 1;
}

TEST(HostInputSubscription, EveryRoundArrivesInOrder) {
    SimRig rig = SimRig::make("iforce2", "firm", "hold:0", reports_at_500());
    Device& dev = *rig.host;
    const peripheral::PeripheralStats before = rig.device->stats();
    Result<InputSubscription> sub = dev.subscribe_input(1024);
    ASSERT_TRUE(sub) << sub.status().message;
    EXPECT_EQ(sub->capacity(), 1024u);
    std::vector<InputState> all;
    while (all.empty() || all.back().t_us - all.front().t_us < 400'000) {
        Result<InputBatch> b = sub->wait(1000ms);
        ASSERT_TRUE(b) << b.status().message;
        EXPECT_FALSE(b->overflowed()) << b->dropped;
        all.insert(all.end(), b->reports.begin(), b->reports.end());
    }
    const peripheral::PeripheralStats after = rig.device->stats();
    // In order, and every round the device sent is there: rounds missing from the device's
    // clock only as many as the device itself skipped or dropped.
    int64_t missing = 0;
    for (size_t i = 1; i < all.size(); ++i) {
        ASSERT_GT(all[i].t_us, all[i - 1].t_us) << "round " << i << " is not newer than the one before";
        missing += rounds_between(all[i - 1], all[i]) - 2;
    }
    EXPECT_LE(missing, device_losses(before, after)) << all.size() << " rounds";
    EXPECT_EQ(sub->dropped_total(), 0u);
}

TEST(HostInputSubscription, AFullQueueDropsTheOldestAndCountsThem) {
    SimRig rig = SimRig::make("iforce2", "firm", "hold:0", reports_at_500());
    Device& dev = *rig.host;
    // The device's losses are counted over a window that holds every round from t0 on.
    const peripheral::PeripheralStats before = rig.device->stats();
    Result<InputSubscription> sub = dev.subscribe_input(8);
    ASSERT_TRUE(sub);
    Result<InputBatch> first = sub->wait(1000ms);
    ASSERT_TRUE(first) << first.status().message;
    const InputState t0 = first->reports.back();
    // Not read for a while: the queue, which holds 8, fills and drops the oldest; until it
    // has dropped 20 (28 rounds after the first batch, 56 ms of the device's time, longer
    // when the machine's load slows the device down).
    const auto until = std::chrono::steady_clock::now() + 10s;
    while (sub->dropped_total() < first->dropped + 20 && std::chrono::steady_clock::now() < until) {
        std::this_thread::sleep_for(10ms);
    }
    const InputBatch b = sub->take();
    const peripheral::PeripheralStats after = rig.device->stats();
    ASSERT_EQ(b.reports.size(), 8u);
    EXPECT_TRUE(b.overflowed());
    EXPECT_GE(b.dropped, 20u);
    for (size_t i = 1; i < b.reports.size(); ++i) EXPECT_GT(b.reports[i].t_us, b.reports[i - 1].t_us);
    // The newest were kept: the rounds after t0 are the dropped ones and the 8 kept.
    const int64_t after_t0 = rounds_between(t0, b.reports.back()) - 1;
    const int64_t accounted = static_cast<int64_t>(b.dropped) + 8;
    EXPECT_LE(accounted, after_t0);
    EXPECT_GE(accounted + device_losses(before, after), after_t0);
    // The flag is per batch: a batch taken in time lost nothing. (Taken within 8 rounds,
    // 16 ms, of the one before; a test thread kept from running longer than that by the
    // machine's load sees a batch that lost rounds again and says how many, so it tries
    // again.)
    uint64_t dropped_in_batches = first->dropped + b.dropped;
    bool lost_nothing = false;
    for (int i = 0; i < 100 && !lost_nothing; ++i) {
        Result<InputBatch> next = sub->wait(1000ms);
        ASSERT_TRUE(next) << next.status().message;
        dropped_in_batches += next->dropped;
        lost_nothing = !next->overflowed();
    }
    EXPECT_TRUE(lost_nothing) << "100 batches in a row each lost rounds";
    // The total is the batches' sum, once no round comes any more.
    dev.close();
    dropped_in_batches += sub->take().dropped;
    EXPECT_EQ(sub->dropped_total(), dropped_in_batches);
}

TEST(HostInputSubscription, SubscribersOnTwoThreadsEachGetEveryRound) {
    SimRig rig = SimRig::make("iforce2", "firm", "hold:0", reports_at_500());
    Device& dev = *rig.host;
    Result<InputSubscription> a = dev.subscribe_input(512);
    Result<InputSubscription> b = dev.subscribe_input(512);
    ASSERT_TRUE(a && b);
    auto read = [](InputSubscription& s, std::vector<int64_t>& times) {
        while (times.size() < 100) {
            Result<InputBatch> got = s.wait(1000ms);
            if (!got) return;
            for (const InputState& r : got->reports) times.push_back(r.t_us);
        }
    };
    std::vector<int64_t> ta, tb;
    std::thread ra([&] { read(*a, ta); });
    std::thread rb([&] { read(*b, tb); });
    ra.join();
    rb.join();
    ASSERT_GE(ta.size(), 100u);
    ASSERT_GE(tb.size(), 100u);
    // Subscribed a moment apart, they share every round from the later first one on.
    const int64_t start = std::max(ta.front(), tb.front());
    std::erase_if(ta, [&](int64_t t) { return t < start; });
    std::erase_if(tb, [&](int64_t t) { return t < start; });
    const size_t n = std::min(ta.size(), tb.size());
    ASSERT_GT(n, 50u);
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(ta[i], tb[i]) << "round " << i;
}

TEST(HostInputSubscription, SubscribingAndLeavingWhileRoundsFlowIsSafe) {
    SimRig rig = SimRig::make("iforce2", "firm", "hold:0", reports_at_500());
    Device& dev = *rig.host;
    for (int i = 0; i < 200; ++i) {
        Result<InputSubscription> s = dev.subscribe_input(4);
        ASSERT_TRUE(s);
        if (i % 20 == 0) {
            Result<InputBatch> got = s->wait(1000ms);
            EXPECT_TRUE(got) << got.status().message;
        }
        InputSubscription moved = std::move(*s);
        EXPECT_FALSE(s->active());
        EXPECT_TRUE(moved.active());
    }
}

TEST(HostInputSubscription, RefusalsAndDisconnection) {
    SimRig rig = SimRig::make("iforce2", "firm", "hold:0", reports_at_500());
    Device& dev = *rig.host;
    for (size_t bad : {size_t{0}, Device::kMaxInputQueue + 1}) {
        Result<InputSubscription> s = dev.subscribe_input(bad);
        ASSERT_FALSE(s);
        EXPECT_EQ(s.status().kind, ErrorKind::invalid_parameter);
        EXPECT_NE(s.status().message.find("allowed 1..16384"), std::string::npos) << s.status().message;
    }
    InputSubscription empty;
    EXPECT_TRUE(empty.take().reports.empty());
    EXPECT_EQ(empty.wait(0ms).status().kind, ErrorKind::invalid_handle);

    Result<InputSubscription> sub = dev.subscribe_input(64);
    ASSERT_TRUE(sub);
    ASSERT_TRUE(sub->wait(1000ms));
    // Nothing queued: a zero wait times out at once (unless a round lands in that instant:
    // some try of many must find the queue empty).
    bool timed_out = false;
    for (int tries = 0; tries < 100 && !timed_out; ++tries) {
        (void)sub->take();
        timed_out = sub->wait(0ms).status().kind == ErrorKind::timeout;
    }
    EXPECT_TRUE(timed_out);
    rig.device.reset();  // the device goes away
    ASSERT_TRUE(wait_until([&] { return !dev.connected(); }));
    (void)sub->take();
    const Result<InputBatch> gone = sub->wait(1000ms);
    EXPECT_EQ(gone.status().kind, ErrorKind::disconnected) << gone.status().message;
    EXPECT_EQ(dev.subscribe_input(8).status().kind, ErrorKind::disconnected);
}

}  // namespace
}  // namespace feel::host::test
