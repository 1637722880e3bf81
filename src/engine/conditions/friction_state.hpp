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
    // The guards' shared gains, recomputed only when the tick period changes (an exp each).
    StopGuardTick guard_tick{};
    double guard_tick_dt_s = -1.0;
};

}  // namespace feel::detail
