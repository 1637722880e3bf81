// SimDevice::step and sense run in the real-time loop: they must never allocate. This
// binary replaces the global operator new to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

#include "feel/sim/sim_device.hpp"
#include "support/counting_allocator.hpp"

namespace feel::sim {
namespace {

TEST(StepAllocation, StepAndSenseNeverAllocate) {
    counting = true;  // this binary counts from here to its end
    const std::string csv =
        (std::filesystem::path(::testing::TempDir()) / "alloc_motion.csv").string();
    std::ofstream(csv) << "t_us,x,y\n0,0,0\n500000,5000,-5000\n1000000,0,0\n";
    const DeviceProfile& joystick = *find_device_profile("joystick");
    {  // The counter sees allocations: building a csv motion allocates its table.
        const long before = allocations.load();
        const TargetMotion table = TargetMotion::parse("csv:" + csv, 1, 2);
        ASSERT_GT(allocations.load() - before, 0);
    }
    for (Grip grip : {Grip::none, Grip::loose, Grip::firm, Grip::stiff, Grip::kinematic}) {
        for (const std::string& motion : {std::string("circle:5000:1"), "csv:" + csv}) {
            SimDevice device(joystick, grip, TargetMotion::parse(motion, 1, 2));
            const long before = allocations.load();
            for (int n = 0; n < 2000; ++n) {
                TickInput in;
                device.sense(in);
                const float force[kMaxAxes] = {n % 2 ? 10000.0f : -10000.0f, in.position[0]};
                device.step(force, n % 5 == 0 ? 1e-2 : 1e-3);
            }
            EXPECT_EQ(allocations.load() - before, 0) << grip_name(grip) << " " << motion;
        }
    }
}

}  // namespace
}  // namespace feel::sim
