// SafetyMonitor::process runs in the loop's tick: it must never allocate. A hooked global
// allocator counts every allocation while the monitor watches a closed loop that goes
// through everything it does: fade-in, let-go, hands-off, fade-out, re-grab, the watchdog.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "feel/engine.hpp"
#include "feel/runtime/safety.hpp"
#include "feel/sim/input_schedule.hpp"
#include "feel/sim/sim_device.hpp"
#include "support/counting_allocator.hpp"

namespace feel::runtime {
namespace {

TEST(SafetyAllocation, TheCounterSeesAllocations) {
    counting = true;
    auto* probe = new int(7);
    counting = false;
    EXPECT_GT(allocations.exchange(0), 0);
    delete probe;
}

TEST(SafetyAllocation, ProcessNeverAllocates) {
    sim::DeviceProfile profile = *sim::find_device_profile("joystick");
    profile.dead_man_switch = false;
    Engine engine(sim::engine_config_for(profile));
    EffectParams push;
    push.type = EffectType::constant;
    push.axis_count = 1;
    push.constant.magnitude = 9000;
    ASSERT_TRUE(engine.start(engine.create(push).id).ok());
    sim::SimDevice device(profile, sim::Grip::firm, sim::TargetMotion::parse("sine:x:2500:2", 4, 2));
    sim::InputSchedule schedule(profile);
    schedule.let_go(1'000'000).grab(2'000'000).let_go(2'500'000).grab(2'600'000);
    SafetyConfig config = safety_config_for(profile);
    config.host_timeout_us = 200'000;
    SafetyMonitor safety;
    ASSERT_TRUE(safety.configure(config).ok());

    float applied[kMaxAxes] = {};
    int64_t heard = 0;
    counting = true;
    for (int64_t t = 0; t < 4'000'000; t += 1000) {
        if (t < 3'000'000) heard = t;  // then the host falls silent
        schedule.apply(device, t);
        TickInput in;
        in.t_us = t;
        device.sense(in);
        TickOutput out;
        engine.tick(in, out);
        float force[kMaxAxes];
        std::copy(std::begin(out.force), std::end(out.force), force);
        const SafetyState& s = safety.process(safety_input(in, out, applied, heard), force);
        if (s.host_lost_event) engine.stop_all();
        if (t == 1'500'000) safety.set_actuators_enabled(false);
        if (t == 1'600'000) safety.set_actuators_enabled(true);
        device.step(force, 1e-3);
        std::copy(force, force + kMaxAxes, applied);
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    // The run went through what it was meant to.
    EXPECT_GE(safety.state().hands_off_trips, 1u);
    EXPECT_EQ(safety.state().host_losses, 1u);
}

}  // namespace
}  // namespace feel::runtime
