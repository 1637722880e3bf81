// An effect's parameters as the engine stores them in its slot: the Effect Structure's
// header and the one type-specific block its type reads.
//
// A host describes an effect with EffectParams (feel/effect.hpp), which carries every
// type's block side by side: 504 bytes on a 2-axis build, 392 of them blocks the effect
// never reads. A device's local memory holds an Effect Structure and the Type Specific
// Structs of its type only (§6.3, §6.6), and so does a slot: the blocks share their bytes
// in a union, and a dynamic's block (the largest, every named dynamic's fields and a
// control law per axis) lives in the dynamic's pooled record, reached through `dynamic`
// (issue 14: RAM on a Cortex-M4F).
//
// The fields keep EffectParams' names, so the engine's functions read a SlotParams the way
// they read an EffectParams. The conversions run at create and update, after validation
// (every value is then within its range); the tick never converts. Converting back gives
// the host's parameters with what the effect never reads at its defaults: the other types'
// blocks, an envelope without has_envelope, a trigger's index without a trigger, the
// condition blocks beyond the effect's axes (Engine::params documents it).
#pragma once

#include <cstdint>

#include "feel/effect.hpp"

namespace feel::detail {

// A Condition Struct block (§6.6.a) as the tick reads it: its integer fields as floats, the
// coefficients already divided by 10000 and negated (condition_math.hpp). Worked out once
// per command (curve_of), not per tick.
struct ConditionCurve {
    float pos_slope = 0.0f;  // -pos_coefficient / 10000
    float neg_slope = 0.0f;  // -neg_coefficient / 10000
    float pos_cap = 0.0f;    // pos_saturation
    float neg_cap = 0.0f;    // neg_saturation
    float band = 0.0f;       // deadband
    float offset = 0.0f;
};

// A spring's, damper's, inertia's or angle spring's blocks as a slot keeps them: the curves
// the tick reads and each block's offset mode. The curves hold the blocks exactly (every
// field an integer within ±10000, a float holds it, and the slopes' one rounding is far
// below half a unit: effect_params recovers each block), so the blocks are not kept too.
struct CurvedConditions {
    ConditionCurve curves[kMaxAxes];
    OffsetMode offset_modes[kMaxAxes];
};

// A friction's block (§6.6.a) in a slot: every field within ±10000, in 16 bits (14 bytes
// where the host's ConditionBlock takes 28). Friction reads its blocks as integers.
struct SlotConditionBlock {
    int16_t pos_coefficient = 0;
    int16_t neg_coefficient = 0;
    int16_t offset = 0;
    int16_t pos_saturation = kFullScale;
    int16_t neg_saturation = kFullScale;
    int16_t deadband = 0;
    OffsetMode offset_mode = OffsetMode::absolute;
};

// The wave times τ in [from_us, until_us] lie outside an enveloped wave's attack and fade
// (or the wave has no envelope): its amplitude there is its value itself, and the envelope
// is not evaluated. Worked out with the command (envelope.hpp's steady_window) and kept in
// the block of each wave that takes an envelope, in the union's room. Outside it the
// envelope is evaluated (a τ past 2^31 µs of an endless wave included: the window is
// 32-bit, the evaluation right either way).
struct SteadyWindow {
    int32_t from_us = 0;
    int32_t until_us = INT32_MAX;
    [[nodiscard]] constexpr bool holds(int64_t tau_us) const noexcept { return tau_us >= from_us && tau_us <= until_us; }
};

// A periodic's or sweep's block (§6.6.b, §6.6.i) in a slot: the period (at most 65e6 µs) in
// 32 bits, so that no member of the union needs 8-byte alignment; the rest as the host's.
// Whether a periodic keeps its last time into the cycle (SlotPeriodicBlock::remainder_us), so
// that the tick advances it instead of dividing τ by the period: on x86; the board's blocks
// have no room to spare in the union on 2 axes, and its build divides as before.
#if !defined(__OPTIMIZE_SIZE__)
#define FEEL_KEEPS_CYCLE_REMAINDER 1
#else
#define FEEL_KEEPS_CYCLE_REMAINDER 0
#endif

struct SlotPeriodicBlock {
    int32_t magnitude = 0;
    int32_t offset = 0;
    int32_t period_us = 1;
    int32_t phase = 0;
    int32_t sweep_start_angle = 0;
    int32_t sweep_end_angle = 0;
    SweepSense sweep_sense = SweepSense::clockwise;

    // Worked out once per command from the fields above (prepare_periodic_block), so that the
    // tick does not: each is the value the tick's expression gave, with the same operations,
    // so the forces are the same bits (docs/tick-cost.md, "The waves' tick, eleventh pass").
    // They lie in the union's room (its largest member is a spring's curves, 52 bytes on 2
    // axes; this block is 48): the slot does not grow.
    float phase_turns = 0.0f;          // phase / 36000: where in the cycle τ = 0 lies
    float sweep_start_turns = 0.0f;    // sweep_start_angle / 36000
    float sweep_span_turns = 0.0f;     // the sweep's travel over the duration, in turns: ≥ 0 clockwise, ≤ 0 counter-clockwise
    SteadyWindow steady{};  // the envelope's steady window (steady_window)
#if FEEL_KEEPS_CYCLE_REMAINDER
    // The time into the cycle the tick last worked out (periodic_wave), and at which τ: a
    // tick later τ has moved on by less than a period, and the new remainder is the old one
    // plus the step, less the period if it passes it (the same integer as τ mod period,
    // without the division). INT32_MIN, the block's fresh state, is never within a period
    // of a τ in [0, 2^31). A command that sets the block makes a fresh one.
    mutable int32_t remainder_at_tau_us = INT32_MIN;
    mutable int32_t remainder_us = 0;
#endif
};

// The prepared fields cost no RAM: on every device of 2 axes or more the union already
// holds a larger member (the firmware's slot stays 160 bytes).
static_assert(kMaxAxes < 2 || sizeof(SlotPeriodicBlock) <= sizeof(CurvedConditions));

struct SlotParams;
// Fills the prepared turns of a periodic's or sweep's block from its other fields
// (waves/periodic_wave.cpp): slot_params calls it, and sets the steady window itself.
void prepare_periodic_block(SlotParams& s) noexcept;

// A force profile's block (§6.6.d) in a slot: the sample period (at most 65e6 µs) in 32 bits.
struct SlotCustomBlock {
    int32_t channels = 1;
    int32_t sample_period_us = 1;
    int32_t sample_count = 0;
    SteadyWindow steady{};
};

// A constant's, vector force's or smart pop's block (§6.6.c) and a ramp's (§6.6.e) in a
// slot: the host's fields, and the envelope's steady window.
struct SlotConstantBlock {
    int32_t magnitude = 0;
    SteadyWindow steady{};
};
struct SlotRampBlock {
    int32_t start = 0;
    int32_t end = 0;
    SteadyWindow steady{};
};

// One axis of a Dynamic Control Law (§8.4) in a dynamic's record: every field within
// 0..10000 or ±10000, in 16 bits.
struct SlotControlLawBlock {
    int16_t mass = 1;
    int16_t k_pos = 1;
    int16_t k_neg = 1;
    int16_t b = 0;
    int16_t vel_init = 0;
    int16_t pos_init = 0;
    int16_t half_cycles = 0;
    int16_t length = 0;
    int16_t drag = 0;
    int16_t gravity = 0;
};

// A Dynamic Sensation's block (§8.4) in its record: DynamicBlock's fields by their names,
// levels in int16 and angles (0..35999) in uint16, 92 bytes on 2 axes where the host's
// takes 184. Only the fields of the effect's type are validated, so only they are kept
// (slot_dynamic_block): another dynamic's fields read back as their defaults.
struct SlotDynamicBlock {
    uint16_t blast_direction = 0;
    int16_t blast_intensity = 0;
    int16_t blast_resonance = 1;
    int16_t blast_decay = 0;
    int16_t dynamic_mass = 1;
    uint16_t impact_direction = 0;
    int16_t impact_intensity = 0;
    int16_t elasticity = 1;
    int16_t collision_absorption = 0;
    int16_t density = 1;
    int16_t settle = 1;
    int16_t viscosity = 0;
    int16_t inertia = 1;
    int16_t play = 0;
    int16_t stiffness = 1;
    int16_t drift_resistance = 0;
    int16_t ball_mass = 1;
    int16_t string_length = 0;
    int16_t string_compliance = 1;
    int16_t ball_damping = 0;
    int16_t initial_velocity = 0;
    uint16_t initial_velocity_direction = 0;
    int16_t paddle_compliance = 1;
    int16_t paddle_damping = 0;
    int16_t gravity = 0;
    SlotControlLawBlock control_law[kMaxAxes] = {};
    bool interim_reporting = false;
};

// A direction (§6.5) in a slot: the values its kind reads, in 16 bits each (8 bytes where
// the host's Direction takes 16). Angles (polar's, spherical's azimuth 0..35999 and
// elevation 0..18000) are kept unsigned, a cartesian or moments vector's components
// (±10000, one per axis of the effect up to 3) signed; value(i) gives either back. The
// values a kind does not read (polar's second and third, spherical's third, components past
// the effect's axes) are not validated, and not kept: they read back as 0.
struct SlotDirection {
    DirectionKind kind = DirectionKind::none;
    uint16_t bits[3] = {0, 0, 0};

    [[nodiscard]] constexpr int32_t value(int i) const noexcept {
        return kind == DirectionKind::cartesian || kind == DirectionKind::moments ? static_cast<int16_t>(bits[i])
                                                                                 : bits[i];
    }
};

// An envelope (§4.2.a) in a slot: levels of at most 10000, times of at most 65e6 µs.
struct SlotEnvelope {
    int32_t settle_time_us = 0;
    int32_t fade_time_us = 0;
    int16_t impulse_level = 0;
    int16_t fade_level = 0;
};

struct SlotParams {
    SlotParams() noexcept : conditions{} {}

    // The Effect Structure (§6.3): EffectParams' header fields by their names, each in the
    // narrowest type that holds its range (validate_effect has checked them): times of at
    // most 65e6 µs, or kInfiniteUs (-1), in 32 bits; levels, gains and counts in 16 or 8.
    // Arithmetic promotes them to int as it did the host's int32 fields; a product of two
    // that may pass 2^31 (a duration times the iterations) widens one to int64 first, and
    // the tick's time minus the start delay is 64-bit as before (the delay widened).
    int32_t start_delay_us = 0;
    int32_t duration_us = kInfiniteUs;
    int32_t trigger_repeat_interval_us = 0;
    SlotDirection direction{};
    SlotEnvelope envelope{};
    int16_t gain = kFullScale;
    int16_t iterations = 1;  // 1..255, or kInfiniteIterations
    EffectType type = EffectType::constant;
    int8_t axis_count = 1;
    bool has_envelope = false;
    TriggerKind trigger_kind = TriggerKind::none;
    int8_t trigger_index = 0;
    Axis axes[kMaxAxes] = {FEEL_AXES_IN_ORDER(FEEL_MAX_AXES)};

    // The type-specific block of `type` (§6.6), the only member written: the others are
    // not alive and must not be read.
    // Its members need at most 4-byte alignment (32-bit periods), and the largest is a
    // spring's curves (52 bytes on 2 axes).
    union {
        CurvedConditions curved;                  // spring, damper, inertia, angle_spring
        SlotConditionBlock conditions[kMaxAxes];  // friction
        SlotPeriodicBlock periodic;               // periodics and sweeps
        SlotConstantBlock constant;               // constant, vector_force, smart_pop
        SlotRampBlock ramp;
        SlotCustomBlock custom;                   // force_profile
        TextureBlock texture;
        WallBlock wall;                           // axis_wall, angle_wall
        BarrierBlock barrier;                     // axis_barrier, angle_barrier
        const SlotDynamicBlock* dynamic;          // dynamics: the block in the effect's DynamicRecord
    };
};

// The stored form of a valid dynamic's block: the fields of p.type (of its axes' control
// laws for dynamic_control_law), the others at their defaults.
[[nodiscard]] SlotDynamicBlock slot_dynamic_block(const EffectParams& p) noexcept;

// The stored form of valid parameters p. A dynamic's block is not copied: `dynamic` points
// at `dynamic_block`, which must hold slot_dynamic_block(p) for as long as the result is
// read (the engine passes its record's copy).
[[nodiscard]] SlotParams slot_params(const EffectParams& p, const SlotDynamicBlock* dynamic_block) noexcept;

// The host's form of stored parameters: every field as given at create or update, the
// blocks of other types at their defaults.
[[nodiscard]] EffectParams effect_params(const SlotParams& s) noexcept;

// is_directed_condition (feel/effect.hpp) of stored parameters.
[[nodiscard]] constexpr bool is_directed_condition(const SlotParams& p) noexcept {
    return (p.type == EffectType::spring || p.type == EffectType::damper || p.type == EffectType::inertia ||
            p.type == EffectType::friction) &&
           p.direction.kind != DirectionKind::none;
}

}  // namespace feel::detail
