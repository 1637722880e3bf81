// Per-effect state of friction and texture conditions, kept in the effect's slot between
// ticks. The engine zeroes it when the effect is created and every time it starts, so the
// bristles start relaxed and take the handle's position at the first tick as their anchor.
#pragma once

#include <cstdint>

#include "conditions/friction_model.hpp"
#include "conditions/stop_guard.hpp"
#include "feel/axis.hpp"

namespace feel::detail {

// Whether friction_condition has its lean way for the common block (a second copy of a
// block's work, about 1.3 KB of Thumb code: a build for size, the Cortex-M4F firmware's,
// leaves it out, and every block takes the general way, which gives the same force).
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool kFrictionLeanWay = false;
#else
inline constexpr bool kFrictionLeanWay = true;
#endif

// What a friction block's law needs that changes only with its block or the tick period,
// worked out when one of them changes rather than every tick (issue 14: friction's cost per
// effect).
struct FrictionBlockLaw {
    // The block it was worked out for: the slot's block's six 16-bit values (its first 12
    // bytes, friction_condition.cpp's law_is_for), compared in one test. All ones (every value
    // -1: a saturation or deadband out of its range): not yet.
    uint32_t key[3] = {~0u, ~0u, ~0u};
    float pos = 0.0f, neg = 0.0f;     // the coefficients as floats
    float pos_limit = 0.0f, neg_limit = 0.0f;  // the saturations as floats
    float stiffness = 0.0f;           // the presliding stiffness K (friction_model.hpp)
    float inverse_presliding = 0.0f;  // K / f = 1/Z, 0 when f = 0
    float damping = 0.0f;             // -K·kBristleDampingTime: the microdamping's σ1
    GuardLimits limits{};             // the stop guard's (stop_guard.hpp); limits.f = max(|pos|, |neg|)
    // A still surface (offset 0), no deadband, both coefficients >= 0 and a presliding zone:
    // the block may take friction_condition's lean way once its bristle is primed.
    bool eligible = false;
    // eligible and the bristle primed (one test on the lean way): set with the law and after
    // the block's general way (a bristle is primed there, and only reset with the law).
    bool lean = false;
    // Equal coefficients and equal saturations on both sides (the same floats): the lean way's
    // choices of a side can be left out (friction_condition.cpp, render_lean_blocks).
    bool symmetric = false;
};

// What a texture's tick needs that changes only with its block or the tick period (issue 14,
// twelfth pass), kept in its block 0 where a friction keeps its law: the same values the
// tick used to work out every tick, so the same bits.
struct TextureLaw {
    // The texture's block it was worked out for: pos_roughness, neg_roughness, spacing,
    // density. (Read only after the tick period matched, which a fresh state never does: so
    // only once this member holds it.)
    int32_t key[4];
    float pos, neg;            // the roughnesses as floats
    float roughness;           // the larger: the bristle's f
    float presliding;          // its presliding distance Z at this tick period (friction_model.hpp)
    float inverse_presliding;  // 1/Z, 0 when Z = 0
    float spacing;             // the bumps' spacing, position units
    float inverse_spacing;     // 1/spacing (x86: the bump's ridge index, nearest_multiple_index)
    float width;               // their width: spacing · density / 10000
    bool bumps;                // spacing and width > 0 (texture_bump's test)
};

// One block's memory, kept together (issue 14: one stride through the blocks).
struct FrictionBlock {
    // friction: the block's bristle; texture: block 0's runs along the texture's line.
    Bristle bristle{};
    // The block's stop guard (stop_guard.hpp).
    StopGuard guard{};
    // The other effects' force along the block's line at the last tick (ConditionContext::
    // others_force), what its stiction held against, in this effect's units (before its gain
    // and the device's): friction_condition.cpp's release.
    float others = 0.0f;
    union {
        // friction: the block's law at this tick period (reset when it changes).
        FrictionBlockLaw law{};
        // texture, block 0: its law at this tick period (texture_condition.cpp), in the same
        // bytes (no RAM).
        TextureLaw texture;
    };
};
static_assert(sizeof(TextureLaw) <= sizeof(FrictionBlockLaw), "the texture's law takes no RAM of its own");

struct FrictionState {
    // friction: index i = the effect's i-th axis; texture: block 0.
    FrictionBlock block[kMaxAxes] = {};
    bool others_known = false;
    // Every block's law is for its block at this tick period (friction's lean way checks the
    // keys once an effect, not once a block): cleared when the tick period or the effect's
    // parameters change (remember_tick, ConditionState::params_changed). x86 only.
    bool laws_current = false;
    // With laws_current: every block's law is symmetric (FrictionBlockLaw::symmetric).
    bool laws_symmetric = false;
    // What every block shares at this tick period, recomputed only when it changes (issue
    // 14: friction's cost per effect): the guards' gains (an exp) and the microdamping's
    // 1/fade speed. (The presliding rule is worked out again with a block's law: rarely.)
    StopGuardTick guard_tick{};
    float inverse_fade_speed = 0.0f;
    // The tick length (s) the above are for, single precision (issue 14), as the contexts
    // carry it; texture keeps guard_tick and inverse_fade_speed under the same key.
    float tick_dt = -1.0f;
};

}  // namespace feel::detail
