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
    // that may pass 2^31 (a duration times the iterations) widens one to int64 first. The
    // start delay stays 64-bit: the tick subtracts it from a 64-bit time at every effect,
    // and its 4 bytes fill what the union's 8-byte alignment would pad.
    int64_t start_delay_us = 0;
    int32_t duration_us = kInfiniteUs;
    int32_t trigger_repeat_interval_us = 0;
    Direction direction{};
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
    union {
        CurvedConditions curved;              // spring, damper, inertia, angle_spring
        ConditionBlock conditions[kMaxAxes];  // friction
        PeriodicBlock periodic;               // periodics and sweeps
        ConstantBlock constant;               // constant, vector_force, smart_pop
        RampBlock ramp;
        CustomBlock custom;                   // force_profile
        TextureBlock texture;
        WallBlock wall;                       // axis_wall, angle_wall
        BarrierBlock barrier;                 // axis_barrier, angle_barrier
        const DynamicBlock* dynamic;          // dynamics: the block in the effect's DynamicRecord
    };
};

// The stored form of valid parameters p. A dynamic's block is not copied: `dynamic` points
// at `dynamic_block`, which must hold p.dynamic for as long as the result is read (the
// engine passes its record's copy; a test may pass &p.dynamic).
[[nodiscard]] SlotParams slot_params(const EffectParams& p, const DynamicBlock* dynamic_block) noexcept;

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
