// §8.4 dynamic wrappers: the named parameters land in the DynamicBlock, and the engine,
// playing them, gets exactly the control law §8.4's mapping table names:
//
//   DynamicRecoil  BlastIntensity -> VelInit, DynamicMass -> Mass, BlastResonance -> KPos = KNeg,
//                  BlastDecay -> B
//   DynamicImpact  ImpactIntensity -> VelInit, DynamicMass -> Mass, Elasticity -> KPos = KNeg,
//                  CollisionAbsorption -> B
//   DynamicLiquid  Density -> Mass, Settle -> KPos = KNeg, Viscosity -> B
//   DynamicInertia Inertia -> Mass, Play -> Length
//   DynamicCenterDrift Stiffness -> KPos = KNeg
//
// The reference is a dynamic_control_law effect written out by hand from that table (and
// §8.4: "the intensity is decomposed into two single axis initial velocities"); both go
// through the engine's own mapping (tether_laws) and must give the same law. Blows from
// due east (9000) and due north (0) split the intensity onto one axis exactly. The law is
// float (issue 14: the control laws compute in single precision), so a value of the table
// is compared with the mapping to float's precision (EXPECT_FLOAT_EQ, 4 ulps): the
// mapping multiplies and divides in float, a rounding or two from the nearest float.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/tether_law.hpp"
#include "feel/iforce.hpp"
#include "iforce_test_util.hpp"

namespace feel::iforce {
namespace {

// The engine's mapping of host parameters, stored as a slot stores them.
int32_t tether_laws_of(const EffectParams& p, const EngineConfig& c, detail::TetherLaw laws[kMaxAxes]) {
    const detail::SlotDynamicBlock block = detail::slot_dynamic_block(p);
    return detail::tether_laws(detail::slot_params(p, &block), c, laws);
}

using test::engine_accepts;

// A control law on x and y, one block per axis, as §8.5 fills didynamic[0] and [1].
EffectParams control_law_xy(const ControlLawBlock& x, const ControlLawBlock& y) {
    EffectParams p;
    p.type = EffectType::dynamic_control_law;
    p.duration_us = kInfiniteUs;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.dynamic.control_law[0] = x;
    p.dynamic.control_law[1] = y;
    return p;
}

void expect_same_law(const EffectParams& named, const EffectParams& reference) {
    ASSERT_TRUE(engine_accepts(named));
    ASSERT_TRUE(engine_accepts(reference));
    const EngineConfig config;  // the joystick's scales; any config maps both alike
    detail::TetherLaw a[kMaxAxes];
    detail::TetherLaw b[kMaxAxes];
    ASSERT_EQ(tether_laws_of(named, config, a), tether_laws_of(reference, config, b));
    for (int i = 0; i < named.axis_count; ++i) {
        SCOPED_TRACE(i);
        EXPECT_DOUBLE_EQ(a[i].mass, b[i].mass);
        EXPECT_DOUBLE_EQ(a[i].k_pos, b[i].k_pos);
        EXPECT_DOUBLE_EQ(a[i].k_neg, b[i].k_neg);
        EXPECT_DOUBLE_EQ(a[i].b, b[i].b);
        // The split of the intensity goes through float sin/cos: exact to float precision.
        EXPECT_NEAR(a[i].vel_init, b[i].vel_init, 1e-6 * config.velocity_ref);
        EXPECT_DOUBLE_EQ(a[i].pos_init, b[i].pos_init);
        EXPECT_EQ(a[i].half_cycles, b[i].half_cycles);
        EXPECT_DOUBLE_EQ(a[i].length, b[i].length);
        EXPECT_DOUBLE_EQ(a[i].gravity, b[i].gravity);
    }
}

void expect_planar_untimed(const EffectParams& p) {
    ASSERT_EQ(p.axis_count, 2);
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.axes[1], Axis::y);
    EXPECT_EQ(p.direction.kind, DirectionKind::none);
    EXPECT_EQ(p.duration_us, kInfiniteUs);  // §8.5: dwDuration = INFINITE
    EXPECT_EQ(p.gain, 10000);
    EXPECT_EQ(p.trigger.kind, TriggerKind::none);
}

TEST(DynamicWrappers, DynamicImpactCarriesItsNamedParameters) {
    const EffectParams p = dynamic_impact(9000, 4000, 3000, 6000, 700);
    EXPECT_EQ(p.type, EffectType::dynamic_impact);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.impact_direction, 9000);
    EXPECT_EQ(p.dynamic.impact_intensity, 4000);
    EXPECT_EQ(p.dynamic.dynamic_mass, 3000);
    EXPECT_EQ(p.dynamic.elasticity, 6000);
    EXPECT_EQ(p.dynamic.collision_absorption, 700);
    EXPECT_FALSE(p.dynamic.interim_reporting);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(DynamicWrappers, DynamicImpactIsTheControlLawOfTheMappingTable) {
    // A blow from the east (9000) drives the mass toward -x: VelInit (-4000, 0).
    // Mass 3000, KPos = KNeg = Elasticity 6000, B = CollisionAbsorption 700, the rest 0.
    expect_same_law(dynamic_impact(9000, 4000, 3000, 6000, 700),
                    control_law_xy({3000, 6000, 6000, 700, -4000, 0, 0, 0, 0, 0},
                                   {3000, 6000, 6000, 700, 0, 0, 0, 0, 0, 0}));
    // From the north (0): toward -y.
    expect_same_law(dynamic_impact(0, 2500, 10000, 1, 0),
                    control_law_xy({10000, 1, 1, 0, 0, 0, 0, 0, 0, 0},
                                   {10000, 1, 1, 0, -2500, 0, 0, 0, 0, 0}));
}

TEST(DynamicWrappers, DynamicRecoilIsTheControlLawOfTheMappingTable) {
    const EffectParams p = dynamic_recoil(18000, 5000, 5000, 8000, 300);
    EXPECT_EQ(p.type, EffectType::dynamic_recoil);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.blast_direction, 18000);
    EXPECT_EQ(p.dynamic.blast_intensity, 5000);
    EXPECT_EQ(p.dynamic.dynamic_mass, 5000);
    EXPECT_EQ(p.dynamic.blast_resonance, 8000);
    EXPECT_EQ(p.dynamic.blast_decay, 300);
    // From the south (18000): the kick pushes toward +y.
    expect_same_law(p, control_law_xy({5000, 8000, 8000, 300, 0, 0, 0, 0, 0, 0},
                                      {5000, 8000, 8000, 300, 5000, 0, 0, 0, 0, 0}));
}

TEST(DynamicWrappers, DynamicLiquidMapsDensitySettleAndViscosity) {
    const EffectParams p = dynamic_liquid(4000, 1500, 600);
    EXPECT_EQ(p.type, EffectType::dynamic_liquid);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.density, 4000);
    EXPECT_EQ(p.dynamic.settle, 1500);
    EXPECT_EQ(p.dynamic.viscosity, 600);
    ASSERT_TRUE(engine_accepts(p));
    const EngineConfig c;
    detail::TetherLaw law[kMaxAxes];
    ASSERT_EQ(tether_laws_of(p, c, law), 2);
    for (int i = 0; i < 2; ++i) {
        EXPECT_FLOAT_EQ(law[i].mass, static_cast<float>(4000.0 / 10000 * c.dynamic_mass_ref));       // Density -> Mass
        EXPECT_FLOAT_EQ(law[i].k_pos, static_cast<float>(1500.0 / 10000 * c.dynamic_stiffness_ref));  // Settle -> KPos
        EXPECT_FLOAT_EQ(law[i].k_neg, law[i].k_pos);                              // = KNeg
        EXPECT_FLOAT_EQ(law[i].b, static_cast<float>(600.0 / 10000 * c.dynamic_damping_ref));         // Viscosity -> B
    }
}

TEST(DynamicWrappers, DynamicInertiaMapsInertiaAndPlay) {
    const EffectParams p = dynamic_inertia(7000, 400);
    EXPECT_EQ(p.type, EffectType::dynamic_inertia);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.inertia, 7000);
    EXPECT_EQ(p.dynamic.play, 400);
    ASSERT_TRUE(engine_accepts(p));
    const EngineConfig c;
    detail::TetherLaw law[kMaxAxes];
    tether_laws_of(p, c, law);
    for (int i = 0; i < 2; ++i) {
        EXPECT_FLOAT_EQ(law[i].mass, static_cast<float>(7000.0 / 10000 * c.dynamic_mass_ref));  // Inertia -> Mass
        EXPECT_FLOAT_EQ(law[i].length, 400.0f);                                // Play -> Length
    }
}

TEST(DynamicWrappers, DynamicCenterDriftMapsStiffness) {
    const EffectParams p = dynamic_center_drift(3000, 1500);
    EXPECT_EQ(p.type, EffectType::dynamic_center_drift);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.stiffness, 3000);
    EXPECT_EQ(p.dynamic.drift_resistance, 1500);
    ASSERT_TRUE(engine_accepts(p));
    const EngineConfig c;
    detail::TetherLaw law[kMaxAxes];
    tether_laws_of(p, c, law);
    for (int i = 0; i < 2; ++i) {
        EXPECT_FLOAT_EQ(law[i].k_pos, static_cast<float>(3000.0 / 10000 * c.dynamic_stiffness_ref));  // Stiffness -> KPos
        EXPECT_FLOAT_EQ(law[i].k_neg, law[i].k_pos);
        EXPECT_GT(law[i].drag, 0);  // DriftResistance -> Drag (on its own scale, docs/dynamics.md)
    }
}

TEST(DynamicWrappers, DynamicSlingCarriesTheBallAndString) {
    const EffectParams p = dynamic_sling(5000, 3000, 8000, 200, true);
    EXPECT_EQ(p.type, EffectType::dynamic_sling);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.ball_mass, 5000);
    EXPECT_EQ(p.dynamic.string_length, 3000);
    EXPECT_EQ(p.dynamic.string_compliance, 8000);
    EXPECT_EQ(p.dynamic.ball_damping, 200);
    EXPECT_TRUE(p.dynamic.interim_reporting);
    EXPECT_TRUE(engine_accepts(p));
    EXPECT_FALSE(dynamic_sling(5000, 3000, 8000, 200, false).dynamic.interim_reporting);
}

TEST(DynamicWrappers, DynamicPaddleCarriesTheBallAndItsVelocity) {
    const EffectParams p = dynamic_paddle(3000, 6000, 0, 5000, 250, 0, true);
    EXPECT_EQ(p.type, EffectType::dynamic_paddle);
    expect_planar_untimed(p);
    EXPECT_EQ(p.dynamic.ball_mass, 3000);
    EXPECT_EQ(p.dynamic.initial_velocity, 6000);
    EXPECT_EQ(p.dynamic.initial_velocity_direction, 0);
    EXPECT_EQ(p.dynamic.paddle_compliance, 5000);
    EXPECT_EQ(p.dynamic.paddle_damping, 250);
    EXPECT_EQ(p.dynamic.gravity, 0);
    EXPECT_TRUE(p.dynamic.interim_reporting);
    EXPECT_TRUE(engine_accepts(p));
    EXPECT_EQ(dynamic_paddle(1, -10000, 35999, 1, 10000, -10000, false).dynamic.gravity, -10000);
}

TEST(DynamicWrappers, DynamicControlLawFillsOneBlockOnOneAxis) {
    const EffectParams p = dynamic_control_law(2000, 3000, 4000, 500, -600, 700, 8, 900, 1000, -1100, true);
    EXPECT_EQ(p.type, EffectType::dynamic_control_law);
    ASSERT_EQ(p.axis_count, 1);
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.duration_us, kInfiniteUs);
    EXPECT_EQ(p.dynamic.control_law[0], (ControlLawBlock{2000, 3000, 4000, 500, -600, 700, 8, 900, 1000, -1100}));
    EXPECT_TRUE(p.dynamic.interim_reporting);
    EXPECT_TRUE(engine_accepts(p));

    const EffectParams y = dynamic_control_law(1, 1, 1, 0, 0, 0, 0, 0, 0, 0, false, Axis::y);
    ASSERT_EQ(y.axis_count, 1);
    EXPECT_EQ(y.axes[0], Axis::y);
    EXPECT_TRUE(engine_accepts(y));
}

}  // namespace
}  // namespace feel::iforce
