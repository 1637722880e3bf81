// feel::iforce — the I-FORCE 2.0 wrapper functions of the primer's §8.
//
// The primer's SDK wrapped DirectX's structures in "a physically intuitive set of
// parameterized function calls" (§8.1): XSpring(KPos, KNeg, Offset, PosSat, NegSat,
// DeadBand) instead of a DIEFFECT, a DICONDITION and an axis array. These are those calls,
// spelled in feel's style (XSpring -> x_spring, SpringatCurrentLocation ->
// spring_at_current_location), taking the primer's parameters in the primer's order and
// units, and returning the plain EffectParams that feel::host::Device::create_effect, the
// engine and the sensation-file writer all take:
//
//   auto spring = device.create_effect(feel::iforce::x_spring(1000, 1000, 0, 10000, 10000, 0));
//   auto bump   = device.create_effect(feel::iforce::dynamic_impact(9000, 5000, 5000, 5000, 500));
//
// Units (docs/conventions.md): levels, coefficients, offsets and positions in ±10000 of the
// device's capability; times in microseconds (feel::kInfiniteUs for "INFINITE"); angles and
// directions in hundredths of a degree, 0..35999, compass angles clockwise from north (+y)
// naming where a force comes FROM (polar 9000 pushes toward -x).
//
// Errors. The wrappers are pure builders, called on the game's thread before anything is
// sent to a device, so a bad argument is a programming error and they throw
// std::invalid_argument, naming the wrapper, the parameter, its value and the allowed range:
//
//   "x_spring: deadband = 12000 is out of range (allowed 0..10000)"
//
// Each wrapper checks its arguments against the range §8's tables give for them. Where the
// primer's range and the engine's differ, the narrower one is enforced, so the result is
// always accepted by feel::validate_effect (a test checks every wrapper); the exceptions
// are listed per parameter below and in docs/wrappers.md. Everything else about the
// effect is what §8.5's sample code sets: gain 10000, no start delay, one iteration,
// duration INFINITE for conditions and dynamics.
//
// Which axes. The wrappers are written for a 2D joystick (§8.5 uses DIJOFS_X and DIJOFS_Y):
// an X... wrapper plays on the axis x, a Y... wrapper on y, the others on x and y. A device
// without those axes refuses the effect when it is created (not_supported / invalid_parameter
// from create_effect), not here: the wrappers do not know the device.
//
// docs/wrappers.md maps every §8 wrapper to its function, effect type and fields.
#pragma once

#include <cstdint>

#include "feel/axis.hpp"
#include "feel/effect.hpp"
#include "feel/effect_type.hpp"
#include "feel/units.hpp"

namespace feel::iforce {

// Triggers (§6.3 "Trigger Button"), for the wave wrappers' Trigger parameter.
inline constexpr Trigger kNoTrigger{};
[[nodiscard]] constexpr Trigger button_trigger(int32_t button) noexcept {  // button 1..32
    return Trigger{TriggerKind::button, button};
}
[[nodiscard]] constexpr Trigger hat_trigger(int32_t hat) noexcept {  // hat switch 1..4
    return Trigger{TriggerKind::hat, hat};
}

// =========================================================================================
// §8.2 Condition function wrappers. All play until stopped (duration INFINITE).
//
//   k_pos, k_neg, k       -10000..10000   stiffness (springs) or damping (dampers)
//   offset                -10000..10000   spring: center position; damper: the velocity of
//                                         zero force (docs/conditions.md)
//   pos_saturation,
//   neg_saturation,
//   saturation            0..10000        largest force on each side of the offset
//   deadband              0..10000        band around the offset with no force
//   angle                 0..35999        compass angle of the spring's line (§8.2 "angle of
//                                         effect"); the + side is the side it points to
// =========================================================================================

// XSpring / YSpring: a spring on one axis (`spring` on [x] or [y], one condition block).
[[nodiscard]] EffectParams x_spring(int32_t k_pos, int32_t k_neg, int32_t offset,
                                    int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
[[nodiscard]] EffectParams y_spring(int32_t k_pos, int32_t k_neg, int32_t offset,
                                    int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
// Spring: springs on both axes (`spring` on [x, y], block 0 for x, block 1 for y).
[[nodiscard]] EffectParams spring(int32_t x_k_pos, int32_t x_k_neg, int32_t x_offset,
                                  int32_t x_pos_saturation, int32_t x_neg_saturation, int32_t x_deadband,
                                  int32_t y_k_pos, int32_t y_k_neg, int32_t y_offset,
                                  int32_t y_pos_saturation, int32_t y_neg_saturation, int32_t y_deadband);
// AngleSpring: a spring along the line at compass angle `angle` (`angle_spring` on [x, y],
// polar direction = angle).
[[nodiscard]] EffectParams angle_spring(int32_t k_pos, int32_t k_neg, int32_t offset,
                                        int32_t pos_saturation, int32_t neg_saturation,
                                        int32_t deadband, int32_t angle);
// CenterSpring: the same spring on x and y, centered (offset 0).
[[nodiscard]] EffectParams center_spring(int32_t k, int32_t saturation, int32_t deadband);
// SpringatCurrentLocation: CenterSpring around where the handle is when the effect starts
// (each block's offset_mode = relative, offset 0).
[[nodiscard]] EffectParams spring_at_current_location(int32_t k, int32_t saturation, int32_t deadband);

// XDamper / YDamper / Damper: as the springs, with damping coefficients b_pos, b_neg.
[[nodiscard]] EffectParams x_damper(int32_t b_pos, int32_t b_neg, int32_t offset,
                                    int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
[[nodiscard]] EffectParams y_damper(int32_t b_pos, int32_t b_neg, int32_t offset,
                                    int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
[[nodiscard]] EffectParams damper(int32_t x_b_pos, int32_t x_b_neg, int32_t x_offset,
                                  int32_t x_pos_saturation, int32_t x_neg_saturation, int32_t x_deadband,
                                  int32_t y_b_pos, int32_t y_b_neg, int32_t y_offset,
                                  int32_t y_pos_saturation, int32_t y_neg_saturation, int32_t y_deadband);

// XInertia / YInertia / Inertia(Mass, Saturation): an added mass, the same in both
// directions (§8.5: both coefficients = mass, both saturations = saturation, offset and
// deadband 0). mass 1..10000 and saturation 1..10000 as §8.2 says (the engine would
// also take a negative mass and a zero saturation; the primer's narrower range wins).
[[nodiscard]] EffectParams x_inertia(int32_t mass, int32_t saturation);
[[nodiscard]] EffectParams y_inertia(int32_t mass, int32_t saturation);
[[nodiscard]] EffectParams inertia(int32_t mass, int32_t saturation);  // x and y

// Friction(F) on x and y; XFriction / YFriction(FPos, FNeg) on one axis. Forces 0..10000
// (the primer's range; the engine's signed coefficient range is wider). Saturations 10000,
// offset and deadband 0 (the primer: offsets are usually not used for friction, §3.5).
[[nodiscard]] EffectParams friction(int32_t f);
[[nodiscard]] EffectParams x_friction(int32_t f_pos, int32_t f_neg);
[[nodiscard]] EffectParams y_friction(int32_t f_pos, int32_t f_neg);

// Texture(Roughness, Spacing, Density, Angle): bumps along the line at compass angle
// `angle` (`texture` on [x, y] with polar direction = angle); XTexture / YTexture: bumps
// along one axis. Roughness, spacing and density 1..10000 (§6.6.j: spacing is the bump
// pitch in position units, density the bump width as a fraction of it).
[[nodiscard]] EffectParams texture(int32_t roughness, int32_t spacing, int32_t density, int32_t angle);
[[nodiscard]] EffectParams x_texture(int32_t roughness, int32_t spacing, int32_t density);
[[nodiscard]] EffectParams x_texture(int32_t pos_roughness, int32_t neg_roughness, int32_t spacing,
                                     int32_t density);
[[nodiscard]] EffectParams y_texture(int32_t pos_roughness, int32_t neg_roughness, int32_t spacing,
                                     int32_t density);

// Walls (§3.7, §6.6.h).
//   hardness          -10000..10000   stiffness of the wall (negative pulls into it)
//   sense             WallSense::positive: the wall resists crossing while moving toward
//                     + (the free side is below the offset); negative: the other way
//   offset            -10000..10000   where the wall's surface lies
//   surface_friction,
//   surface_texture   0..10000        rubbing along the surface while pressing into it
//   clipping          report the position as stopped at the surface (§3.7)
//
// Wall(Hardness, Sense, Offset, Angle): a wall at any compass angle in the x-y plane
// (`angle_wall`): its surface is the line at distance offset from the center along the
// angle's direction u = (sin angle, cos angle), and "positive" is along u.
[[nodiscard]] EffectParams wall(int32_t hardness, WallSense sense, int32_t offset, int32_t angle);
// HorizontalWall: a HORIZONTAL LINE across the workspace, y = offset, felt along y
// (`axis_wall` on [y]); positive sense: solid above (+y, away from the user).
// VerticalWall: a vertical line x = offset, felt along x (`axis_wall` on [x]); positive
// sense: solid to the right. (docs/conditions.md: an axis_wall on y is the primer's
// HorizontalWall, on x its VerticalWall.)
[[nodiscard]] EffectParams horizontal_wall(int32_t hardness, WallSense sense, int32_t offset,
                                           int32_t surface_friction, int32_t surface_texture,
                                           bool clipping);
[[nodiscard]] EffectParams vertical_wall(int32_t hardness, WallSense sense, int32_t offset,
                                         int32_t surface_friction, int32_t surface_texture,
                                         bool clipping);

// Barriers (§3.8, §6.6.g): a slab of `thickness` (1..10000) centered on `offset` that the
// handle can pop through; pos_hardness is felt crossing it toward +, neg_hardness toward −
// (both -10000..10000). Barrier(..., Angle) is an `angle_barrier`; HorizontalBarrier the
// line y = offset (`axis_barrier` on [y]), VerticalBarrier x = offset (on [x]).
[[nodiscard]] EffectParams barrier(int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                                   int32_t offset, int32_t angle);
[[nodiscard]] EffectParams horizontal_barrier(int32_t pos_hardness, int32_t neg_hardness,
                                              int32_t thickness, int32_t offset,
                                              int32_t surface_friction, int32_t surface_texture);
[[nodiscard]] EffectParams vertical_barrier(int32_t pos_hardness, int32_t neg_hardness,
                                            int32_t thickness, int32_t offset,
                                            int32_t surface_friction, int32_t surface_texture);

// =========================================================================================
// §8.3 Wave function wrappers. They play on x and y in the polar direction given.
//
//   magnitude         1..10000          strength of the force or wave (§8.3's range; the
//                                       direction gives the sign)
//   offset            0..10000          baseline of a periodic wave (§8.3's range; the engine
//                                       would take -10000..10000)
//   phase             0..35999          where in the cycle the wave starts
//   period_us         1..65e6 µs
//   duration_us       1..65e6 µs, or kInfiniteUs where noted
//   direction, angle  0..35999          compass angle the force comes FROM
//   impulse_level     0..10000          envelope level at the start (§4.2.a)
//   settle_time_us    1..65e6 µs        impulse -> steady state
//   fade_level        0..10000          envelope level at the end
//   fade_time_us      1..65e6 µs        steady state -> fade level
//   start, end        0..10000          ramp levels (§8.3's range)
//   trigger           kNoTrigger, button_trigger(1..32) or hat_trigger(1..4): a reflex
//   trigger_repeat_interval_us
//                     0 or 1..65e6 µs   restart while the trigger is held. §8.3 says
//                                       1..65 million; 0 ("no repeat", §6.3 and §8.5's own
//                                       sample code) is also accepted. Needs a trigger.
// =========================================================================================

// VectorForce: "a force of indefinite duration" (`vector_force`): duration_us may be
// kInfiniteUs (the usual value: the game changes or stops it) or 1..65e6.
[[nodiscard]] EffectParams vector_force(int32_t magnitude, int64_t duration_us, int32_t direction);
// ConstantForce: "a force of a defined duration" (`constant`): 1..65e6 µs, not infinite.
[[nodiscard]] EffectParams constant_force(int32_t magnitude, int64_t duration_us, int32_t direction);
// ConstantForceTrigger: ConstantForce played as a reflex of `trigger` (not kNoTrigger).
[[nodiscard]] EffectParams constant_force_trigger(int32_t magnitude, int64_t duration_us,
                                                  int32_t direction, Trigger trigger,
                                                  int64_t trigger_repeat_interval_us);
// EnvelopeConstant: a constant force shaped by an envelope; duration 1..65e6 or kInfiniteUs
// (then the fade never comes). `constant`.
[[nodiscard]] EffectParams envelope_constant(int32_t magnitude, int64_t duration_us, int32_t direction,
                                             int32_t impulse_level, int64_t settle_time_us,
                                             int32_t fade_level, int64_t fade_time_us, Trigger trigger,
                                             int64_t trigger_repeat_interval_us);
// Ramp: from `start` to `end` over duration_us (finite: a ramp is shaped over it). `ramp`.
[[nodiscard]] EffectParams ramp(int32_t start, int32_t end, int64_t duration_us, int32_t direction,
                                Trigger trigger, int64_t trigger_repeat_interval_us);
[[nodiscard]] EffectParams ramp_envelope(int32_t start, int32_t end, int64_t duration_us,
                                         int32_t direction, int32_t impulse_level,
                                         int64_t settle_time_us, int32_t fade_level,
                                         int64_t fade_time_us, Trigger trigger,
                                         int64_t trigger_repeat_interval_us);
// Periodic: a sine, square, triangle, saw-up or saw-down wave (the effect type is the
// waveform's). duration_us 1..65e6 or kInfiniteUs.
[[nodiscard]] EffectParams periodic(Waveform waveform, int32_t magnitude, int32_t offset, int32_t phase,
                                    int64_t period_us, int64_t duration_us, int32_t angle,
                                    Trigger trigger, int64_t trigger_repeat_interval_us);
[[nodiscard]] EffectParams envelope_periodic(Waveform waveform, int32_t magnitude, int32_t offset,
                                             int32_t phase, int64_t period_us, int64_t duration_us,
                                             int32_t angle, int32_t impulse_level,
                                             int64_t settle_time_us, int32_t fade_level,
                                             int64_t fade_time_us, Trigger trigger,
                                             int64_t trigger_repeat_interval_us);
// DelayedPeriodic: Periodic that starts after `pause_us` (0..65e6 µs; §8.3 gives no
// range, this is the engine's start delay range), for staggered onsets.
[[nodiscard]] EffectParams delayed_periodic(int64_t pause_us, Waveform waveform, int32_t magnitude,
                                            int32_t offset, int32_t phase, int64_t period_us,
                                            int64_t duration_us, int32_t angle, Trigger trigger,
                                            int64_t trigger_repeat_interval_us);
// SweepPeriodic: a periodic wave whose direction turns from start_angle to stop_angle over
// the duration, the way `sense` says (`sweep_<waveform>`). Note §8.3's order: Period before
// Phase here. duration_us 1..65e6: the engine needs a finite duration to sweep over (§8.3
// allows INFINITE for waves in general; the engine's rule wins).
[[nodiscard]] EffectParams sweep_periodic(int32_t start_angle, int32_t stop_angle, SweepSense sense,
                                          Waveform waveform, int32_t magnitude, int32_t offset,
                                          int64_t period_us, int32_t phase, int64_t duration_us);

// =========================================================================================
// §8.4 Dynamic function wrappers. The effect carries the primer's named parameters in its
// DynamicBlock; the engine maps them onto the control law by §8.4's table
// (docs/dynamics.md). They play until stopped or until they end themselves (the paddle when
// the ball leaves, the control law after half_cycles); duration INFINITE as in §8.5.
// Ranges are those of the control-law parameter each maps to (§8.4's table):
//   masses (dynamic_mass, density, inertia, ball_mass, mass)       1..10000
//   stiffnesses (blast_resonance, elasticity, settle, stiffness,
//                string_compliance, paddle_compliance, k_pos, k_neg) 1..10000
//   dampings (blast_decay, collision_absorption, viscosity, b,
//             drift_resistance, ball_damping, paddle_damping, drag)  0..10000
//   velocities (blast_intensity, impact_intensity, initial_velocity,
//               vel_init)                                            -10000..10000
//   lengths (play, string_length, length)                            0..10000
//   pos_init, gravity                                                -10000..10000
//   half_cycles                                                      0..10000 (0 = never)
//   directions (blast_direction, impact_direction,
//               initial_velocity_direction)                          0..35999, FROM
// =========================================================================================

// DynamicRecoil: a weapon's kick from compass direction blast_direction (on x and y).
[[nodiscard]] EffectParams dynamic_recoil(int32_t blast_direction, int32_t blast_intensity,
                                          int32_t dynamic_mass, int32_t blast_resonance,
                                          int32_t blast_decay);
// DynamicImpact: a blow from compass direction impact_direction (on x and y).
[[nodiscard]] EffectParams dynamic_impact(int32_t impact_direction, int32_t impact_intensity,
                                          int32_t dynamic_mass, int32_t elasticity,
                                          int32_t collision_absorption);
// DynamicLiquid, DynamicInertia, DynamicCenterDrift, DynamicSling: on x and y.
[[nodiscard]] EffectParams dynamic_liquid(int32_t density, int32_t settle, int32_t viscosity);
[[nodiscard]] EffectParams dynamic_inertia(int32_t inertia, int32_t play);
[[nodiscard]] EffectParams dynamic_center_drift(int32_t stiffness, int32_t drift_resistance);
[[nodiscard]] EffectParams dynamic_sling(int32_t ball_mass, int32_t string_length,
                                         int32_t string_compliance, int32_t ball_damping,
                                         bool interim_reporting);
// DynamicPaddle: a ball hits the paddle (the handle), on x and y. §5.9: the initial
// velocity "has both a magnitude and direction", so §8.4's InitialVelocity is two
// arguments here: initial_velocity (the speed, -10000..10000) and
// initial_velocity_direction (the compass angle the ball comes FROM, 0..35999). Gravity is
// one signed number along the line the ball came in on (+ pulls it toward the paddle).
[[nodiscard]] EffectParams dynamic_paddle(int32_t ball_mass, int32_t initial_velocity,
                                          int32_t initial_velocity_direction,
                                          int32_t paddle_compliance, int32_t paddle_damping,
                                          int32_t gravity, bool interim_reporting);
// DynamicControlLaw: the law itself on one axis ("simulates dynamic behavior on a single
// axis", §8.4), `dynamic_control_law` with one control_law block. `axis` (after the
// primer's parameters) picks the axis, x by default.
[[nodiscard]] EffectParams dynamic_control_law(int32_t mass, int32_t k_pos, int32_t k_neg, int32_t b,
                                               int32_t vel_init, int32_t pos_init, int32_t half_cycles,
                                               int32_t length, int32_t drag, int32_t gravity,
                                               bool interim_reporting, Axis axis = Axis::x);

}  // namespace feel::iforce
