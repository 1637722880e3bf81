// Direction conventions (§6.5): from an effect's Direction to a force on each device axis.
//
// Every form names where the force comes FROM; the force pushes the opposite way.
//
//   polar, compass clockwise from north      spherical (§6.5.c)
//            N 0 (+y)                               +z
//            |                                       |  elevation φ from +z
//   W 27000 -+- E 9000 (+x)                          |/
//            |                                       +----- +x, azimuth θ toward +y
//          S 18000
//   from = (sin a, cos a) in (x, y)          from = (sinφ cosθ, sinφ sinθ, cosφ)
//
// cartesian and moments: the given vector, normalized, over the effect's axes in order.
// none: a single-axis effect's value drives its axis with its own (physical) sign.
#pragma once

#include "feel/effect.hpp"
#include "slot_params.hpp"

namespace feel::detail {

// Fills factors[device axis] so that force on that axis = factors[axis] · value.
// Assumes validate_effect() accepted the params. Axes the effect does not use get 0.
void direction_factors(const SlotParams& params, float factors[kMaxAxes]) noexcept;

// The factors for a compass angle (whole hundredths of a degree, any int32) on x, y.
// Float, by turn_trig.hpp's polynomial, exact at the cardinal points: once per command.
void polar_factors(int32_t angle_centideg, float factors[kMaxAxes]) noexcept;
// The same for an angle in turns, in single precision (turn_trig.hpp): a sweep's
// direction, every tick. Exact at the cardinal points too.
void polar_factors_turns(float turns, float factors[kMaxAxes]) noexcept;

}  // namespace feel::detail
