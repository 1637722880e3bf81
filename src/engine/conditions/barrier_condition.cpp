// Barriers (§3.8, §6.6.g): axis_barrier and angle_barrier, a two-sided penetrable surface.
//
// Geometry (contact_surface.hpp): s = position·u; the barrier is a slab of the given
// thickness t centered on s = c (§8.2: "location of center of barrier"), with faces at
// c − t/2 and c + t/2, where, as for the wall (§3.8: the Offset-Flag is "same as the wall"),
//
//     c = offset                         offset_mode absolute (from the center of travel)
//     c = start_position·u + offset      offset_mode relative (from where the handle was
//                                        when the effect began playing)
//
// ContactState remembers two things:
//
//     side      which side of the center the handle is on, −1 or +1;
//     crossing  while the handle is inside the slab, the direction it entered in: +1 if
//               it came in from the negative side moving in +u, −1 from the positive side.
//
// Hardness follows the crossing: "a positive hardness and a negative hardness which define
// the feel of the barrier depending upon which direction you are crossing it" (§3.8).
// A crossing in +u feels pos_hardness from the moment the handle enters until it leaves
// the slab, on either side; a crossing in −u feels neg_hardness.
//
// Force, with K the crossing's hardness/10000 · EngineConfig::wall_stiffness, saturated
// at full scale:
//
//     side −1: F = −clamp(K·(s − (offset − t/2)))   pushes back out of the negative face
//     side +1: F = +clamp(K·((offset + t/2) − s))   pushes out of the positive face
//
// Pop-through (Figure 3-13): when the handle has pushed in past half the thickness, i.e.
// past the center, its side flips. The force, K·t/2 against the motion just before, is
// K·t/2 along it just after: it flips direction and pushes the handle on through and out
// of the far face. Coming back from the other side works the same way. The side starts as
// the side of the center the handle is on at the effect's first tick. Within one crossing
// the force is the slope of a tent-shaped potential of height K·t²/8, and K changes only
// outside the slab where the potential is zero, so the barrier is conservative: a pop
// returns exactly what pushing in stored, whatever the two hardnesses.
//
// Passivity: the port observer and controller (passivity.hpp) watch the barrier like a
// wall, with the tent as the ideal element's energy; over a tick in which the handle
// popped through, the ideal work is split at the center, so the controller does not
// mistake the designed pop for generated energy.
//
// Surface friction and texture: pressure mode along the barrier's surface while the
// handle presses on a face (contact_surface.hpp).
#include <cmath>

#include "conditions/condition.hpp"
#include "conditions/contact_surface.hpp"
#include "conditions/passivity.hpp"

namespace feel::detail {
namespace {

// The out-of-contact way below costs about 100 bytes of Thumb code in the barrier: a build
// for size (the Cortex-M4F firmware, whose flash is at its goal) leaves it out, as friction's
// lean way, and every tick takes the general way, which gives the same force (the wall keeps
// its way everywhere: docs/tick-cost.md, "Walls and barriers out of contact").
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool kBarrierOutOfContactWay = false;
#else
inline constexpr bool kBarrierOutOfContactWay = true;
#endif

// The face that holds a handle on one side: its stiffness (the crossing's), the direction
// of travel into it along u, and its coordinate.
struct Face {
    float k = 0;        // force units per position unit
    float into = 1;     // +1: the negative side's face, entered moving in +u; −1 otherwise
    float surface = 0;  // the face's coordinate along u
};

Face face_of(const BarrierBlock& barrier, float center, const EngineConfig& config, int side,
             int crossing) noexcept {
    const float half = 0.5f * static_cast<float>(barrier.thickness);
    const float k = element_stiffness(config, crossing > 0 ? barrier.pos_hardness : barrier.neg_hardness);
    if (side < 0) return {k, 1.0f, center - half};
    return {k, -1.0f, center + half};
}

float face_depth(const Face& f, float s) noexcept { return f.into * (s - f.surface); }

// The ideal energy change from the handle at `from` against face `before` to `to` against
// `after` (the same face, or one of another hardness where the tent is zero). One
// difference when the faces are alike, so the rounding is the change's, not the energy's
// (passivity.hpp).
float face_energy_change(const Face& before, float from, const Face& after, float to) noexcept {
    if (before.k == after.k && before.into == after.into && before.surface == after.surface) {
        return saturated_spring_energy_change(after.k, face_depth(before, from), face_depth(after, to));
    }
    return saturated_spring_energy(after.k, face_depth(after, to)) -
           saturated_spring_energy(before.k, face_depth(before, from));
}

}  // namespace

void barrier_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const BarrierBlock& barrier = c.params->barrier;
    const float* u = c.direction;  // across the surface (element_direction)
    const float s = along(c, u, c.position);
    const float center = static_cast<float>(barrier.offset) +
                         (barrier.offset_mode == OffsetMode::relative ? along(c, u, c.start_position) : 0.0f);

    ContactState& state = c.state->contact;
    if (state.side == 0) state.side = s >= center ? 1 : -1;
    const int previous_side = state.side;
    const int previous_crossing = state.crossing != 0 ? state.crossing : -state.side;
    const float half = 0.5f * static_cast<float>(barrier.thickness);
    const bool inside = std::fabs(s - center) < half;
    if (!inside) state.crossing = 0;
    else if (state.crossing == 0) state.crossing = static_cast<int8_t>(-state.side);  // entered from this side
    if (state.side < 0 && s > center) state.side = 1;        // pushed past half the thickness
    else if (state.side > 0 && s < center) state.side = -1;  // from the other side
    const int crossing = state.crossing != 0 ? state.crossing : -state.side;

    // Out of the slab on the same side on both ticks (most of a barrier's ticks): the face
    // holds nothing and the tent is zero at both ends, whatever the hardness, so there is
    // no spring to evaluate, nothing to book and nothing to rub (passivity.hpp).
    float pressure = 0;
    if (!kBarrierOutOfContactWay || state.side != previous_side ||
        !port_out_of_contact(state, s, state.side < 0 ? 1.0f : -1.0f, state.side < 0 ? center - half : center + half)) {
        // The ideal energy change since the last tick: the tent of the crossing, split at the
        // center if the handle popped through. Outside the slab the tent is zero whatever its
        // hardness, so a new crossing's hardness changes nothing that was stored.
        const Face face = face_of(barrier, center, *c.config, state.side, crossing);
        const Face before = face_of(barrier, center, *c.config, previous_side, previous_crossing);
        float ideal_energy_change = 0;
        if (state.side == previous_side) {
            ideal_energy_change = face_energy_change(before, state.coordinate, face, s);
        } else {
            const Face before_at_center = face_of(barrier, center, *c.config, previous_side, crossing);
            ideal_energy_change = face_energy_change(before, state.coordinate, before_at_center, center) +
                                  face_energy_change(face, center, face, s);
        }

        pressure = press_port(state, s, ideal_energy_change, face.into * saturated_spring_force(face.k, face_depth(face, s)),
                              face.k, along(c, u, c.velocity), c.dt_s, c.config->sensor_step,
                              c.config->passivity_control);
    }
    // The force along u to command, passive_port_force's or port_out_of_contact's zero.
    const float normal_force = state.force;
    add_force_along(c, u, normal_force, force);

    add_rubbing_force(c, pressure, barrier.surface_friction, barrier.surface_texture, force);
}

}  // namespace feel::detail
