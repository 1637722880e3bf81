// Dynamic Paddle (§5.9) in the closed loop: the hand pumps or cushions the paddle during
// the rebound. "If the user pumps the paddle forward during the rebound stage with
// appropriate timing, the paddle will pump energy into the ball and it will leave the
// paddle with extra energy behind it"; pulling back cushions it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

#include "contact_loop.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::test {
namespace {


// A ball from the screen (compass 0: it comes from +y and moves toward the user), an
// elastic paddle: the paddle's normal is +y.
EffectParams incoming_ball() {
    EffectParams p;
    p.type = EffectType::dynamic_paddle;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.dynamic.ball_mass = 6000;
    p.dynamic.initial_velocity = 6000;
    p.dynamic.initial_velocity_direction = 0;
    p.dynamic.paddle_compliance = 2000;
    p.dynamic.paddle_damping = 0;
    p.dynamic.gravity = 0;
    p.dynamic.interim_reporting = true;
    return p;
}

struct Leave {
    bool left = false;
    double speed = 0;      // the ball's velocity along +y in the fixed frame, position units/s
    double relative = 0;   // as reported: relative to the handle
    int interim = 0;       // interim reports before the final one
};

// The hand holds the paddle still through the compression (a quarter period π/(2ω) of
// the ball on a still paddle), then over the next quarter period, the rebound, moves it
// `shift` position units along y (+ toward the ball: pumping; − away: cushioning) and
// holds. The motion is a csv file in the test's temporary directory.
Leave bounce(sim::Grip grip, double shift, const std::string& name) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("joystick");
    const EngineConfig config = sim::engine_config_for(profile);
    const EffectParams p = incoming_ball();
    const double m = p.dynamic.ball_mass / 10000.0 * config.dynamic_mass_ref;
    const double k = p.dynamic.paddle_compliance / 10000.0 * config.dynamic_stiffness_ref;
    const double quarter_s = std::numbers::pi / (2 * std::sqrt(k / m));

    const std::string path = ::testing::TempDir() + "feel_paddle_" + name + ".csv";
    {
        std::ofstream csv(path);
        const auto us = [](double s) { return static_cast<long long>(std::llround(s * 1e6)); };
        csv << "t_us,x,y\n0,0,0\n"
            << us(quarter_s) << ",0,0\n"
            << us(2 * quarter_s) << ",0," << shift << "\n"
            << us(2.0) << ",0," << shift << "\n";
    }
    sim::SimDevice device(profile, grip, sim::TargetMotion::parse("csv:" + path, 2.0, profile.axis_count));
    loop::ClosedLoop rig(config);
    const EffectId id = rig.play(p);
    Leave leave;
    for (int i = 0; i < 2000 && !leave.left; ++i) {
        const TickOutput out = rig.tick(device);
        DynamicReport r;
        while (rig.engine().pop_report(r)) {
            EXPECT_EQ(r.effect, id);
            if (r.kind == DynamicReport::Kind::interim) {
                ++leave.interim;
                continue;
            }
            leave.left = true;
            leave.relative = r.velocity[1];
            // The report is relative to the handle; the handle moved at the engine's
            // estimate of its velocity, which the model subtracted.
            leave.speed = r.velocity[1] + out.velocity[1];
        }
    }
    std::remove(path.c_str());
    return leave;
}

class PaddlePump : public ::testing::TestWithParam<sim::Grip> {};

TEST_P(PaddlePump, PumpingLaunchesFasterAndCushioningSlower) {
    const sim::Grip grip = GetParam();
    const std::string g(sim::grip_name(grip));
    const Leave cushion = bounce(grip, -2000, g + "_cushion");
    const Leave still = bounce(grip, 0, g + "_still");
    const Leave pump = bounce(grip, 2000, g + "_pump");
    ASSERT_TRUE(cushion.left && still.left && pump.left);
    for (const Leave& l : {cushion, still, pump}) {
        EXPECT_GT(l.speed, 0.0) << "the ball leaves toward where it came from";
        EXPECT_GE(l.interim, 3) << "interim reports at 60 Hz during an ~80 ms bounce";
    }
    EXPECT_GT(pump.speed, still.speed * 1.1);
    EXPECT_LT(cushion.speed, still.speed * 0.9);
}

INSTANTIATE_TEST_SUITE_P(Grips, PaddlePump, ::testing::Values(sim::Grip::kinematic, sim::Grip::firm),
                         [](const ::testing::TestParamInfo<sim::Grip>& grip) {
                             return std::string(sim::grip_name(grip.param));
                         });

TEST(PaddlePumpKinematic, AStillPaddleReturnsTheBallAtItsSpeed) {
    // Held exactly still, an elastic paddle returns the ball at its incoming speed: the
    // closed loop adds no energy and takes none.
    const Leave still = bounce(sim::Grip::kinematic, 0, "kinematic_reference");
    const EngineConfig config = sim::engine_config_for(*sim::find_device_profile("joystick"));
    const double V = incoming_ball().dynamic.initial_velocity / 10000.0 * config.velocity_ref;
    ASSERT_TRUE(still.left);
    EXPECT_NEAR(still.speed, V, 1e-4 * V);
    EXPECT_NEAR(still.relative, V, 1e-4 * V);
}

}  // namespace
}  // namespace feel::test
