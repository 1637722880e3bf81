// Friction in closed loop: a hand moving the joystick back and forth through a friction
// feels the force turn around smoothly, once per reversal, with no step and no chatter.
#include "friction_loop.hpp"

namespace feel::test {
namespace {

TEST(FrictionClosedLoop, ReversingDirectionGivesNoStepInForce) {
    // A firm hand swings the stick ±3000 at 1 Hz through a friction of 6000. The ideal
    // Coulomb law of Figure 3-9 would step by 2f = 12000 at each of the 6 reversals.
    const int32_t f = 6000;
    const auto rows = run_loop("joystick", sim::Grip::firm, "sine:x:3000:1", {friction_on({Axis::x}, f)}, 3.0);
    const size_t from = 100;  // past the first pull into the friction
    EXPECT_LT(largest_force_step(rows, from, 0), 0.05 * 2 * f);
    // The force turns around once per reversal: 2 per period, and never buzzes.
    EXPECT_EQ(force_sign_changes(rows, from, 0, 0.05 * f), 6);
    EXPECT_EQ(force_sign_changes(rows, from, 0), 6);
    // Once it has slid 5 presliding distances past a reversal it is the friction itself:
    // -f moving toward +, +f moving toward - (the joystick's Z = f / (2b/T) = 534 units).
    const double Z = f / (2 * (0.5 * 0.05 / 4.45) / 1e-3);
    int sliding = 0;
    double turned_at = rows[0].x[0];
    for (size_t i = 1; i < rows.size(); ++i) {
        if ((rows[i].v[0] > 0) != (rows[i - 1].v[0] > 0)) turned_at = rows[i].x[0];
        if (i < from || std::fabs(rows[i].x[0] - turned_at) < 5 * Z) continue;
        ++sliding;
        ASSERT_NEAR(rows[i].force[0], rows[i].v[0] > 0 ? -f : f, 0.02 * f) << rows[i].t_s;  // 2·e^-5 = 1.3%
    }
    EXPECT_GT(sliding, 600);
}

TEST(FrictionClosedLoop, ReversingOnEveryProfileStaysSmooth) {
    for (const char* profile : {"joystick", "wheel", "3axis"}) {
        SCOPED_TRACE(profile);
        const auto rows = run_loop(profile, sim::Grip::firm, "sine:x:2000:2", {friction_on({Axis::x}, 4000)}, 2.0);
        EXPECT_LT(largest_force_step(rows, 100, 0), 0.1 * 8000);
        EXPECT_EQ(force_sign_changes(rows, 100, 0), 8);
    }
}

}  // namespace
}  // namespace feel::test
