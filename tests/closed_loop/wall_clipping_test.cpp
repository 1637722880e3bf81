// Clipping in closed loop (§3.7): a hand pushes the handle deep into walls that cannot be
// rigid (the motor gives at most full force), and the position the device reports never
// crosses the wall surface, while the sensed position does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_loop.hpp"

namespace feel::test::loop {
namespace {

struct ClipRun {
    double deepest_sensed = -1e9;    // along the wall's normal, past the surface (> 0: inside)
    double deepest_reported = -1e9;
    int ticks_inside = 0;
};

// Plays `wall` on the joystick held by a stiff hand that follows `motion` for `seconds`,
// and measures how far past the surface (along `normal`, pointing into the solid) the
// sensed and the reported positions go. Every tick the reported position must equal the
// sensed one while the handle is outside the solid and lie on the surface while inside,
// with the component along the surface untouched.
ClipRun push_through(const EffectParams& wall, const char* motion, double seconds, const double normal[2],
                     double surface) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    ClosedLoop loop(sim::engine_config_for(joystick));
    loop.play(wall);
    sim::SimDevice device(joystick, sim::Grip::stiff, sim::TargetMotion::parse(motion, seconds, 2));
    ClipRun run;
    const int ticks = static_cast<int>(seconds * 1000);
    for (int n = 0; n < ticks; ++n) {
        TickInput sensed;
        device.sense(sensed);
        const TickOutput out = loop.tick(device);
        const double s = sensed.position[0] * normal[0] + sensed.position[1] * normal[1];
        const double r = out.reported_position[0] * normal[0] + out.reported_position[1] * normal[1];
        const double tangent_sensed = sensed.position[0] * normal[1] - sensed.position[1] * normal[0];
        const double tangent_reported = out.reported_position[0] * normal[1] - out.reported_position[1] * normal[0];
        run.deepest_sensed = std::max(run.deepest_sensed, s - surface);
        run.deepest_reported = std::max(run.deepest_reported, r - surface);
        if (s > surface) {
            ++run.ticks_inside;
            EXPECT_NEAR(r, surface, 1e-3) << "tick " << n << ": inside, the report sits on the surface";
        } else {
            EXPECT_EQ(out.reported_position[0], sensed.position[0]) << "tick " << n;
            EXPECT_EQ(out.reported_position[1], sensed.position[1]) << "tick " << n;
        }
        EXPECT_NEAR(tangent_reported, tangent_sensed, 1e-3) << "tick " << n << ": sliding along is reported";
    }
    return run;
}

EffectParams clipping_wall(EffectType type, Axis axis, int32_t angle, WallSense sense, int32_t offset) {
    EffectParams p;
    p.type = type;
    if (type == EffectType::axis_wall) {
        p.axis_count = 1;
        p.axes[0] = axis;
    } else {
        p.axis_count = 2;
        p.axes[0] = Axis::x;
        p.axes[1] = Axis::y;
        p.wall.angle = angle;
    }
    p.wall.hardness = 10000;
    p.wall.sense = sense;
    p.wall.offset = offset;
    p.wall.clipping = true;
    return p;
}

TEST(WallClipping, HorizontalWallHoldsTheReportedYAtTheSurface) {
    // A HorizontalWall at y = 2000 facing the user; the hand drives the target round a
    // circle of radius 9000, so it sweeps along the wall while pushing up to 7000 past
    // it. The stiff grip out-pushes the motor, so the handle goes deep into the wall, but
    // the host never sees y past 2000, and sees x as it is.
    const double normal[2] = {0, 1};
    const ClipRun run = push_through(clipping_wall(EffectType::axis_wall, Axis::y, 0, WallSense::positive, 2000),
                                     "circle:9000:0.5", 2.0, normal, 2000);
    EXPECT_GT(run.deepest_sensed, 500.0) << "the handle must really penetrate for the test to mean anything";
    EXPECT_GT(run.ticks_inside, 500);
    EXPECT_LE(run.deepest_reported, 0.0);
}

TEST(WallClipping, VerticalWallHoldsTheReportedXAtTheSurface) {
    // A VerticalWall at x = −3000 with the solid to the left (negative sense): the normal
    // into the solid is −x.
    const double normal[2] = {-1, 0};
    const ClipRun run = push_through(clipping_wall(EffectType::axis_wall, Axis::x, 0, WallSense::negative, -3000),
                                     "sine:x:9000:0.5", 2.0, normal, 3000);
    EXPECT_GT(run.deepest_sensed, 500.0);
    EXPECT_LE(run.deepest_reported, 0.0);
}

TEST(WallClipping, AngleWallsAtTheAxisAnglesClipLikeHorizontalAndVerticalWalls) {
    // angle 18000: u = −y, positive sense, offset 1500: the solid is y < −1500.
    {
        const double normal[2] = {0, -1};
        const ClipRun run = push_through(
            clipping_wall(EffectType::angle_wall, Axis::x, 18000, WallSense::positive, 1500), "sine:y:9000:0.5", 2.0,
            normal, 1500);
        EXPECT_GT(run.deepest_sensed, 500.0);
        EXPECT_LE(run.deepest_reported, 0.0);
    }
    // angle 9000: u = +x, negative sense, offset 4000: the solid is x < 4000, a handle
    // starting at x = 0 is inside it from the start and is pushed out along +x.
    {
        const double normal[2] = {-1, 0};
        const ClipRun run = push_through(
            clipping_wall(EffectType::angle_wall, Axis::x, 9000, WallSense::negative, 4000), "circle:6000:0.5", 2.0,
            normal, -4000);
        EXPECT_GT(run.deepest_sensed, 500.0);
        EXPECT_LE(run.deepest_reported, 0.0);
    }
}

TEST(WallClipping, AnObliqueWallClipsOntoItsLine) {
    // At 4500 the report is projected onto the wall line: its distance along u never
    // passes the offset.
    const double r = std::sqrt(0.5);
    const double normal[2] = {r, r};
    const ClipRun run = push_through(clipping_wall(EffectType::angle_wall, Axis::x, 4500, WallSense::positive, 2000),
                                     "circle:7000:0.5", 2.0, normal, 2000);
    EXPECT_GT(run.deepest_sensed, 500.0);
    EXPECT_LE(run.deepest_reported, 1e-3);
}

}  // namespace
}  // namespace feel::test::loop
