// The number of device axes an engine build keeps state for.
//
// The public types (EffectParams, TickInput, TickOutput, DynamicReport) carry kMaxAxes (6)
// axes, so that every host speaks the same API. The engine's own per-axis storage (the
// velocity estimator's history, a slot's condition curves and friction bristles, the
// report queue) needs only as many axes as the device has, and on a microcontroller that
// difference is most of the RAM: the estimator's history for 6 axes is twice the size of
// the one for 2. So that storage is sized by kEngineAxes, a capacity fixed when the engine
// is compiled, in the way an embedded physics library fixes its limits: hosts keep 6 (the
// default), the Cortex-M4F firmware for a 2-axis device builds with FEEL_ENGINE_AXES=2
// (firmware/CMakeLists.txt). An EngineConfig with more axes than the build keeps is refused
// by the constructor's check (check_engine_config), naming the allowed range; an effect can
// only name the device's axes (Engine::create), so every device-axis index stays below it.
//
// Arrays the effect code walks to kMaxAxes (directions, start positions, the dynamics'
// masses) stay kMaxAxes: only storage whose every use is bounded by the device's or the
// effect's axis count is sized by kEngineAxes.
#pragma once

#include "feel/axis.hpp"

#ifndef FEEL_ENGINE_AXES
#define FEEL_ENGINE_AXES 6
#endif

namespace feel::detail {

inline constexpr int kEngineAxes = FEEL_ENGINE_AXES;
static_assert(kEngineAxes >= 1 && kEngineAxes <= kMaxAxes, "FEEL_ENGINE_AXES must be 1..6 (kMaxAxes)");

}  // namespace feel::detail
