// The device runtime on its real-time thread: commands from this (host) thread, acks and
// state reports back, a clean stop, and device time that goes on across a restart. Nothing
// here asserts a timing figure: waits have generous deadlines and only give up.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "feel/runtime/device_runtime.hpp"
#include "runtime_rig.hpp"

namespace feel::runtime::test {
namespace {

using Clock = std::chrono::steady_clock;

std::unique_ptr<SimBackend> held_joystick() {
    return std::make_unique<SimBackend>(joystick(), sim::Grip::firm, sim::TargetMotion::hold_at({0}));
}

DeviceRuntimeOptions ordinary_thread() {
    DeviceRuntimeOptions o;
    o.lock_memory = false;  // leave the test process's memory alone
    return o;
}

// The host's side: polls until the ack of `sequence` arrives (gives up after 5 s), keeping
// the state reports it reads on the way.
struct Host {
    DeviceRuntime& rt;
    std::vector<StateReport> states;

    CommandAck await(std::optional<uint32_t> sequence) {
        EXPECT_TRUE(sequence.has_value());
        const auto give_up = Clock::now() + std::chrono::seconds(5);
        Report r;
        while (sequence && Clock::now() < give_up) {
            while (rt.poll(r)) {
                if (r.kind == ReportKind::state) states.push_back(r.state);
                if (r.kind == ReportKind::ack && r.ack.sequence == *sequence) return r.ack;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        ADD_FAILURE() << "no ack";
        return {};
    }
    void read_for(std::chrono::milliseconds span) {
        const auto end = Clock::now() + span;
        Report r;
        while (Clock::now() < end) {
            while (rt.poll(r)) {
                if (r.kind == ReportKind::state) states.push_back(r.state);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }
};

TEST(DeviceRuntime, RunsTheLoopOnItsThreadAndTalksThroughTheQueues) {
    RuntimeConfig config = quiet_config();
    config.report_rate_hz = 500;
    DeviceRuntime rt(config, held_joystick(), ordinary_thread());
    Host host{rt, {}};
    // Commands may be queued before the loop runs; they wait.
    const auto created_seq = rt.create([] {
        EffectParams p;
        p.type = EffectType::constant;
        p.axis_count = 1;
        p.constant.magnitude = 3000;
        return p;
    }());
    rt.start();
    EXPECT_TRUE(rt.running());
    const CommandAck created = host.await(created_seq);
    ASSERT_TRUE(created.error.ok()) << created.error.message();
    const CommandAck started = host.await(rt.start_effect(created.effect));
    ASSERT_TRUE(started.error.ok());
    host.read_for(std::chrono::milliseconds(300));
    const CommandAck status = host.await(rt.status(created.effect));
    EXPECT_EQ(status.status.state, EffectState::playing);
    EXPECT_GT(status.status.elapsed_us, 0);
    rt.stop();
    EXPECT_FALSE(rt.running());

    // State reports flowed, in device time, showing the effect's force after its start.
    ASSERT_FALSE(host.states.empty());
    for (size_t i = 1; i < host.states.size(); ++i) EXPECT_GT(host.states[i].t_us, host.states[i - 1].t_us);
    EXPECT_EQ(host.states.back().force[0], 3000.0f);
    ASSERT_EQ(host.states.back().effect_count, 1);
    EXPECT_EQ(host.states.back().effects[0].state, ReportedEffectState::playing);

    // The loop ran every tick through the pipeline; the ack times are device times of ticks.
    const DeviceRuntimeStats s = rt.stats();
    EXPECT_EQ(s.pipeline.ticks, s.loop.ticks);
    EXPECT_GT(s.pipeline.ticks, 100);
    EXPECT_EQ(s.pipeline.commands, 3);
    EXPECT_EQ(s.pipeline.rejected_ticks, 0);
    EXPECT_EQ(started.t_us % 1000, 0);
    std::printf("device runtime: %lld ticks, %lld overruns, %lld missed; %s\n", static_cast<long long>(s.loop.ticks),
                static_cast<long long>(s.loop.overruns), static_cast<long long>(s.loop.missed_ticks),
                rt.setup().describe().c_str());
}

TEST(DeviceRuntime, DeviceTimeGoesOnAcrossARestart) {
    DeviceRuntime rt(quiet_config(), held_joystick(), ordinary_thread());
    Host host{rt, {}};
    rt.start();
    EXPECT_THROW(rt.start(), std::logic_error);
    host.await(rt.keep_alive());
    rt.stop();
    rt.stop();  // harmless
    const int64_t last_t = rt.pipeline().counters().t_us;
    const int64_t next = rt.pipeline().next_tick_index();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    rt.start();
    const CommandAck after = host.await(rt.keep_alive());
    rt.stop();
    // No gap in device time for the stop: the first tick after the restart is the next index.
    EXPECT_GT(after.t_us, last_t);
    EXPECT_EQ(rt.pipeline().counters().rejected_ticks, 0);
    EXPECT_GE(rt.pipeline().next_tick_index(), next + 1);
    EXPECT_EQ(rt.pipeline().backend().axis_count(), 2);
}

TEST(DeviceRuntime, TheDestructorStopsARunningLoop) {
    auto rt = std::make_unique<DeviceRuntime>(quiet_config(), held_joystick(), ordinary_thread());
    rt->start();
    Host host{*rt, {}};
    host.await(rt->keep_alive());
    rt.reset();  // joins the thread before the pipeline goes
    SUCCEED();
}

TEST(DeviceRuntime, ForceProfilesCrossTheQueueFromTheHost) {
    DeviceRuntime rt(quiet_config(), held_joystick(), ordinary_thread());
    Host host{rt, {}};
    rt.start();
    std::vector<int16_t> samples(2000);
    for (size_t i = 0; i < samples.size(); ++i) samples[i] = static_cast<int16_t>(static_cast<int>(i % 200) * 50 - 5000);
    EffectParams p;
    p.type = EffectType::force_profile;
    p.axis_count = 1;
    p.custom = {1, 1000, 2000};
    const CommandAck created = host.await(rt.create(p, samples));
    rt.stop();
    ASSERT_TRUE(created.error.ok()) << created.error.message();
    EXPECT_EQ(created.pool.free_bytes, 16384 - (14 + 8 + 2 * 2000));
    // More samples than the queue could ever hold at once is the host's error, at once.
    std::vector<int16_t> huge(256 * kSamplesPerCommand);
    EXPECT_THROW((void)rt.create(p, huge), std::invalid_argument);
}

}  // namespace
}  // namespace feel::runtime::test
