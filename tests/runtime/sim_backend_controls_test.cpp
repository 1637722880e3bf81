// The simulated hand's buttons and hats handed to a running SimBackend from another thread:
// the next sense() shows them; a control the profile lacks is refused and changes nothing.
#include <gtest/gtest.h>

#include <thread>

#include "feel/runtime/runtime_backend.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::runtime {
namespace {

TEST(SimBackendControls, ButtonsAndHatsSetFromAnotherThreadShowAtTheNextSense) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("iforce2");  // 4 buttons, 2 hats
    SimBackend backend(profile, sim::Grip::firm, sim::TargetMotion::hold_at({0}));
    TickInput in;
    backend.sense(0, in);
    EXPECT_EQ(in.buttons, 0u);
    EXPECT_EQ(in.hats, 0u);

    std::thread hand([&] {
        EXPECT_TRUE(backend.set_buttons(0b1001));  // buttons 1 and 4
        EXPECT_TRUE(backend.set_hats(0b10));       // hat 2
    });
    hand.join();
    backend.sense(1000, in);
    EXPECT_EQ(in.buttons, 0b1001u);
    EXPECT_EQ(in.hats, 0b10u);
    backend.sense(2000, in);  // they stay as set
    EXPECT_EQ(in.buttons, 0b1001u);
    EXPECT_EQ(in.hats, 0b10u);

    EXPECT_FALSE(backend.set_buttons(0b10000));  // button 5: the profile has 4
    EXPECT_FALSE(backend.set_hats(0b100));       // hat 3: it has 2
    backend.sense(3000, in);
    EXPECT_EQ(in.buttons, 0b1001u);
    EXPECT_EQ(in.hats, 0b10u);

    EXPECT_TRUE(backend.set_buttons(0));
    backend.sense(4000, in);
    EXPECT_EQ(in.buttons, 0u);
}

}  // namespace
}  // namespace feel::runtime
