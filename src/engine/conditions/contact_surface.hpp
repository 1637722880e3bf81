// The geometry shared by walls and barriers, and the rubbing felt along their surface.
//
// Geometry. A wall or barrier is a flat surface in the device's space. Its direction u is
// a unit vector across the surface: the effect's single axis for axis_wall/axis_barrier,
// or, for angle_wall/angle_barrier on x and y, the compass direction of the block's angle,
//
//     u = (sin a, cos a)   (a clockwise from north = +y: 0 → +y, 9000 → +x)
//
// so that the offset is the primer's "radial distance along a radius" at that angle
// (§6.6.h): the surface is the line s = offset, s = position·u. The angles 0, 9000, 18000
// and 27000 give exact axis vectors, so angle walls there are exactly the horizontal and
// vertical walls. The surface's tangent directions are the rest of the device's axes:
// for an axis element every other device axis, for an angle element the in-plane
// t = (cos a, −sin a) plus any device axes beyond x and y.
//
// Rubbing in pressure mode (§3.7 "Surface Friction", "Surface Texture"). While the
// handle presses on the surface with the normal force N (the element's own force, which in
// a steady press equals the user's push), moving along the surface meets
//
//     F_t = −N·(μ + τ·bump(r))·tanh(|v_t| / v_s)·v_t/|v_t|
//
//   μ = surface_friction / 10000: a Coulomb coefficient, 10000 is μ = 1 (rubber on
//       concrete), 0 is glass or ice;
//   τ = surface_texture / 10000: extra resistance on bumps; bump(r) ∈ [0, 1] is a raised
//       cosine ridge, 1 on the ridge line, of width kSurfaceBumpWidth every
//       kSurfaceBumpSpacing along each tangent direction (the largest ridge under the
//       handle counts), so dragging feels bumpy like rough concrete;
//   v_t: the velocity along the surface; tanh(|v_t|/v_s) is the smooth transition of §3.5
//       that keeps a reversal free of a sharp jerk, v_s = kSurfaceSlipSpeed·velocity_ref.
//
// Both friction and texture therefore scale with how hard the user pushes (pressure mode)
// and both always oppose the motion along the surface: they only ever dissipate, so they
// cannot make the contact unstable and the passivity ledger (passivity.hpp) need not watch
// them. The texture is a friction that varies along the surface rather than a washboard
// potential: a conservative grating of useful depth would be far stiffer than the
// device's passivity bound.
//
// Single precision (issue 14 §2): positions, forces and directions are float, as the
// tick's other conditions; u is worked out once per command (in 64-bit integers, rounded
// once to float: no double on a Cortex-M4F), not per tick.
#pragma once

#include <cstdint>

#include "conditions/condition.hpp"

namespace feel::detail {

// Bumps of the surface texture: a ridge every 2% of the travel (1 mm on the joystick),
// half as wide as the spacing (§3.6's density 5000).
inline constexpr float kSurfaceBumpSpacing = 200.0f;  // position units
inline constexpr float kSurfaceBumpWidth = 100.0f;     // position units
// The rubbing force reaches tanh(1) = 76% of its full value at 10% of velocity_ref
// (50 mm/s on the joystick). A sharper transition would act near rest as a damper too
// stiff for the device's tick (μN/v_s is its slope) and chatter.
inline constexpr float kSurfaceSlipSpeed = 0.1f;       // fraction of EngineConfig::velocity_ref

// The direction u across the surface of a wall or barrier (axis_wall, angle_wall,
// axis_barrier, angle_barrier), on the device's axes: the effect's one axis, or the compass
// direction of the block's angle on x, y. Worked out once per command (prepare_slot puts it
// in the slot's direction, which the tick hands the element as ConditionContext::direction);
// any other type's factors are left alone.
void element_direction(const SlotParams& params, float u[kMaxAxes]) noexcept;

// The stiffness of a wall or barrier of this hardness (-10000..10000): hardness/10000 of
// EngineConfig::wall_stiffness, in force units per position unit.
float element_stiffness(const EngineConfig& config, int32_t hardness) noexcept;

// The rubbing force of a surface across u (c.direction) pressed with normal force
// `pressure` (>= 0, force units), added into force[]. friction and texture are the block's
// 0..10000 parameters. The surface's tangent directions are the device axes other than an
// axis element's own, or for an angle element the in-plane t = (cos a, −sin a) and any
// axes beyond x and y: the velocity along the surface is v − (v·u)·u.
void add_rubbing_force(const ConditionContext& c, float pressure, int32_t friction, int32_t texture,
                       float force[kMaxAxes]) noexcept;

// bump(r): 1 on a ridge line (r a multiple of kSurfaceBumpSpacing), falling as a raised
// cosine to 0 at kSurfaceBumpWidth/2 from it, 0 between ridges.
float surface_bump(float r) noexcept;

}  // namespace feel::detail
