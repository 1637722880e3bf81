// Walls (§3.7, §6.6.h): axis_wall and angle_wall, a one-sided hard stop.
//
// Geometry (contact_surface.hpp): the wall is the surface s = s_w across the direction u,
// s = position·u, with
//
//     s_w = offset                       offset_mode absolute (from the center of travel)
//     s_w = start_position·u + offset    offset_mode relative (from where the handle was
//                                        when the effect began playing, §3.7 Offset-Flag)
//
// Sense, as §3.7 defines it: "a wall with positive sense will resist crossing of the wall
// when moving in a positive direction". So
//
//     positive: the free side is s < s_w, the solid is s > s_w; depth p = s − s_w
//     negative: the free side is s > s_w, the solid is s < s_w; depth p = s_w − s
//
// (§8.2's "wall on left or right of location": positive puts the wall on the positive
// side of its location.) For an axis_wall on x with positive sense and offset 3000, the
// handle moves freely left of x = 3000 and meets the wall moving right.
//
// Force: a spring on the depth, saturated at the motor's full scale,
//
//     F = −clamp(K·p, ±10000)   along the direction into the solid, while p > 0
//     K = hardness/10000 · EngineConfig::wall_stiffness
//
// so positive hardness pushes the handle out; a negative hardness pulls it in (the
// primer's sign convention for every coefficient). wall_stiffness maps each device
// profile's hardness to a physical stiffness; docs/stability.md gives the numbers and the
// passivity bound they are measured against.
//
// Passivity: the force passes through the port's observer and controller
// (passivity.hpp) when EngineConfig::passivity_control is on, so a wall stiffer than the
// sampled-data bound K ≤ 2b/T still settles.
//
// Surface friction and texture act in pressure mode, scaled by the wall's normal force
// (contact_surface.hpp), along the surface's tangent directions.
//
// Clipping (§3.7): while the reported position lies inside the solid it is moved back onto
// the surface along u (for the horizontal and vertical walls, axis walls and angle walls at
// 0/9000/18000/27000, that holds the one axis at the surface and leaves the others alone;
// at other angles it is the projection onto the wall line). The reported position starts
// each tick as the sensed one, so clipping walls act in turn and two walls meeting at a
// right angle clip the handle into their corner.
#include <cmath>

#include "conditions/condition.hpp"
#include "conditions/contact_surface.hpp"
#include "conditions/passivity.hpp"
#include "float_round.hpp"

namespace feel::detail {

void wall_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const WallBlock& wall = c.params->wall;
    const float* u = c.direction;  // across the surface (element_direction)
    const float s = along(c, u, c.position);
    const float surface = static_cast<float>(wall.offset) +
                          (wall.offset_mode == OffsetMode::relative ? along(c, u, c.start_position) : 0.0f);
    const float into = wall.sense == WallSense::positive ? 1.0f : -1.0f;  // along u, into the solid
    ContactState& state = c.state->contact;

    float pressure = 0;
    // Free on both ticks (most of a wall's ticks): no spring, no ledger, no rubbing.
    if (!port_out_of_contact(state, s, into, surface)) {
        const float k = element_stiffness(*c.config, wall.hardness);
        const float depth = into * (s - surface);
        const float energy_change = saturated_spring_energy_change(k, into * (state.coordinate - surface), depth);
        pressure = press_port(state, s, energy_change, into * saturated_spring_force(k, depth), k, along(c, u, c.velocity),
                              c.dt_s, c.config->sensor_step, c.config->passivity_control);
    }
    // The force along u to command: passive_port_force's, or port_out_of_contact's zero.
    const float normal_force = state.force;
    add_force_along(c, u, normal_force, force);

    if (pressure > 0) add_rubbing_force(c, pressure, wall.surface_friction, wall.surface_texture, force);

    if (wall.clipping) {
        const float reported_depth = into * (along(c, u, c.reported_position) - surface);
        if (reported_depth > 0) {
            float clipped[kMaxAxes];  // (u is 0 beyond the device's axes: nothing to move there)
            for (int a = 0; a < condition_lanes(c); ++a) {
                clipped[a] = c.reported_position[a] - into * reported_depth * u[a];
            }
            // The projection is rounded: if it still reads inside, step the moved
            // coordinates an ulp toward the free side (once: each further step would only
            // chase the rounding of the test itself away from the surface).
            if (into * (along(c, u, clipped) - surface) > 0) {
                for (int a = 0; a < condition_lanes(c); ++a) {
                    if (u[a] == 0) continue;
                    clipped[a] = next_float(clipped[a], -into * u[a] > 0);
                }
            }
            for (int a = 0; a < condition_lanes(c); ++a) {
                if (u[a] != 0) c.reported_position[a] = clipped[a];
            }
        }
    }
}

}  // namespace feel::detail
