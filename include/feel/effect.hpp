// feel — the description of one effect, in the primer's integer units (§6.3, §6.6).
//
// EffectParams is plain data: no pointers, no heap, trivially copyable, so that it can
// cross a lock-free queue into the real-time loop and be stored in a fixed slot. Sample
// data for force profiles travels separately (see Engine::create).
//
// Every field states its unit and range; the ranges are the constants of units.hpp and
// are enforced by validate_effect() (effect_validation.hpp).
#pragma once

#include <cstdint>

#include "feel/axis.hpp"
#include "feel/effect_type.hpp"
#include "feel/units.hpp"

namespace feel {

// Where a directional effect's force comes FROM (§6.5). The force pushes the other way.
//
//   polar (2D), compass angle clockwise from north (+y):
//
//                 0 (from +y: pushes toward -y)
//                 N
//       27000 W --+-- E 9000 (from +x: pushes toward -x)
//                 S
//               18000
//
//   cartesian: a vector pointing to where the force comes from, one component per axis
//              of the effect, each in ±10000; only its direction matters.
//   spherical (3D, §6.5.c): value[0] is the angle in the XY plane from +x toward +y,
//              value[1] the angle away from +z; both hundredths of a degree.
//   moments (nD, §6.5.d): rotational components about x, y, z for rx/ry/rz axes, like
//              cartesian.
//   none: the effect plays on its single axis with the physical sign of its value
//         (+ pushes toward +axis), the primer's "axis wave" (§4.2.c).
enum class DirectionKind : uint8_t { none, polar, cartesian, spherical, moments };

struct Direction {
    DirectionKind kind = DirectionKind::none;
    int32_t value[3] = {0, 0, 0};  // see DirectionKind for the meaning of each slot

    friend bool operator==(const Direction&, const Direction&) = default;
};

// The impulse envelope of a wave (§4.2.a, §6.3).
struct Envelope {
    int32_t impulse_level = 0;   // 0..10000, the level at the start of the wave
    int64_t settle_time_us = 0;  // 0..65e6, time to settle from impulse level to steady state
    int32_t fade_level = 0;      // 0..10000, the level at the end of the wave
    int64_t fade_time_us = 0;    // 0..65e6, time from steady state to the fade level

    friend bool operator==(const Envelope&, const Envelope&) = default;
};

// Where an offset is measured from: the axis origin, or the handle's position when the
// effect starts (the primer's SpringAtCurrentLocation, §8.2; a wall's relative offset, §3.7).
enum class OffsetMode : uint8_t { absolute, relative };

// One axis of a spring, damper, inertia or friction (§6.6.a).
struct ConditionBlock {
    int32_t pos_coefficient = 0;     // -10000..10000
    int32_t neg_coefficient = 0;     // -10000..10000
    int32_t offset = 0;              // -10000..10000 (position for springs, velocity for dampers)
    int32_t pos_saturation = 10000;  // 0..10000, largest force on the positive side
    int32_t neg_saturation = 10000;  // 0..10000, largest force on the negative side
    int32_t deadband = 0;            // 0..10000, zero-force band around the offset
    OffsetMode offset_mode = OffsetMode::absolute;  // springs: relative = from the start position

    friend bool operator==(const ConditionBlock&, const ConditionBlock&) = default;
};

enum class SweepSense : uint8_t { clockwise, counterclockwise };

// Periodic and Advanced Periodic structs (§6.6.b, §6.6.i).
struct PeriodicBlock {
    int32_t magnitude = 0;       // 0..10000 (periodic), -10000..10000 (sweep)
    int32_t offset = 0;          // -10000..10000, baseline the wave oscillates about
    int64_t period_us = 1;       // 1..65e6
    int32_t phase = 0;           // 0..35999 hundredths of a degree into the cycle at t = 0
    int32_t sweep_start_angle = 0;  // 0..35999, sweeps only: compass direction at the start
    int32_t sweep_end_angle = 0;    // 0..35999, sweeps only: compass direction at the end
    SweepSense sweep_sense = SweepSense::clockwise;  // sweeps only

    friend bool operator==(const PeriodicBlock&, const PeriodicBlock&) = default;
};

struct ConstantBlock {
    int32_t magnitude = 0;  // -10000..10000 (§6.6.c)

    friend bool operator==(const ConstantBlock&, const ConstantBlock&) = default;
};

struct RampBlock {
    int32_t start = 0;  // -10000..10000, level at the start of the duration (§6.6.e)
    int32_t end = 0;    // -10000..10000, level at the end of the duration

    friend bool operator==(const RampBlock&, const RampBlock&) = default;
};

// Custom struct (§6.6.d). The samples themselves are passed beside the params.
struct CustomBlock {
    int32_t channels = 1;           // 1..6; channel i drives the effect's axis i
    int64_t sample_period_us = 1;   // 1..65e6, each sample is held this long
    int32_t sample_count = 0;       // 1..65535, a multiple of channels, interleaved by channel

    friend bool operator==(const CustomBlock&, const CustomBlock&) = default;
};

struct TextureBlock {  // §6.6.j
    int32_t pos_roughness = 1;  // 1..10000
    int32_t neg_roughness = 1;  // 1..10000
    int32_t spacing = 1;        // 1..10000, center-to-center bump spacing (position units)
    int32_t density = 1;        // 1..10000, bump width as a fraction of spacing (5000 = 50%)

    friend bool operator==(const TextureBlock&, const TextureBlock&) = default;
};

// Which way a wall faces (§3.7): positive resists motion toward +axis, so the handle is free
// on the negative side; negative resists motion toward -axis.
enum class WallSense : uint8_t { positive, negative };

struct WallBlock {  // §6.6.h
    int32_t hardness = 0;              // -10000..10000
    WallSense sense = WallSense::positive;
    int32_t offset = 0;                // -10000..10000
    OffsetMode offset_mode = OffsetMode::absolute;
    int32_t angle = 0;                 // 0..35999 (angle_wall only)
    int32_t surface_friction = 0;      // 0..10000
    int32_t surface_texture = 0;       // 0..10000
    bool clipping = false;

    friend bool operator==(const WallBlock&, const WallBlock&) = default;
};

struct BarrierBlock {  // §6.6.g
    int32_t pos_hardness = 0;      // -10000..10000
    int32_t neg_hardness = 0;      // -10000..10000
    int32_t thickness = 1;         // 1..10000
    int32_t offset = 0;            // -10000..10000
    int32_t angle = 0;             // 0..35999 (angle_barrier only)
    int32_t surface_friction = 0;  // 0..10000
    int32_t surface_texture = 0;   // 0..10000
    // The Offset-Flag, "same as the wall" (§3.8): relative measures offset from where the
    // handle is when the effect starts. Last, so that brace-initialised blocks keep their order.
    OffsetMode offset_mode = OffsetMode::absolute;

    friend bool operator==(const BarrierBlock&, const BarrierBlock&) = default;
};

// DynamicControlLaw on one axis (§8.4): the law every dynamic maps onto.
struct ControlLawBlock {
    int32_t mass = 1;         // 1..10000, mass tethered to the handle
    int32_t k_pos = 1;        // 1..10000, tether stiffness, positive stretch
    int32_t k_neg = 1;        // 1..10000, tether stiffness, negative stretch
    int32_t b = 0;            // 0..10000, tether damping
    int32_t vel_init = 0;     // -10000..10000, initial velocity relative to the handle
    int32_t pos_init = 0;     // -10000..10000, initial position relative to the handle
    int32_t half_cycles = 0;  // 0..10000, end after this many half oscillations, 0 = never
    int32_t length = 0;       // 0..10000, free play between mass and handle
    int32_t drag = 0;         // 0..10000, ambient damping
    int32_t gravity = 0;      // -10000..10000

    friend bool operator==(const ControlLawBlock&, const ControlLawBlock&) = default;
};

// The named dynamics' parameters (§8.4). Only the fields of the effect's type are used;
// the §8.4 table maps them onto the control law.
struct DynamicBlock {
    // dynamic_recoil
    int32_t blast_direction = 0;   // 0..35999
    int32_t blast_intensity = 0;   // -10000..10000
    int32_t blast_resonance = 1;   // 1..10000
    int32_t blast_decay = 0;       // 0..10000
    // dynamic_recoil and dynamic_impact
    int32_t dynamic_mass = 1;      // 1..10000
    // dynamic_impact
    int32_t impact_direction = 0;      // 0..35999
    int32_t impact_intensity = 0;      // -10000..10000
    int32_t elasticity = 1;            // 1..10000
    int32_t collision_absorption = 0;  // 0..10000
    // dynamic_liquid
    int32_t density = 1;    // 1..10000
    int32_t settle = 1;     // 1..10000
    int32_t viscosity = 0;  // 0..10000
    // dynamic_inertia
    int32_t inertia = 1;  // 1..10000
    int32_t play = 0;     // 0..10000
    // dynamic_center_drift
    int32_t stiffness = 1;         // 1..10000
    int32_t drift_resistance = 0;  // 0..10000
    // dynamic_sling and dynamic_paddle
    int32_t ball_mass = 1;  // 1..10000
    // dynamic_sling
    int32_t string_length = 0;      // 0..10000
    int32_t string_compliance = 1;  // 1..10000
    int32_t ball_damping = 0;       // 0..10000
    // dynamic_paddle
    int32_t initial_velocity = 0;            // -10000..10000
    int32_t initial_velocity_direction = 0;  // 0..35999
    int32_t paddle_compliance = 1;           // 1..10000
    int32_t paddle_damping = 0;              // 0..10000
    int32_t gravity = 0;                     // -10000..10000
    // dynamic_control_law: one block per axis of the effect
    ControlLawBlock control_law[kMaxAxes] = {};
    // all dynamics: report the mass state to the host while playing (§6.6.f)
    bool interim_reporting = false;

    friend bool operator==(const DynamicBlock&, const DynamicBlock&) = default;
};

// A trigger: the button or hat switch that starts the effect as a reflex (§1.2.c, §6.3).
enum class TriggerKind : uint8_t { none, button, hat };
struct Trigger {
    TriggerKind kind = TriggerKind::none;
    int32_t index = 0;  // button 1..32 or hat 1..4

    friend bool operator==(const Trigger&, const Trigger&) = default;
};

// The Effect Structure (§6.3) with its type-specific blocks.
struct EffectParams {
    EffectType type = EffectType::constant;
    int64_t duration_us = kInfiniteUs;  // 1..65e6 or kInfiniteUs
    int64_t start_delay_us = 0;         // 0..65e6, once, before the first iteration
    int32_t gain = kFullScale;          // 0..10000, scales this effect's force
    int32_t iterations = 1;             // 1..255, or kInfiniteIterations
    int32_t axis_count = 1;             // 1..kMaxAxes (6; the firmware build: 2)
    Axis axes[kMaxAxes] = {FEEL_AXES_IN_ORDER(FEEL_MAX_AXES)};  // x, y, z, rx, ry, rz
    Direction direction{};
    Trigger trigger{};
    int64_t trigger_repeat_interval_us = 0;  // 0 = no repeat, else 1..65e6
    bool has_envelope = false;
    Envelope envelope{};

    // Type-specific blocks (§6.6): only the one(s) of `type` are read.
    ConditionBlock conditions[kMaxAxes] = {};  // one per axis of the effect
    PeriodicBlock periodic{};
    ConstantBlock constant{};
    RampBlock ramp{};
    CustomBlock custom{};
    TextureBlock texture{};
    WallBlock wall{};
    BarrierBlock barrier{};
    DynamicBlock dynamic{};

    friend bool operator==(const EffectParams&, const EffectParams&) = default;
};

inline constexpr int32_t kInfiniteIterations = -1;

// A spring, damper, inertia or friction given a direction (§3.1: "for multi-axis conditions,
// you can define a direction"): one condition block, conditions[0], applied along the
// direction, DirectInput's single DICONDITION "in the specified direction". Without one, a
// block per axis acts on each axis separately. (angle_spring is the polar special case with
// its own type.) docs/conditions.md, "Conditions with a direction".
[[nodiscard]] constexpr bool is_directed_condition(const EffectParams& p) noexcept {
    return (p.type == EffectType::spring || p.type == EffectType::damper || p.type == EffectType::inertia ||
            p.type == EffectType::friction) &&
           p.direction.kind != DirectionKind::none;
}

}  // namespace feel
