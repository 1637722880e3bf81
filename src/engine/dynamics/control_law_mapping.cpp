// The §8.4 table: every named dynamic but the sling and the paddle is the control law on
// one or more axes, with these parameters (docs/dynamics.md has the table with units):
//
//   recoil        BlastIntensity → VelInit (split over x, y by BlastDirection),
//                 DynamicMass → Mass, BlastResonance → KPos = KNeg, BlastDecay → B
//   impact        ImpactIntensity → VelInit (split by ImpactDirection), DynamicMass → Mass,
//                 Elasticity → KPos = KNeg, CollisionAbsorption → B
//   liquid        Density → Mass, Settle → KPos = KNeg, Viscosity → B
//   inertia       Inertia → Mass, Play → Length
//   center drift  Stiffness → KPos = KNeg, DriftResistance → Drag
//
// What the table leaves unmapped is 0, except where 0 would break the sensation §5 asks
// for (each choice is argued in docs/dynamics.md):
//   * liquid: Drag = Viscosity too. B alone resists only motion relative to the liquid's
//     mass, so a handle moving steadily would feel nothing; §5.5's viscosity is "the
//     resistance to motion ... High viscosity will feel like mud", which needs a drag.
//   * inertia: KPos = KNeg = 10000 (the stiffest tether the device holds stably, so the mass
//     follows the handle closely) and B for a damping ratio of 0.7 against a held handle,
//     so the mass does not ring on its tether: the handle feels weight, not a spring.
//     The mass is simulated in the handle's frame, driven by the handle's estimated
//     acceleration (control_law_dynamic.cpp): a tether this stiff driven by the sensed
//     counts and the estimated velocity jitters by far more than the inertial force it
//     carries (issue 16 §2). With play the same frame holds the gap: the stretch is the
//     mass's offset from the handle, free within ±Play. The mass, the tether and the play
//     are the table's.
//   * center drift: the origin is a mass of 1 (the lightest) held by the spring to the
//     handle and by the drag to the world. A light mass under heavy drag creeps: with M → 0,
//     d·ẋ = k·(p − x), the origin follows the handle with time constant d/k. A drag on
//     the Drag scale of the other dynamics (full force at a brisk hand speed) would make
//     that milliseconds, so DriftResistance has its own scale: 10000 is kDriftTime × the
//     stiffness of 10000, i.e. the time constant is kDriftTime · resistance / stiffness
//     (10 s at equal values). B damps the light mass critically so it cannot ring.
//
// Directions (§8.4, §8.5). The primer's sample code writes VelInit = Intensity·cos(angle)
// on x and ·sin(angle) on y, a mathematical angle. feel's angles are compass angles that
// name where a force comes from (docs/conventions.md), so the intensity is split along
// the direction the kick pushes: vel = −Intensity·(sin θ, cos θ) on (x, y). A recoil's
// mass (the weapon) kicks back away from where it fires, an impact's mass is driven away
// from where the blow comes from; either way the first pull on the handle comes from θ,
// like a constant force with polar direction θ. A negative intensity reverses it. On one
// axis the intensity's sign is the direction (§5.4's car hitting a wall, on a wheel); on
// x, y, z a spherical direction aims it the way it aims a wave (§5.10's 3D devices).
#include <cmath>

#include "direction.hpp"
#include "dynamics/dynamic_units.hpp"
#include "dynamics/tether_law.hpp"

namespace feel::detail {

namespace {

// Inertia: the tether's damping ratio against a held handle.
constexpr float kInertiaDampingRatio = 0.7f;
// Center drift: the origin's time constant at DriftResistance = Stiffness, s.
constexpr float kDriftTime_s = 10.0f;

// A law with both stiffnesses k and nothing else but a mass.
TetherLaw spring_law(float mass, float k) noexcept {
    TetherLaw law;
    law.mass = mass;
    law.k_pos = k;
    law.k_neg = k;
    return law;
}

// The initial velocity a directional dynamic gives effect axis i: the intensity along the
// push of a force that comes from the compass angle (polar_factors: −(sin θ, cos θ)).
// On one axis the intensity's sign is the direction: positive kicks toward +, like a
// positive constant force on that axis. On x, y, z the spherical direction aims it
// (direction_factors, as for a wave).
float kick_velocity(const SlotParams& p, const EngineConfig& c, int i, int32_t angle, int32_t intensity) noexcept {
    if (p.axis_count == 1) return dynamic_velocity<float>(c, intensity);
    float push[kMaxAxes] = {};
    if (p.direction.kind == DirectionKind::spherical) {
        direction_factors(p, push);
    } else {
        polar_factors(angle, push);
    }
    return dynamic_velocity<float>(c, intensity) * push[axis_index(p.axes[i])];
}

}  // namespace

int32_t tether_laws(const SlotParams& p, const EngineConfig& c, TetherLaw laws[kMaxAxes]) noexcept {
    const SlotDynamicBlock& d = *p.dynamic;
    for (int i = 0; i < p.axis_count; ++i) {
        TetherLaw& law = laws[i];
        switch (p.type) {
            case EffectType::dynamic_recoil:
                law = spring_law(dynamic_mass<float>(c, d.dynamic_mass),
                                 dynamic_stiffness<float>(c, d.blast_resonance));
                law.b = dynamic_damping<float>(c, d.blast_decay);
                law.vel_init = kick_velocity(p, c, i, d.blast_direction, d.blast_intensity);
                break;
            case EffectType::dynamic_impact:
                law = spring_law(dynamic_mass<float>(c, d.dynamic_mass), dynamic_stiffness<float>(c, d.elasticity));
                law.b = dynamic_damping<float>(c, d.collision_absorption);
                law.vel_init = kick_velocity(p, c, i, d.impact_direction, d.impact_intensity);
                break;
            case EffectType::dynamic_liquid:
                law = spring_law(dynamic_mass<float>(c, d.density), dynamic_stiffness<float>(c, d.settle));
                law.b = dynamic_damping<float>(c, d.viscosity);
                law.drag = law.b;
                break;
            case EffectType::dynamic_inertia:
                law = spring_law(dynamic_mass<float>(c, d.inertia), dynamic_stiffness<float>(c, kFullScale));
                law.b = 2 * kInertiaDampingRatio * std::sqrt(law.k_pos * law.mass);
                law.length = static_cast<float>(d.play);
                law.handle_frame = true;  // driven by −M·a (control_law_dynamic.cpp says why)
                break;
            case EffectType::dynamic_center_drift:
                law = spring_law(dynamic_mass<float>(c, 1), dynamic_stiffness<float>(c, d.stiffness));
                law.b = 2 * std::sqrt(law.k_pos * law.mass);
                law.drag = static_cast<float>(d.drift_resistance) / static_cast<float>(kFullScale) *
                           c.dynamic_stiffness_ref * kDriftTime_s;
                break;
            default: {  // dynamic_control_law: the block of this axis, as it is
                const SlotControlLawBlock& b = d.control_law[i];
                law.mass = dynamic_mass<float>(c, b.mass);
                law.k_pos = dynamic_stiffness<float>(c, b.k_pos);
                law.k_neg = dynamic_stiffness<float>(c, b.k_neg);
                law.b = dynamic_damping<float>(c, b.b);
                law.drag = dynamic_damping<float>(c, b.drag);
                law.gravity = dynamic_gravity<float>(c, b.gravity);
                law.length = static_cast<float>(b.length);
                law.pos_init = static_cast<float>(b.pos_init);
                law.vel_init = dynamic_velocity<float>(c, b.vel_init);
                law.half_cycles = b.half_cycles;
                break;
            }
        }
    }
    return p.axis_count;
}

}  // namespace feel::detail
