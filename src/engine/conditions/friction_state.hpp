// Per-effect state of friction and texture conditions, kept in the effect's slot between
// ticks. The engine zeroes it when the effect is created and every time it starts, so the
// bristles start relaxed and take the handle's position at the first tick as their anchor.
#pragma once

#include <cstdint>

#include "conditions/friction_model.hpp"
#include "conditions/stop_guard.hpp"
#include "feel/axis.hpp"

namespace feel::detail {

// What a friction block's law needs that changes only with its coefficients or the tick
// period, worked out when one of them changes rather than every tick (issue 14: friction's
// cost per effect).
struct FrictionBlockLaw {
    // The coefficients it was worked out for; INT32_MIN (out of their range): not yet.
    int32_t pos_coefficient = INT32_MIN;
    int32_t neg_coefficient = INT32_MIN;
    float pos = 0.0f, neg = 0.0f;     // the coefficients as floats
    float magnitude = 0.0f;           // f = max(|pos|, |neg|)
    float stiffness = 0.0f;           // the presliding stiffness K (friction_model.hpp)
    float inverse_presliding = 0.0f;  // K / f = 1/Z, 0 when f = 0
    float damping = 0.0f;             // -K·kBristleDampingTime: the microdamping's σ1
    GuardLimits limits{};             // the stop guard's (stop_guard.hpp)
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
    // friction: the block's law at this tick period (reset when it changes).
    FrictionBlockLaw law{};
};

struct FrictionState {
    // friction: index i = the effect's i-th axis; texture: block 0.
    FrictionBlock block[kMaxAxes] = {};
    bool others_known = false;
    // What every block shares at this tick period, recomputed only when it changes (issue
    // 14: friction's cost per effect): the guards' gains (an exp), the presliding rule's
    // bounds 2b/T and the resolution cap, and the microdamping's 1/fade speed.
    StopGuardTick guard_tick{};
    float passive = 0.0f, cap = 0.0f, inverse_fade_speed = 0.0f;
    double tick_dt_s = -1.0;
};

}  // namespace feel::detail
