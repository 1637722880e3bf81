// §8.4 Dynamic function wrappers.
//
// feel keeps the primer's named parameters: a DynamicImpact is an effect of type
// dynamic_impact whose DynamicBlock holds ImpactDirection, ImpactIntensity, DynamicMass,
// Elasticity and CollisionAbsorption as given, and the engine maps them onto the control
// law by §8.4's table when it plays (src/engine/dynamics/control_law_mapping.cpp,
// docs/dynamics.md). So a wrapper does not do §8.5's decomposition into two DIDYNAMIC
// blocks itself: it would be done twice, and §8.5's own arithmetic (cos/sin of an angle in
// hundredths of a degree, a mathematical rather than a compass angle) is not feel's
// convention. Only DynamicControlLaw fills a control_law block directly.
//
// Every range is that of the control-law parameter the value maps to (§8.4's table);
// they equal the engine's (units.hpp), which checks them again.
#include "feel/iforce.hpp"
#include "wrapper_args.hpp"

namespace feel::iforce {
namespace {

using detail::Args;
using detail::on_axes;

EffectParams planar_dynamic(EffectType type) {
    return on_axes(type, {Axis::x, Axis::y});
}

}  // namespace

EffectParams dynamic_recoil(int32_t blast_direction, int32_t blast_intensity, int32_t dynamic_mass,
                            int32_t blast_resonance, int32_t blast_decay) {
    const Args args("dynamic_recoil");
    args.check("blast_direction", blast_direction, range::kAngle);
    args.check("blast_intensity", blast_intensity, range::kSignedLevel);  // VelInit
    args.check("dynamic_mass", dynamic_mass, range::kDynamicMass);       // Mass
    args.check("blast_resonance", blast_resonance, range::kDynamicStiffness);  // KPos = KNeg
    args.check("blast_decay", blast_decay, range::kLevel);               // B
    EffectParams p = planar_dynamic(EffectType::dynamic_recoil);
    p.dynamic.blast_direction = blast_direction;
    p.dynamic.blast_intensity = blast_intensity;
    p.dynamic.dynamic_mass = dynamic_mass;
    p.dynamic.blast_resonance = blast_resonance;
    p.dynamic.blast_decay = blast_decay;
    return args.finish(p);
}

EffectParams dynamic_impact(int32_t impact_direction, int32_t impact_intensity, int32_t dynamic_mass,
                            int32_t elasticity, int32_t collision_absorption) {
    const Args args("dynamic_impact");
    args.check("impact_direction", impact_direction, range::kAngle);
    args.check("impact_intensity", impact_intensity, range::kSignedLevel);  // VelInit
    args.check("dynamic_mass", dynamic_mass, range::kDynamicMass);         // Mass
    args.check("elasticity", elasticity, range::kDynamicStiffness);        // KPos = KNeg
    args.check("collision_absorption", collision_absorption, range::kLevel);  // B
    EffectParams p = planar_dynamic(EffectType::dynamic_impact);
    p.dynamic.impact_direction = impact_direction;
    p.dynamic.impact_intensity = impact_intensity;
    p.dynamic.dynamic_mass = dynamic_mass;
    p.dynamic.elasticity = elasticity;
    p.dynamic.collision_absorption = collision_absorption;
    return args.finish(p);
}

EffectParams dynamic_liquid(int32_t density, int32_t settle, int32_t viscosity) {
    const Args args("dynamic_liquid");
    args.check("density", density, range::kDynamicMass);        // Mass
    args.check("settle", settle, range::kDynamicStiffness);     // KPos = KNeg
    args.check("viscosity", viscosity, range::kLevel);          // B
    EffectParams p = planar_dynamic(EffectType::dynamic_liquid);
    p.dynamic.density = density;
    p.dynamic.settle = settle;
    p.dynamic.viscosity = viscosity;
    return args.finish(p);
}

EffectParams dynamic_inertia(int32_t inertia, int32_t play) {
    const Args args("dynamic_inertia");
    args.check("inertia", inertia, range::kDynamicMass);  // Mass
    args.check("play", play, range::kLevel);              // Length
    EffectParams p = planar_dynamic(EffectType::dynamic_inertia);
    p.dynamic.inertia = inertia;
    p.dynamic.play = play;
    return args.finish(p);
}

EffectParams dynamic_center_drift(int32_t stiffness, int32_t drift_resistance) {
    const Args args("dynamic_center_drift");
    args.check("stiffness", stiffness, range::kDynamicStiffness);   // KPos = KNeg
    args.check("drift_resistance", drift_resistance, range::kLevel);  // Drag
    EffectParams p = planar_dynamic(EffectType::dynamic_center_drift);
    p.dynamic.stiffness = stiffness;
    p.dynamic.drift_resistance = drift_resistance;
    return args.finish(p);
}

EffectParams dynamic_sling(int32_t ball_mass, int32_t string_length, int32_t string_compliance,
                           int32_t ball_damping, bool interim_reporting) {
    const Args args("dynamic_sling");
    args.check("ball_mass", ball_mass, range::kDynamicMass);                   // Mass
    args.check("string_length", string_length, range::kLevel);                 // Length
    args.check("string_compliance", string_compliance, range::kDynamicStiffness);  // KPos = KNeg
    args.check("ball_damping", ball_damping, range::kLevel);                   // Drag
    EffectParams p = planar_dynamic(EffectType::dynamic_sling);
    p.dynamic.ball_mass = ball_mass;
    p.dynamic.string_length = string_length;
    p.dynamic.string_compliance = string_compliance;
    p.dynamic.ball_damping = ball_damping;
    p.dynamic.interim_reporting = interim_reporting;
    return args.finish(p);
}

EffectParams dynamic_paddle(int32_t ball_mass, int32_t initial_velocity, int32_t initial_velocity_direction,
                            int32_t paddle_compliance, int32_t paddle_damping, int32_t gravity,
                            bool interim_reporting) {
    const Args args("dynamic_paddle");
    args.check("ball_mass", ball_mass, range::kDynamicMass);                  // Mass
    args.check("initial_velocity", initial_velocity, range::kSignedLevel);    // VelInit
    args.check("initial_velocity_direction", initial_velocity_direction, range::kAngle);
    args.check("paddle_compliance", paddle_compliance, range::kDynamicStiffness);  // KPos = KNeg
    args.check("paddle_damping", paddle_damping, range::kLevel);              // B
    args.check("gravity", gravity, range::kSignedLevel);                      // Gravity
    EffectParams p = planar_dynamic(EffectType::dynamic_paddle);
    p.dynamic.ball_mass = ball_mass;
    p.dynamic.initial_velocity = initial_velocity;
    p.dynamic.initial_velocity_direction = initial_velocity_direction;
    p.dynamic.paddle_compliance = paddle_compliance;
    p.dynamic.paddle_damping = paddle_damping;
    p.dynamic.gravity = gravity;
    p.dynamic.interim_reporting = interim_reporting;
    return args.finish(p);
}

EffectParams dynamic_control_law(int32_t mass, int32_t k_pos, int32_t k_neg, int32_t b, int32_t vel_init,
                                 int32_t pos_init, int32_t half_cycles, int32_t length, int32_t drag,
                                 int32_t gravity, bool interim_reporting, Axis axis) {
    const Args args("dynamic_control_law");
    args.check("mass", mass, range::kDynamicMass);
    args.check("k_pos", k_pos, range::kDynamicStiffness);
    args.check("k_neg", k_neg, range::kDynamicStiffness);
    args.check("b", b, range::kLevel);
    args.check("vel_init", vel_init, range::kSignedLevel);
    args.check("pos_init", pos_init, range::kSignedLevel);
    args.check("half_cycles", half_cycles, range::kHalfCycles);
    args.check("length", length, range::kLevel);
    args.check("drag", drag, range::kLevel);
    args.check("gravity", gravity, range::kSignedLevel);
    args.check("axis", static_cast<int64_t>(axis), Range{0, kMaxAxes - 1});
    EffectParams p = on_axes(EffectType::dynamic_control_law, {axis});
    p.dynamic.control_law[0] =
        ControlLawBlock{mass, k_pos, k_neg, b, vel_init, pos_init, half_cycles, length, drag, gravity};
    p.dynamic.interim_reporting = interim_reporting;
    return args.finish(p);
}

}  // namespace feel::iforce
