// The validator's table of fields (effect_validation.cpp): for each block of EffectParams,
// the fields it checks, in the order it checks them, each with where it lives and what it
// must hold. One row a field, 8 bytes on the Cortex-M4, where written-out checks took about
// 40 (docs/firmware.md, "The fourth size pass"). A row's name is the C++ member's (#member),
// which is also the sensation format's (src/format/effect_fields.cpp names the same members).
#pragma once

#include <cstddef>
#include <cstdint>

#include "feel/effect.hpp"
#include "feel/units.hpp"

namespace feel::detail::field_rules {

// What a field must hold: one of the ranges of units.hpp, or (kChoice and up) one of a
// few enumerators, refused with the rule that names them.
enum Check : uint8_t {
    kLevel, kSignedLevel, kPositiveLevel, kAngle, kDelayUs, kPeriodUs, kGain, kDynamicMass,
    kDynamicStiffness, kHalfCycles, kChannels, kSampleCount,
    kChoice,
    kOffsetModeChoice = kChoice, kWallSenseChoice, kSweepSenseChoice,
};

inline constexpr Range kRanges[kChoice] = {
    range::kLevel,         range::kSignedLevel,  range::kPositiveLevel,     range::kAngle,
    range::kDelayUs,       range::kPeriodUs,     range::kGain,              range::kDynamicMass,
    range::kDynamicStiffness, range::kHalfCycles, range::kChannels,         range::kSampleCount,
};

struct Choice {
    int64_t last;      // the enumerators are 0..last
    const char* rule;  // the error's sentence
};

inline constexpr Choice kChoices[] = {
    {1, "the offset mode must be absolute or relative"},             // OffsetMode
    {1, "the sense must be positive or negative"},                   // WallSense
    {1, "the sweep sense must be clockwise or counterclockwise"},    // SweepSense
};

// One checked field of a block. Its name is the member's, which is also the format's.
struct FieldRule {
    const char* name;
    uint16_t offset;  // bytes into its block
    uint8_t width;    // 1 (an enum), 4 (int32_t) or 8 (int64_t)
    Check check;
};

#define FEEL_FIELD(Block, member, check)                                                   \
    FieldRule {                                                                           \
        #member, static_cast<uint16_t>(offsetof(Block, member)),                          \
            static_cast<uint8_t>(sizeof(Block::member)), check                            \
    }

inline constexpr FieldRule kTimingRules[] = {
    FEEL_FIELD(EffectParams, start_delay_us, kDelayUs),
    FEEL_FIELD(EffectParams, gain, kGain),
};

inline constexpr FieldRule kEnvelopeRules[] = {
    FEEL_FIELD(Envelope, impulse_level, kLevel),
    FEEL_FIELD(Envelope, settle_time_us, kDelayUs),
    FEEL_FIELD(Envelope, fade_level, kLevel),
    FEEL_FIELD(Envelope, fade_time_us, kDelayUs),
};

inline constexpr FieldRule kConditionRules[] = {
    FEEL_FIELD(ConditionBlock, pos_coefficient, kSignedLevel),
    FEEL_FIELD(ConditionBlock, neg_coefficient, kSignedLevel),
    FEEL_FIELD(ConditionBlock, offset, kSignedLevel),
    FEEL_FIELD(ConditionBlock, pos_saturation, kLevel),
    FEEL_FIELD(ConditionBlock, neg_saturation, kLevel),
    FEEL_FIELD(ConditionBlock, deadband, kLevel),
};

inline constexpr FieldRule kTextureRules[] = {
    FEEL_FIELD(TextureBlock, pos_roughness, kPositiveLevel),
    FEEL_FIELD(TextureBlock, neg_roughness, kPositiveLevel),
    FEEL_FIELD(TextureBlock, spacing, kPositiveLevel),
    FEEL_FIELD(TextureBlock, density, kPositiveLevel),
};

// A wall's and a barrier's fields before their angle, and after it.
inline constexpr FieldRule kWallRules[] = {
    FEEL_FIELD(WallBlock, hardness, kSignedLevel),
    FEEL_FIELD(WallBlock, sense, kWallSenseChoice),
    FEEL_FIELD(WallBlock, offset, kSignedLevel),
    FEEL_FIELD(WallBlock, offset_mode, kOffsetModeChoice),
};

inline constexpr FieldRule kWallSurfaceRules[] = {
    FEEL_FIELD(WallBlock, surface_friction, kLevel),
    FEEL_FIELD(WallBlock, surface_texture, kLevel),
};

inline constexpr FieldRule kBarrierRules[] = {
    FEEL_FIELD(BarrierBlock, pos_hardness, kSignedLevel),
    FEEL_FIELD(BarrierBlock, neg_hardness, kSignedLevel),
    FEEL_FIELD(BarrierBlock, thickness, kPositiveLevel),
    FEEL_FIELD(BarrierBlock, offset, kSignedLevel),
    FEEL_FIELD(BarrierBlock, offset_mode, kOffsetModeChoice),
};

inline constexpr FieldRule kBarrierSurfaceRules[] = {
    FEEL_FIELD(BarrierBlock, surface_friction, kLevel),
    FEEL_FIELD(BarrierBlock, surface_texture, kLevel),
};

// §6.6.b: a periodic magnitude is 0..10000; §6.6.i: an advanced periodic (sweep) one is signed.
inline constexpr FieldRule kPeriodicRules[] = {
    FEEL_FIELD(PeriodicBlock, magnitude, kLevel),
    FEEL_FIELD(PeriodicBlock, offset, kSignedLevel),
    FEEL_FIELD(PeriodicBlock, period_us, kPeriodUs),
    FEEL_FIELD(PeriodicBlock, phase, kAngle),
};

inline constexpr FieldRule kSweepRules[] = {
    FEEL_FIELD(PeriodicBlock, magnitude, kSignedLevel),
    FEEL_FIELD(PeriodicBlock, offset, kSignedLevel),
    FEEL_FIELD(PeriodicBlock, period_us, kPeriodUs),
    FEEL_FIELD(PeriodicBlock, phase, kAngle),
    FEEL_FIELD(PeriodicBlock, sweep_start_angle, kAngle),
    FEEL_FIELD(PeriodicBlock, sweep_end_angle, kAngle),
    FEEL_FIELD(PeriodicBlock, sweep_sense, kSweepSenseChoice),
};

inline constexpr FieldRule kConstantRules[] = {FEEL_FIELD(ConstantBlock, magnitude, kSignedLevel)};

inline constexpr FieldRule kRampRules[] = {
    FEEL_FIELD(RampBlock, start, kSignedLevel),
    FEEL_FIELD(RampBlock, end, kSignedLevel),
};

inline constexpr FieldRule kCustomRules[] = {
    FEEL_FIELD(CustomBlock, channels, kChannels),
    FEEL_FIELD(CustomBlock, sample_period_us, kPeriodUs),
    FEEL_FIELD(CustomBlock, sample_count, kSampleCount),
};

// §8.4: each wrapper parameter has the range of the control-law parameter it maps to.
inline constexpr FieldRule kRecoilRules[] = {
    FEEL_FIELD(DynamicBlock, blast_direction, kAngle),
    FEEL_FIELD(DynamicBlock, blast_intensity, kSignedLevel),
    FEEL_FIELD(DynamicBlock, dynamic_mass, kDynamicMass),
    FEEL_FIELD(DynamicBlock, blast_resonance, kDynamicStiffness),
    FEEL_FIELD(DynamicBlock, blast_decay, kLevel),
};

inline constexpr FieldRule kImpactRules[] = {
    FEEL_FIELD(DynamicBlock, impact_direction, kAngle),
    FEEL_FIELD(DynamicBlock, impact_intensity, kSignedLevel),
    FEEL_FIELD(DynamicBlock, dynamic_mass, kDynamicMass),
    FEEL_FIELD(DynamicBlock, elasticity, kDynamicStiffness),
    FEEL_FIELD(DynamicBlock, collision_absorption, kLevel),
};

inline constexpr FieldRule kLiquidRules[] = {
    FEEL_FIELD(DynamicBlock, density, kDynamicMass),
    FEEL_FIELD(DynamicBlock, settle, kDynamicStiffness),
    FEEL_FIELD(DynamicBlock, viscosity, kLevel),
};

inline constexpr FieldRule kInertiaRules[] = {
    FEEL_FIELD(DynamicBlock, inertia, kDynamicMass),
    FEEL_FIELD(DynamicBlock, play, kLevel),
};

inline constexpr FieldRule kCenterDriftRules[] = {
    FEEL_FIELD(DynamicBlock, stiffness, kDynamicStiffness),
    FEEL_FIELD(DynamicBlock, drift_resistance, kLevel),
};

inline constexpr FieldRule kSlingRules[] = {
    FEEL_FIELD(DynamicBlock, ball_mass, kDynamicMass),
    FEEL_FIELD(DynamicBlock, string_length, kLevel),
    FEEL_FIELD(DynamicBlock, string_compliance, kDynamicStiffness),
    FEEL_FIELD(DynamicBlock, ball_damping, kLevel),
};

inline constexpr FieldRule kPaddleRules[] = {
    FEEL_FIELD(DynamicBlock, ball_mass, kDynamicMass),
    FEEL_FIELD(DynamicBlock, initial_velocity, kSignedLevel),
    FEEL_FIELD(DynamicBlock, initial_velocity_direction, kAngle),
    FEEL_FIELD(DynamicBlock, paddle_compliance, kDynamicStiffness),
    FEEL_FIELD(DynamicBlock, paddle_damping, kLevel),
    FEEL_FIELD(DynamicBlock, gravity, kSignedLevel),
};

inline constexpr FieldRule kControlLawRules[] = {
    FEEL_FIELD(ControlLawBlock, mass, kDynamicMass),
    FEEL_FIELD(ControlLawBlock, k_pos, kDynamicStiffness),
    FEEL_FIELD(ControlLawBlock, k_neg, kDynamicStiffness),
    FEEL_FIELD(ControlLawBlock, b, kLevel),
    FEEL_FIELD(ControlLawBlock, vel_init, kSignedLevel),
    FEEL_FIELD(ControlLawBlock, pos_init, kSignedLevel),
    FEEL_FIELD(ControlLawBlock, half_cycles, kHalfCycles),
    FEEL_FIELD(ControlLawBlock, length, kLevel),
    FEEL_FIELD(ControlLawBlock, drag, kLevel),
    FEEL_FIELD(ControlLawBlock, gravity, kSignedLevel),
};

#undef FEEL_FIELD

}  // namespace feel::detail::field_rules
