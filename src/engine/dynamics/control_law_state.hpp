// Per-effect state of the control-law dynamics, kept in the effect's slot between ticks.
//
// Plain data, fixed size, single precision: the mass's stretch (its position relative to
// the handle) and velocity are float, advanced by the float propagators of each region of
// the law (tether_propagator.hpp), which are worked out once per command and tick length.
// docs/dynamics.md ("Precision") says why float keeps an undamped tether's energy.
#pragma once

#include <cstdint>

#include "dynamics/tether_propagator.hpp"
#include "feel/axis.hpp"

namespace feel::detail {

// One axis of the simulated mass.
struct TetherAxisState {
    // Position units: the mass relative to the handle at the current tick (the stretch).
    float stretch = 0;
    // Position units/s: the mass's velocity in the fixed frame; for a law simulated in the
    // handle's frame (TetherLaw::handle_frame), relative to the handle.
    float velocity = 0;
    int32_t half_cycles = 0;  // half oscillations completed so far, 0..
    int8_t side = 0;          // -1/+1: the side of its rest stretch the mass was last seen on
                              // beyond the hysteresis band; 0: not yet seen off it
};

// One axis of the law in float, and the propagators of its three regions for one piece
// length: what every tick needs, worked out when the parameters or the tick length change.
struct PreparedTether {
    // The propagators below are for pieces of this many per step of step_s seconds (0: none
    // yet).
    float step_s = 0;
    int32_t pieces = 1;
    float mass = 1, k_pos = 1, k_neg = 1, b = 0, drag = 0, gravity = 0, length = 0;
    float pos_init = 0, vel_init = 0;
    int32_t half_cycles = 0;
    bool handle_frame = false;
    bool piecewise = false;  // free play, or k_pos != k_neg: regions must be tracked
    // One region, nothing counted, in the fixed frame (recoil, impact, liquid, center
    // drift): a tick is two propagators (control_law_dynamic.cpp's plain_tick). It fills
    // the padding after the flags above.
    bool plain = false;
    TetherPropagator below{}, slack{}, above{};
#if !defined(__OPTIMIZE_SIZE__)
    // What a law with one region that counts nothing needs each tick and only the command
    // and the tick length fix, worked out with the propagators (prepare_pieces) by the
    // operations the tick did, so the same bits: the prediction's impulse as a linear form
    // of the caught-up state (weighted_change_form of `above`), the weight M·g and its
    // impulse over the step M·g·h. Not in a build for size (the Cortex-M4F image, whose RAM
    // is the tighter budget), which works them out each tick (tether_tick.hpp).
    WeightedChangeForm prediction_form{};
    float weight = 0;          // force units
    float weight_impulse = 0;  // force units·s
#endif
};

struct ControlLawState {
    // The mass at the time of the current tick, per EFFECT axis (axes[i] of the params).
    TetherAxisState now[kMaxAxes] = {};
    // The handle at the current tick: where the sensor saw it and the velocity the engine
    // estimated. The next tick advances the mass from here (control_law_dynamic.cpp).
    float handle_position[kMaxAxes] = {};      // position units
    float handle_velocity[kMaxAxes] = {};      // position units/s
    float handle_acceleration[kMaxAxes] = {};  // position units/s², as the estimator gave it
#if !defined(__OPTIMIZE_SIZE__)
    // The mass where this tick's prediction ended, and the handle's velocity along the line
    // it followed: the next tick's catch-up takes it when its line is the same
    // (DynamicState::kept_ahead, control_law_dynamic.cpp). Not in a build for size (the
    // Cortex-M4F image, whose RAM is the tighter budget), which advances twice.
    float ahead_stretch[kMaxAxes] = {};   // position units
    float ahead_velocity[kMaxAxes] = {};  // position units/s
    float ahead_line[kMaxAxes] = {};      // position units/s
    // Every axis's law has regions to track in one piece a step and counts nothing (the
    // control law with play, Dynamic Inertia): the tick takes watched_tick
    // (control_law_dynamic.cpp). Set with the pieces, cleared with the laws.
    bool watched = false;
#endif
    // The laws of the effect's axes (false after every command that sets parameters:
    // DynamicState::prepared).
    PreparedTether laws[kMaxAxes] = {};
};

}  // namespace feel::detail
