// CommandQueue, the non-blocking host calls: order kept, bursts coalesced to the newest,
// outcomes on the caller's poll, immediate refusals, bounded memory. Forces are checked
// against the spring law F = -k/10000 * x (§3.2) at the position the device reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <string>
#include <vector>

#include "feel/host/command_queue.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

std::vector<Outcome> drain(CommandQueue& queue) {
    std::vector<Outcome> out;
    queue.poll([&](const Outcome& o) { out.push_back(o); });
    return out;
}

TEST(CommandQueue, CommandsRunInTheOrderTheyWereQueued) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> spring = dev.create_effect(spring_x(1000));
    ASSERT_TRUE(spring) << spring.status().message;
    CommandQueue queue(dev);
    // start, stop, start: the effect ends playing; start, stop: it ends stopped.
    ASSERT_TRUE(queue.start(*spring));
    ASSERT_TRUE(queue.stop(*spring));
    ASSERT_TRUE(queue.start(*spring, kInfiniteIterations));
    ASSERT_TRUE(queue.flush(5000ms).ok());
    Result<EffectStatusInfo> s = spring->status();
    ASSERT_TRUE(s);
    EXPECT_EQ(s->state, runtime::ReportedEffectState::playing);
    ASSERT_TRUE(queue.stop(*spring));
    ASSERT_TRUE(queue.flush(5000ms).ok());
    s = spring->status();
    ASSERT_TRUE(s);
    EXPECT_EQ(s->state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(s->last_end, PlayEnd::stopped);

    const std::vector<Outcome> outcomes = drain(queue);
    ASSERT_EQ(outcomes.size(), 4u);
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
        EXPECT_EQ(outcomes[i].ticket, i + 1) << "outcomes come in the order the commands ran";
        EXPECT_TRUE(outcomes[i].status.ok()) << outcomes[i].status.message;
        EXPECT_FALSE(outcomes[i].coalesced);
    }
    EXPECT_STREQ(outcomes[1].what, "stop");
}

TEST(CommandQueue, ABurstOfUpdatesCoalescesToTheNewestAndTheSpringFollowsIt) {
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:4000,0", fast_reports());
    Device& dev = *rig.host;
    ASSERT_TRUE(wait_for_full_force(dev));
    Result<Effect> spring = dev.create_effect(spring_x(1000));
    ASSERT_TRUE(spring) << spring.status().message;
    ASSERT_TRUE(spring->start(kInfiniteIterations).ok());
    CommandQueue queue(dev);
    constexpr int kUpdates = 200;
    for (int i = 1; i <= kUpdates; ++i) {
        // Each update names only the type-specific block: its gain of 1 must not apply.
        EffectParams p = spring_x(40 * i);
        p.gain = 1;
        ASSERT_TRUE(queue.set_parameters(*spring, p, effect_field::kTypeSpecific));
    }
    ASSERT_TRUE(queue.flush(10000ms).ok());
    EXPECT_EQ(spring->parameters().conditions[0].pos_coefficient, 40 * kUpdates);
    EXPECT_EQ(spring->parameters().gain, kFullScale);

    const std::vector<Outcome> outcomes = drain(queue);
    ASSERT_EQ(outcomes.size(), static_cast<std::size_t>(kUpdates)) << "every call gets its outcome";
    std::set<Ticket> tickets, carriers;
    int coalesced = 0;
    for (const Outcome& o : outcomes) {
        EXPECT_TRUE(o.status.ok()) << o.status.message;
        tickets.insert(o.ticket);
        if (o.coalesced) {
            ++coalesced;
            EXPECT_GT(o.into, o.ticket) << "a call is carried by a later one";
        } else {
            carriers.insert(o.ticket);
        }
    }
    EXPECT_EQ(tickets.size(), static_cast<std::size_t>(kUpdates));
    EXPECT_EQ(*tickets.begin(), 1u);
    EXPECT_EQ(*tickets.rbegin(), static_cast<Ticket>(kUpdates));
    EXPECT_GT(coalesced, 0) << "200 updates in a burst, each a device round trip: most wait and coalesce";
    for (const Outcome& o : outcomes) {
        if (o.coalesced) {
            EXPECT_TRUE(carriers.count(o.into)) << "carried by a command that ran";
        }
    }

    // The device plays the newest spring: F = -k/10000 * x with k = 8000.
    const InputState in = settled(dev);
    EXPECT_NEAR(in.position[0], 4000, 5);
    EXPECT_NEAR(in.force[0], -0.8 * in.position[0], 2.0);
}

TEST(CommandQueue, TheNewestGainWinsAndScalesTheForce) {
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:3000,0", fast_reports());
    Device& dev = *rig.host;
    ASSERT_TRUE(wait_for_full_force(dev));
    Result<Effect> spring = dev.create_effect(spring_x(10000));
    ASSERT_TRUE(spring) << spring.status().message;
    ASSERT_TRUE(spring->start(kInfiniteIterations).ok());
    CommandQueue queue(dev);
    for (int32_t gain : {1000, 9000, 2000, 5000}) ASSERT_TRUE(queue.set_gain(gain));
    ASSERT_TRUE(queue.flush(5000ms).ok());
    const InputState in = settled(dev);
    EXPECT_EQ(in.gain, 5000);
    EXPECT_NEAR(in.force[0], -0.5 * in.position[0], 2.0);
    EXPECT_EQ(drain(queue).size(), 4u);
}

TEST(CommandQueue, TheDevicesRefusalArrivesAtTheNextPollAndChangesNothing) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> spring = dev.create_effect(spring_x(1000));
    ASSERT_TRUE(spring) << spring.status().message;
    CommandQueue queue(dev);
    EffectParams bad = spring_x(1000);
    bad.conditions[0].deadband = 12000;
    Result<Ticket> t = queue.set_parameters(*spring, bad);
    ASSERT_TRUE(t) << "accepted at once: the range is checked when it runs";
    ASSERT_TRUE(queue.flush(5000ms).ok());
    const std::vector<Outcome> outcomes = drain(queue);
    ASSERT_EQ(outcomes.size(), 1u);
    EXPECT_EQ(outcomes[0].ticket, t.value());
    EXPECT_EQ(outcomes[0].status.kind, ErrorKind::invalid_parameter);
    EXPECT_NE(outcomes[0].status.message.find("conditions[0].deadband = 12000 is out of range (allowed 0..10000)"),
              std::string::npos)
        << outcomes[0].status.message;
    EXPECT_EQ(spring->parameters().conditions[0].deadband, 0);
    EXPECT_EQ(drain(queue).size(), 0u) << "an outcome is delivered once";
}

TEST(CommandQueue, WhatNeedsNoDeviceIsRefusedAtTheCall) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> spring = dev.create_effect(spring_x(1000));
    ASSERT_TRUE(spring);
    CommandQueue queue(dev);
    Effect empty;
    EXPECT_EQ(queue.start(empty).status().kind, ErrorKind::invalid_handle);
    Result<Ticket> r = queue.start(*spring, 300);
    EXPECT_EQ(r.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(r.status().message.find("iterations = 300 is out of range"), std::string::npos) << r.status().message;
    EXPECT_EQ(queue.set_parameters(*spring, spring_x(1), 1u << 12).status().kind, ErrorKind::invalid_parameter);
    EffectParams other = spring_x(1);
    other.type = EffectType::damper;
    EXPECT_EQ(queue.set_parameters(*spring, other).status().kind, ErrorKind::invalid_parameter);
    r = queue.set_gain(12000);
    EXPECT_EQ(r.status().message, "set_gain: gain = 12000 is out of range (allowed 0..10000)");
    const int32_t three[3] = {0, 0, 0};
    EXPECT_EQ(queue.stream_force(three).status().kind, ErrorKind::invalid_parameter);
    EXPECT_EQ(queue.pending(), 0u) << "nothing refused was queued";
    EXPECT_THROW(CommandQueue(dev, CommandQueueOptions{0, 16}), std::invalid_argument);
}

TEST(CommandQueue, AFullQueueRefusesAndKeepsItsBound) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> spring = dev.create_effect(spring_x(1000));
    ASSERT_TRUE(spring);
    CommandQueue queue(dev, CommandQueueOptions{2, 4});
    int accepted = 0, refused = 0;
    std::string message;
    for (int i = 0; i < 50; ++i) {  // starts never coalesce; each takes a device round trip
        Result<Ticket> t = queue.start(*spring);
        if (t) {
            ++accepted;
        } else {
            ++refused;
            EXPECT_EQ(t.status().kind, ErrorKind::device_full);
            message = t.status().message;
        }
        EXPECT_LE(queue.pending(), 3u) << "two waiting and one running at most";
    }
    EXPECT_GT(refused, 0);
    EXPECT_NE(message.find("max_pending = 2"), std::string::npos) << message;
    ASSERT_TRUE(queue.flush(5000ms).ok());
    // At most 4 outcomes wait; the others were dropped and counted.
    const std::vector<Outcome> outcomes = drain(queue);
    EXPECT_EQ(outcomes.size(), static_cast<std::size_t>(std::min(accepted, 4)));
    EXPECT_EQ(queue.dropped_outcomes(), static_cast<uint64_t>(std::max(accepted - 4, 0)));
}

TEST(CommandQueue, ACommandForAnEffectDestroyedMeanwhileReportsInvalidHandle) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    CommandQueue queue(dev);
    {
        Result<Effect> spring = dev.create_effect(spring_x(1000));
        ASSERT_TRUE(spring);
        ASSERT_TRUE(queue.flush(5000ms).ok());
        ASSERT_TRUE(queue.set_gain(8000));       // keeps the worker busy for a round trip
        ASSERT_TRUE(queue.start(*spring));
    }  // the game destroys its Effect (unloading it) while the start may still wait
    ASSERT_TRUE(queue.flush(5000ms).ok());
    const std::vector<Outcome> outcomes = drain(queue);
    ASSERT_EQ(outcomes.size(), 2u);
    // Either the start ran before the unload (ok) or after it (invalid_handle): never a crash,
    // never another effect started.
    EXPECT_TRUE(outcomes[1].status.ok() || outcomes[1].status.kind == ErrorKind::invalid_handle)
        << outcomes[1].status.message;
    EXPECT_TRUE(wait_until([&] { return dev.input().playing_effects == 0; }));
}

}  // namespace
}  // namespace feel::host::test
