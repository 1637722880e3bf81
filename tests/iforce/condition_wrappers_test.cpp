// §8.2 condition wrappers against §8.2's definitions and §8.5's sample code: which effect
// type, which axes, what goes into each DICONDITION / DITEXTURE / DIWALL / DIBARRIER field.
#include <gtest/gtest.h>

#include "feel/iforce.hpp"
#include "iforce_test_util.hpp"

namespace feel::iforce {
namespace {

using test::engine_accepts;

// §8.5 XSpring: one DICONDITION {lOffset, lPositiveCoefficient, lNegativeCoefficient,
// dwPositiveSaturation, dwNegativeSaturation, lDeadBand} on DIJOFS_X, duration INFINITE.
void expect_block(const ConditionBlock& c, int32_t pos, int32_t neg, int32_t offset, int32_t pos_sat,
                  int32_t neg_sat, int32_t deadband, OffsetMode mode = OffsetMode::absolute) {
    EXPECT_EQ(c.pos_coefficient, pos);
    EXPECT_EQ(c.neg_coefficient, neg);
    EXPECT_EQ(c.offset, offset);
    EXPECT_EQ(c.pos_saturation, pos_sat);
    EXPECT_EQ(c.neg_saturation, neg_sat);
    EXPECT_EQ(c.deadband, deadband);
    EXPECT_EQ(c.offset_mode, mode);
}

void expect_untimed(const EffectParams& p) {
    EXPECT_EQ(p.duration_us, kInfiniteUs);  // dieffect.dwDuration = INFINITE
    EXPECT_EQ(p.start_delay_us, 0);
    EXPECT_EQ(p.gain, 10000);               // dieffect.dwGain = 10000
    EXPECT_EQ(p.iterations, 1);
    EXPECT_EQ(p.trigger.kind, TriggerKind::none);  // DIEB_NOTRIGGER
    EXPECT_EQ(p.trigger_repeat_interval_us, 0);
    EXPECT_FALSE(p.has_envelope);                   // lpEnvelope = NULL
}

void expect_axes(const EffectParams& p, std::initializer_list<Axis> axes) {
    ASSERT_EQ(p.axis_count, static_cast<int32_t>(axes.size()));
    int i = 0;
    for (Axis a : axes) EXPECT_EQ(p.axes[i++], a) << "axis " << i - 1;
}

TEST(ConditionWrappers, XSpringIsOneSpringBlockOnX) {
    const EffectParams p = x_spring(1000, 2000, -300, 9000, 8000, 150);
    EXPECT_EQ(p.type, EffectType::spring);
    expect_axes(p, {Axis::x});
    EXPECT_EQ(p.direction.kind, DirectionKind::none);  // conditions use no direction
    expect_block(p.conditions[0], 1000, 2000, -300, 9000, 8000, 150);
    expect_untimed(p);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, YSpringIsTheSameOnY) {
    const EffectParams p = y_spring(-500, 700, 2500, 10000, 0, 10000);
    EXPECT_EQ(p.type, EffectType::spring);
    expect_axes(p, {Axis::y});
    expect_block(p.conditions[0], -500, 700, 2500, 10000, 0, 10000);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, SpringHasAnXBlockThenAYBlock) {
    const EffectParams p = spring(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12);
    EXPECT_EQ(p.type, EffectType::spring);
    expect_axes(p, {Axis::x, Axis::y});
    expect_block(p.conditions[0], 1, 2, 3, 4, 5, 6);
    expect_block(p.conditions[1], 7, 8, 9, 10, 11, 12);
    expect_untimed(p);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, AngleSpringCarriesItsAngleAsAPolarDirection) {
    const EffectParams p = angle_spring(3000, 2000, 100, 7000, 6000, 50, 4500);
    EXPECT_EQ(p.type, EffectType::angle_spring);
    expect_axes(p, {Axis::x, Axis::y});
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], 4500);
    expect_block(p.conditions[0], 3000, 2000, 100, 7000, 6000, 50);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, CenterSpringIsSymmetricOnBothAxesAroundTheCenter) {
    // §8.5 CenterSpring: both blocks lOffset 0, both coefficients Stiffness, both
    // saturations Saturation, deadband DeadBand.
    const EffectParams p = center_spring(4000, 6000, 250);
    EXPECT_EQ(p.type, EffectType::spring);
    expect_axes(p, {Axis::x, Axis::y});
    expect_block(p.conditions[0], 4000, 4000, 0, 6000, 6000, 250);
    expect_block(p.conditions[1], 4000, 4000, 0, 6000, 6000, 250);
    expect_untimed(p);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, SpringAtCurrentLocationCentersOnTheStartPosition) {
    // §8.2: "returning to location of device when command is called": a relative offset 0.
    const EffectParams p = spring_at_current_location(4000, 6000, 250);
    EXPECT_EQ(p.type, EffectType::spring);
    expect_axes(p, {Axis::x, Axis::y});
    expect_block(p.conditions[0], 4000, 4000, 0, 6000, 6000, 250, OffsetMode::relative);
    expect_block(p.conditions[1], 4000, 4000, 0, 6000, 6000, 250, OffsetMode::relative);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, DampersMirrorTheSprings) {
    const EffectParams x = x_damper(100, 200, -50, 3000, 4000, 10);
    EXPECT_EQ(x.type, EffectType::damper);
    expect_axes(x, {Axis::x});
    expect_block(x.conditions[0], 100, 200, -50, 3000, 4000, 10);
    expect_untimed(x);
    EXPECT_TRUE(engine_accepts(x));

    const EffectParams y = y_damper(100, 200, -50, 3000, 4000, 10);
    EXPECT_EQ(y.type, EffectType::damper);
    expect_axes(y, {Axis::y});
    expect_block(y.conditions[0], 100, 200, -50, 3000, 4000, 10);
    EXPECT_TRUE(engine_accepts(y));

    const EffectParams both = damper(-1, -2, -3, 4, 5, 6, 7, 8, 9, 10, 11, 12);
    EXPECT_EQ(both.type, EffectType::damper);
    expect_axes(both, {Axis::x, Axis::y});
    expect_block(both.conditions[0], -1, -2, -3, 4, 5, 6);
    expect_block(both.conditions[1], 7, 8, 9, 10, 11, 12);
    EXPECT_TRUE(engine_accepts(both));
}

TEST(ConditionWrappers, InertiaIsAMassTheSameBothWays) {
    // §8.5 XInertia: lOffset 0, both coefficients Mass, both saturations Saturation, no deadband.
    const EffectParams x = x_inertia(2500, 7000);
    EXPECT_EQ(x.type, EffectType::inertia);
    expect_axes(x, {Axis::x});
    expect_block(x.conditions[0], 2500, 2500, 0, 7000, 7000, 0);
    expect_untimed(x);
    EXPECT_TRUE(engine_accepts(x));

    const EffectParams y = y_inertia(2500, 7000);
    expect_axes(y, {Axis::y});
    expect_block(y.conditions[0], 2500, 2500, 0, 7000, 7000, 0);
    EXPECT_TRUE(engine_accepts(y));

    const EffectParams both = inertia(1, 1);
    EXPECT_EQ(both.type, EffectType::inertia);
    expect_axes(both, {Axis::x, Axis::y});
    expect_block(both.conditions[0], 1, 1, 0, 1, 1, 0);
    expect_block(both.conditions[1], 1, 1, 0, 1, 1, 0);
    EXPECT_TRUE(engine_accepts(both));
}

TEST(ConditionWrappers, FrictionForcesPerDirection) {
    const EffectParams both = friction(3000);
    EXPECT_EQ(both.type, EffectType::friction);
    expect_axes(both, {Axis::x, Axis::y});
    // "friction force in both directions": both coefficients F, nothing capping it below F.
    expect_block(both.conditions[0], 3000, 3000, 0, 10000, 10000, 0);
    expect_block(both.conditions[1], 3000, 3000, 0, 10000, 10000, 0);
    expect_untimed(both);
    EXPECT_TRUE(engine_accepts(both));

    const EffectParams x = x_friction(1000, 0);
    EXPECT_EQ(x.type, EffectType::friction);
    expect_axes(x, {Axis::x});
    expect_block(x.conditions[0], 1000, 0, 0, 10000, 10000, 0);
    EXPECT_TRUE(engine_accepts(x));

    const EffectParams y = y_friction(0, 10000);
    expect_axes(y, {Axis::y});
    expect_block(y.conditions[0], 0, 10000, 0, 10000, 10000, 0);
    EXPECT_TRUE(engine_accepts(y));
}

TEST(ConditionWrappers, TextureAtAnAngleIsSymmetricAlongThatLine) {
    // §8.5 Texture: cAxes 2, rglDirection[0] = Angle, dwPosRoughness = dwNegRoughness =
    // Roughness, dwSpacing, dwDensity.
    const EffectParams p = texture(5000, 2000, 7500, 9000);
    EXPECT_EQ(p.type, EffectType::texture);
    expect_axes(p, {Axis::x, Axis::y});
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], 9000);
    EXPECT_EQ(p.texture.pos_roughness, 5000);
    EXPECT_EQ(p.texture.neg_roughness, 5000);
    EXPECT_EQ(p.texture.spacing, 2000);
    EXPECT_EQ(p.texture.density, 7500);
    expect_untimed(p);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, AxisTexturesTakeOneOrTwoRoughnesses) {
    const EffectParams sym = x_texture(4000, 300, 5000);
    EXPECT_EQ(sym.type, EffectType::texture);
    expect_axes(sym, {Axis::x});
    EXPECT_EQ(sym.direction.kind, DirectionKind::none);
    EXPECT_EQ(sym.texture, (TextureBlock{4000, 4000, 300, 5000}));
    EXPECT_TRUE(engine_accepts(sym));

    const EffectParams x = x_texture(4000, 1000, 300, 5000);
    expect_axes(x, {Axis::x});
    EXPECT_EQ(x.texture, (TextureBlock{4000, 1000, 300, 5000}));
    EXPECT_TRUE(engine_accepts(x));

    const EffectParams y = y_texture(1, 10000, 10000, 1);
    EXPECT_EQ(y.type, EffectType::texture);
    expect_axes(y, {Axis::y});
    EXPECT_EQ(y.texture, (TextureBlock{1, 10000, 10000, 1}));
    EXPECT_TRUE(engine_accepts(y));
}

TEST(ConditionWrappers, WallAtAnAngleIsAnAngleWall) {
    // §8.5 Wall: DIFORCE_ANGLEWALL, diwall.dwK = Hardness, dwSense, lOffset, angle.
    const EffectParams p = wall(8000, WallSense::negative, -2000, 13500);
    EXPECT_EQ(p.type, EffectType::angle_wall);
    expect_axes(p, {Axis::x, Axis::y});
    EXPECT_EQ(p.direction.kind, DirectionKind::none);  // the angle lives in the block
    EXPECT_EQ(p.wall.hardness, 8000);
    EXPECT_EQ(p.wall.sense, WallSense::negative);
    EXPECT_EQ(p.wall.offset, -2000);
    EXPECT_EQ(p.wall.angle, 13500);
    EXPECT_EQ(p.wall.offset_mode, OffsetMode::absolute);
    EXPECT_EQ(p.wall.surface_friction, 0);
    EXPECT_EQ(p.wall.surface_texture, 0);
    EXPECT_FALSE(p.wall.clipping);
    expect_untimed(p);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(ConditionWrappers, AHorizontalWallIsTheLineYEqualsOffsetFeltAlongY) {
    const EffectParams h = horizontal_wall(6000, WallSense::positive, 5000, 300, 400, true);
    EXPECT_EQ(h.type, EffectType::axis_wall);
    expect_axes(h, {Axis::y});
    EXPECT_EQ(h.wall.hardness, 6000);
    EXPECT_EQ(h.wall.sense, WallSense::positive);
    EXPECT_EQ(h.wall.offset, 5000);
    EXPECT_EQ(h.wall.angle, 0);
    EXPECT_EQ(h.wall.surface_friction, 300);
    EXPECT_EQ(h.wall.surface_texture, 400);
    EXPECT_TRUE(h.wall.clipping);
    EXPECT_TRUE(engine_accepts(h));

    const EffectParams v = vertical_wall(-6000, WallSense::negative, -5000, 0, 10000, false);
    EXPECT_EQ(v.type, EffectType::axis_wall);
    expect_axes(v, {Axis::x});
    EXPECT_EQ(v.wall.hardness, -6000);
    EXPECT_EQ(v.wall.sense, WallSense::negative);
    EXPECT_EQ(v.wall.offset, -5000);
    EXPECT_EQ(v.wall.surface_texture, 10000);
    EXPECT_FALSE(v.wall.clipping);
    EXPECT_TRUE(engine_accepts(v));
}

TEST(ConditionWrappers, BarriersCarryBothHardnessesAndTheirThickness) {
    // §8.5 Barrier: DIFORCE_ANGLEBARRIER, dwKPos, dwKNeg, dwThickness, lOffset, angle.
    const EffectParams a = barrier(7000, 3000, 800, 1000, 27000);
    EXPECT_EQ(a.type, EffectType::angle_barrier);
    expect_axes(a, {Axis::x, Axis::y});
    EXPECT_EQ(a.barrier, (BarrierBlock{7000, 3000, 800, 1000, 27000, 0, 0}));
    expect_untimed(a);
    EXPECT_TRUE(engine_accepts(a));

    const EffectParams h = horizontal_barrier(7000, 3000, 800, 1000, 200, 100);
    EXPECT_EQ(h.type, EffectType::axis_barrier);
    expect_axes(h, {Axis::y});
    EXPECT_EQ(h.barrier, (BarrierBlock{7000, 3000, 800, 1000, 0, 200, 100}));
    EXPECT_TRUE(engine_accepts(h));

    const EffectParams v = vertical_barrier(-7000, 10000, 10000, -10000, 10000, 0);
    EXPECT_EQ(v.type, EffectType::axis_barrier);
    expect_axes(v, {Axis::x});
    EXPECT_EQ(v.barrier, (BarrierBlock{-7000, 10000, 10000, -10000, 0, 10000, 0}));
    EXPECT_TRUE(engine_accepts(v));
}

}  // namespace
}  // namespace feel::iforce
