// InputSchedule::apply and the hand and button setters run in the real-time loop: they must
// never allocate. This binary replaces the global operator new to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "feel/sim/input_schedule.hpp"
#include "feel/sim/sim_device.hpp"
#include "support/counting_allocator.hpp"

namespace feel::sim {
namespace {

TEST(InputScheduleAllocation, ApplyNeverAllocates) {
    counting = true;  // this binary counts from here to its end
    const DeviceProfile& joystick = *find_device_profile("joystick");
    InputSchedule schedule(joystick);
    {  // The counter sees allocations: adding events grows the list.
        const long before = allocations.load();
        for (int64_t t = 0; t < 2'000'000; t += 1'000) {
            schedule.press(t, 1 + static_cast<int32_t>(t / 1000 % 4));
            if (t % 7000 == 0) schedule.let_go(t);
            if (t % 7000 == 3000) schedule.grab(t);
            if (t % 5000 == 0) schedule.set_buttons(t, 0);
        }
        ASSERT_GT(allocations.load() - before, 0);
    }
    SimDevice device(joystick, Grip::firm, TargetMotion::parse("circle:5000:1", 2, 2));
    const long before = allocations.load();
    int64_t applied = 0;
    for (int64_t t = 0; t < 2'000'000; t += 1'000) {
        applied += schedule.apply(device, t);
        TickInput in;
        device.sense(in);
        const float force[kMaxAxes] = {in.handle_held ? 5000.0f : 0.0f, -in.position[0]};
        device.step(force, 1e-3);
    }
    EXPECT_EQ(allocations.load() - before, 0);
    EXPECT_EQ(applied, static_cast<int64_t>(schedule.size()));
}

}  // namespace
}  // namespace feel::sim
