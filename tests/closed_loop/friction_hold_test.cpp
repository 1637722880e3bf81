// Friction in closed loop with the simulated devices: it holds a handle still against a
// smaller push, stops a coasting handle and keeps it there, and does not chatter doing so.
#include "friction_loop.hpp"

namespace feel::test {
namespace {

// The span of the handle's true position on x from row `from` on.
double position_span(const std::vector<LoopRow>& rows, size_t from) {
    double lo = rows[from].x[0], hi = lo;
    for (size_t i = from; i < rows.size(); ++i) {
        lo = std::min(lo, rows[i].x[0]);
        hi = std::max(hi, rows[i].x[0]);
    }
    return hi - lo;
}

TEST(FrictionClosedLoop, HoldsAFreeHandleAgainstASmallerPush) {
    // A free joystick, friction 6000, a constant push of 3000: the bristle deflects
    // (z = 0.5, a few hundred units) and then the handle stands still for good.
    const auto rows = run_loop("joystick", sim::Grip::none, "hold:0",
                               {friction_on({Axis::x}, 6000), constant_force_on_x(3000)}, 2.0);
    const size_t settled = 500;  // 0.5 s
    EXPECT_LT(std::fabs(rows.back().x[0]), 1000.0);
    EXPECT_LT(position_span(rows, settled), 0.01);
    EXPECT_EQ(force_sign_changes(rows, settled, 0), 0);
    EXPECT_LT(largest_force_step(rows, settled, 0), 1e-3);
    EXPECT_GT(rows.back().force[0], -1.0);  // friction and push balance (net near 0)
}

TEST(FrictionClosedLoop, APushLargerThanTheFrictionSlides) {
    const auto rows = run_loop("joystick", sim::Grip::none, "hold:-9000",
                               {friction_on({Axis::x}, 3000), constant_force_on_x(6000)}, 0.4);
    EXPECT_GT(rows.back().x[0] - rows[0].x[0], 2000.0);
}

TEST(FrictionClosedLoop, StopsACoastingHandleAndKeepsItStillOnEveryProfile) {
    for (const char* profile : {"joystick", "wheel", "3axis"}) {
        for (int32_t f : {2000, 6000, 10000}) {
            SCOPED_TRACE(std::string(profile) + " f=" + std::to_string(f));
            const auto rows = run_loop(profile, sim::Grip::none, "hold:0", {friction_on({Axis::x}, f)}, 2.0, 1000,
                                       30000);
            const size_t late = 1000;  // the last second
            EXPECT_EQ(force_sign_changes(rows, late, 0), 0);
            EXPECT_LT(position_span(rows, late), 1.0);
        }
    }
}

}  // namespace
}  // namespace feel::test
