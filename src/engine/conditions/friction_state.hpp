// Per-effect state of friction and texture conditions, kept in the effect's slot between
// ticks. The engine zeroes it when the effect is created and every time it starts, so the
// bristles start relaxed and take the handle's position at the first tick as their anchor.
#pragma once

#include "conditions/friction_model.hpp"
#include "conditions/stop_guard.hpp"
#include "feel/axis.hpp"

namespace feel::detail {

struct FrictionState {
    // friction: one bristle per block, index i = the effect's i-th axis.
    // texture: bristle 0 runs along the texture's line.
    Bristle bristle[kMaxAxes] = {};
    // friction: the stop guard of each block (stop_guard.hpp).
    StopGuard guard[kMaxAxes] = {};
    // The other effects' force along each block's line at the last tick (ConditionContext::
    // others_force), what its stiction held against, in this effect's units (before its gain
    // and the device's): friction_condition.cpp's release.
    float others[kMaxAxes] = {};
    bool others_known = false;
    // What every block shares at this tick period, recomputed only when it changes (issue
    // 14: friction's cost per effect): the guards' gains (an exp), the presliding rule's
    // bounds 2b/T and the resolution cap, and the microdamping's 1/fade speed.
    StopGuardTick guard_tick{};
    float passive = 0.0f, cap = 0.0f, inverse_fade_speed = 0.0f;
    double tick_dt_s = -1.0;
};

}  // namespace feel::detail
