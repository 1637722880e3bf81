// Texture (§3.6, §6.6.j): a grating of raised-cosine bumps, each a patch of friction whose
// strength is the roughness of the direction of travel. Checked against
//
//     F_s = -R·bump(s)·z,   bump(r) = (1 + cos(2π·r/w))/2 for |r| <= w/2, else 0,
//
// r the distance from s to the nearest multiple of spacing, w = spacing·density/10000, and z
// the Dahl bristle of friction_test.cpp (the smooth sign of the direction of travel), plus
// the bristle's microdamping scaled by the bump (bristle_model.hpp).
#include "bristle_model.hpp"
#include "condition_fixture.hpp"

namespace feel::test {
namespace {

using Texture = ConditionFixture;

double presliding(double f) { return feel::test::presliding(f, kJoystickDamping, 1e-3, kJoystickStep); }

double bump(double s, double spacing, double density) {
    const double w = spacing * density / 10000;
    const double r = s - spacing * std::round(s / spacing);
    return std::fabs(r) <= w / 2 ? 0.5 * (1 + std::cos(2 * kPi * r / w)) : 0.0;
}

TEST_F(Texture, HandComputedBumps) {
    // spacing 400, density 5000: bumps 200 wide on every multiple of 400.
    EXPECT_DOUBLE_EQ(bump(800, 400, 5000), 1.0);
    EXPECT_DOUBLE_EQ(bump(850, 400, 5000), 0.5);
    EXPECT_DOUBLE_EQ(bump(1000, 400, 5000), 0.0);
    EXPECT_NEAR(bump(-50, 400, 5000), 0.5, 1e-12);
}

TEST_F(Texture, BothDirectionsOfTravelOnOneAxis) {
    // pos_roughness 7000, neg_roughness 2500, spacing 500, density 3000 (bumps 150 wide).
    play(texture({Axis::x}, 7000, 2500, 500, 3000));
    const double Z = presliding(7000);
    const double x0 = -8000, turn = 8000;
    const int out_ticks = 1600;  // 10 units per tick
    const double z_turn = bristle(0, turn - x0, Z);
    auto x_at = [&](int k) { return k <= out_ticks ? x0 + 10.0 * k : turn - 10.0 * (k - out_ticks); };
    expect_along(
        2 * out_ticks, [&](int k) { return Point{x_at(k), 0}; },
        [&](int k, int axis, const TickOutput& out) {
            if (axis != 0) return 0.0;
            const double x = x_at(k);
            const double z = k <= out_ticks ? bristle(0, x - x0, Z) : bristle(z_turn, x - turn, Z);
            const double b = bump(x, 500, 3000);
            return -(z >= 0 ? 7000 : 2500) * b * z + microdamping(7000 * b / Z, z, out.velocity[0]);
        },
        0.5);
}

TEST_F(Texture, FarFromTurningTheForceIsTheRoughnessOfTheDirectionTimesTheBump) {
    play(texture({Axis::y}, 6000, 3000, 1000, 8000));
    const double Z = presliding(6000);
    for (int k = 0; k <= 400; ++k) tick_at(0, -9000 + 10.0 * k);  // 4000 units toward +
    double z = bristle(0, 4000, Z);                                // 1 - 5e-4
    // Moving toward +y over a bump top (a multiple of 1000): -6000·z; in a gap: 0.
    z = bristle(z, 1000, Z);
    EXPECT_NEAR(tick_at(0, -4000).force[1], -6000 * z, 1e-2);
    EXPECT_NEAR(z, 1.0, 1e-4);
    EXPECT_NEAR(tick_at(0, -3500).force[1], 0.0, 1e-6);  // r = 500 > w/2 = 400: a gap
    z = bristle(z, 500, Z);
    for (int k = 0; k <= 400; ++k) tick_at(0, -3500 - 10.0 * k);  // turn, 4000 units toward -
    z = bristle(z, -4000, Z);
    z = bristle(z, -500, Z);
    EXPECT_NEAR(tick_at(0, -8000).force[1], -3000 * z, 1e-2);
    EXPECT_NEAR(z, -1.0, 1e-3);
    z = bristle(z, -200, Z);
    EXPECT_NEAR(tick_at(0, -8200).force[1], -3000 * bump(-8200, 1000, 8000) * z, 1e-2);
}

TEST_F(Texture, AnUpdateWhilePlayingTakesItsNewRoughnessAndGratingAtOnce) {
    // Sliding toward +y over bumps 800 wide every 1000, then the roughness, spacing and
    // density change in play (its state kept, §2.2 update without restart): the next ticks
    // feel the new grating, bumps 200 wide every 500, with the new roughness toward + and
    // the presliding distance of the larger one.
    const EffectId id = play(texture({Axis::y}, 6000, 3000, 1000, 8000));
    const double Z = presliding(6000);
    for (int k = 0; k <= 400; ++k) tick_at(0, -9000 + 10.0 * k);  // 4000 units toward +, to -5000
    double z = bristle(0, 4000, Z);
    ASSERT_TRUE(engine_->update(id, texture({Axis::y}, 2000, 3000, 500, 4000), effect_field::kTypeSpecific, false).ok());
    const double Z2 = presliding(3000);  // the bristle's f: the larger roughness
    for (int k = 1; k <= 125; ++k) {
        const double y = -5000 + 10.0 * k;
        z = bristle(z, 10, Z2);
        const TickOutput out = tick_at(0, y);
        const double b = bump(y, 500, 4000);
        ASSERT_NEAR(out.force[1], -2000 * b * z + microdamping(3000 * b / Z2, z, out.velocity[1]), 1e-2) << "y " << y;
    }
    // y = -3750 was on a bump of the old grating (0.35 of its top) and is in a gap of the new.
    EXPECT_GT(bump(-3750, 1000, 8000), 0.3);
    EXPECT_EQ(bump(-3750, 500, 4000), 0.0);
}

TEST_F(Texture, OnTwoAxesTheGratingRunsAlongItsDirection) {
    // polar 3000: the line u = (sin 30°, cos 30°). Motion across the line does not rub.
    EffectParams p = texture({Axis::x, Axis::y}, 5000, 5000, 600, 5000);
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = 3000;
    play(p);
    const double ux = 0.5, uy = std::sqrt(3.0) / 2;
    const double Z = presliding(5000);
    // Along the line from s = -6000, 8 units a tick.
    auto along_line = [&](int k) { return Point{(-6000 + 8.0 * k) * ux, (-6000 + 8.0 * k) * uy}; };
    auto expected = [&](double s, double z, const TickOutput& out) {
        const double b = bump(s, 600, 5000);
        return -5000 * b * z + microdamping(5000 * b / Z, z, out.velocity[0] * ux + out.velocity[1] * uy);
    };
    expect_along(1200, along_line, [&](int k, int axis, const TickOutput& out) {
        return expected(-6000 + 8.0 * k, bristle(0, 8.0 * k, Z), out) * (axis == 0 ? ux : uy);
    }, 0.5);
    // Across it (perpendicular, t = (cos 30°, -sin 30°)): s stays put, so does the bristle.
    // TickInput's float positions make s wobble by ~1e-3 units (the bump's slope turns that
    // into ~0.1 force units): that wobble is all that may change, once the velocity
    // estimate has caught up with the turn.
    const double s_end = -6000 + 8.0 * 1200, z_end = bristle(0, 8.0 * 1200, Z);
    const Point end = along_line(1200);
    for (int k = 1; k <= 300; ++k) {
        const TickOutput out = tick_at(end.x + 10.0 * k * uy, end.y - 10.0 * k * ux);
        ASSERT_NEAR(out.force[0], expected(s_end, z_end, out) * ux, 1.0) << k;
        ASSERT_NEAR(out.force[1], expected(s_end, z_end, out) * uy, 1.0) << k;
    }
}

TEST_F(Texture, ThePrimersWashboardRunsAlongY) {
    // §7.5: a texture on x, y with polar 0 lies along y; pulling the stick back (toward -y)
    // rubs over the bumps, moving sideways does not.
    EffectParams p = texture({Axis::x, Axis::y}, 8000, 8000, 2000, 5000);
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = 0;
    play(p);
    for (int k = 0; k < 500; ++k) {
        const TickOutput out = tick_at(-8000 + 30.0 * k, 0);
        ASSERT_EQ(out.force[0], 0.0f);
        ASSERT_EQ(out.force[1], 0.0f);
    }
    double strongest = 0;
    for (int k = 0; k < 600; ++k) strongest = std::max(strongest, static_cast<double>(tick_at(7000, -10.0 * k).force[1]));
    EXPECT_NEAR(strongest, 8000, 80);  // on a bump top, moving toward -y: pushed toward +y
}

TEST_F(Texture, AtRestNothingChanges) {
    play(texture({Axis::x}, 9000, 9000, 300, 9000));
    for (int k = 0; k < 300; ++k) tick_at(-2000 + 3.0 * k);
    for (int k = 0; k < 110; ++k) tick_at(-2000 + 3.0 * 300);  // the velocity estimate settles to 0
    const float held = tick_at(-2000 + 3.0 * 300).force[0];
    for (int k = 0; k < 300; ++k) ASSERT_EQ(tick_at(-2000 + 3.0 * 300).force[0], held);
}

}  // namespace
}  // namespace feel::test
