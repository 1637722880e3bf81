// Surface friction in pressure mode, in closed loop (§3.7): a hand presses the handle
// against a horizontal wall and drags it along; the harder it presses, the harder the
// rubbing resists, in proportion.
//
// The law (contact_surface.hpp): while sliding at speed v along the surface, the wall
// resists with μ·N·tanh(v/v_s), N its normal force, μ = surface_friction/10000,
// v_s = 0.1·velocity_ref. The test measures how hard the hand pushes into the wall at the
// hand, in the simulator, independently of the engine, and checks that a harder push
// gives a proportionally harder rubbing through the wall's normal force N (which the
// push sets, less whatever the mechanism's own friction on that axis holds).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact_loop.hpp"

namespace feel::test::loop {
namespace {

struct Drag {
    double hand_push = 0;   // mean force of the hand into the wall, normalized units
    double normal = 0;      // mean normal force of the wall (pushing back, > 0), normalized units
    double rubbing = 0;     // mean force of the engine along the wall (x), normalized units
    double speed = 0;       // mean speed of the handle along the wall, normalized units/s
};

// The joystick with a horizontal wall at y = 0 (solid above); a firm hand holds the target
// `depth` units into the wall and sweeps it along x at 8000 units/s (40 mm/s). Averages
// over the middle of the sweep, where the drag is steady.
Drag drag_along(double depth, int32_t surface_friction) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    ClosedLoop loop(sim::engine_config_for(joystick));
    EffectParams wall;
    wall.type = EffectType::axis_wall;
    wall.axis_count = 1;
    wall.axes[0] = Axis::y;
    wall.wall.hardness = 10000;
    wall.wall.sense = WallSense::positive;
    wall.wall.surface_friction = surface_friction;
    loop.play(wall);

    // Target: x from -6000 to 6000 in 1.5 s, y held at `depth`.
    const std::string y = std::to_string(depth);
    const std::string csv = "t_us,x,y\n0,-6000," + y + "\n1500000,6000," + y + "\n";
    const std::string path = ::testing::TempDir() + "feel_drag_" + std::to_string(static_cast<int>(depth)) + ".csv";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        EXPECT_NE(f, nullptr);
        std::fputs(csv.c_str(), f);
        std::fclose(f);
    }
    sim::SimDevice device(joystick, sim::Grip::firm, sim::TargetMotion::parse("csv:" + path, 1.5, 2));
    const double to_normalized = 10000.0 / joystick.axes[1].max_force;
    Drag d;
    int n = 0;
    for (int k = 0; k < 1500; ++k) {
        const TickOutput out = loop.tick(device);
        if (k < 500 || k >= 1000) continue;
        d.hand_push += device.hand_force(1) * to_normalized;
        d.rubbing += out.force[0];
        d.normal -= out.force[1];
        d.speed += device.velocity(0);
        ++n;
    }
    d.hand_push /= n;
    d.rubbing /= n;
    d.normal /= n;
    d.speed /= n;
    return d;
}

TEST(WallSurfaceFriction, GrowsWithHowHardTheHandPushes) {
    const double mu = 0.7;
    const double slip = 0.1 * 1e5;
    const Drag light = drag_along(150, 7000);
    const Drag hard = drag_along(700, 7000);
    ASSERT_GT(light.hand_push, 500.0) << "the light drag must still press";
    ASSERT_GT(hard.hand_push, 2.5 * light.hand_push) << "the hard drag must press clearly harder";
    ASSERT_GT(hard.normal, 2.5 * light.normal);
    for (const Drag& d : {light, hard}) {
        ASSERT_GT(d.speed, 6000.0) << "the handle must slide";
        const double expected = -mu * d.normal * std::tanh(d.speed / slip);
        EXPECT_NEAR(d.rubbing, expected, 0.05 * std::fabs(expected)) << "normal force " << d.normal;
    }
    // In proportion: the rubbing grows as the normal force does (same speed in both runs).
    EXPECT_NEAR(hard.rubbing / light.rubbing, hard.normal / light.normal, 0.05 * hard.normal / light.normal);
}

TEST(WallSurfaceFriction, NoSurfaceFrictionNoRubbing) {
    const Drag d = drag_along(600, 0);
    EXPECT_EQ(d.rubbing, 0.0);
}

}  // namespace
}  // namespace feel::test::loop
