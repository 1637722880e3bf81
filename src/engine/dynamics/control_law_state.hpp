// Per-effect state of the control-law dynamics, kept in the effect's slot between ticks.
//
// Plain data, fixed size, double precision: an undamped tether must keep its energy for
// minutes (docs/dynamics.md), and float rounding at every tick would not.
#pragma once

#include <cstdint>

#include "feel/axis.hpp"

namespace feel::detail {

// One axis of the simulated mass. Positions and velocities are absolute (not relative to
// the handle), so that the handle's sensed motion between ticks needs no bookkeeping here.
struct TetherAxisState {
    double position = 0;      // position units, absolute
    double velocity = 0;      // position units/s, absolute
    int32_t half_cycles = 0;  // half oscillations completed so far, 0..
    int8_t side = 0;          // -1/+1: the side of its rest stretch the mass was last seen on
                              // beyond the hysteresis band; 0: not yet seen off it
};

struct ControlLawState {
    // The mass at the time of the current tick, per EFFECT axis (axes[i] of the params).
    // For a law simulated in the handle's frame (TetherLaw::handle_frame), relative to the
    // handle: position = stretch, velocity = its rate.
    TetherAxisState now[kMaxAxes] = {};
    // The handle at the current tick: where the sensor saw it and the velocity the engine
    // estimated. The next tick advances the mass from here (control_law_dynamic.cpp).
    double handle_position[kMaxAxes] = {};  // position units
    double handle_velocity[kMaxAxes] = {};  // position units/s
    float handle_acceleration[kMaxAxes] = {};  // position units/s², as the estimator gave it
};

}  // namespace feel::detail
