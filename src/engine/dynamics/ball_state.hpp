// Per-effect state of the sling and paddle balls, kept in the effect's slot between ticks.
//
// The engine zeroes it when the effect is created and every time it starts; the model
// fills it on its first playing tick (DynamicState::initialized). Plain data, fixed size.
// ball_tick.hpp explains how a tick uses it.
#pragma once

#include "feel/axis.hpp"

namespace feel::detail {

// The ball at one instant.
struct BallMotion {
    // In the fixed frame, per DEVICE axis (only the effect's axes are used): position in
    // position units (±10000 is the handle's travel; the ball may be anywhere) and
    // velocity in position units/s. Double: a sling may spin for hours and its energy must
    // not drift with rounding.
    double position[kMaxAxes] = {};
    double velocity[kMaxAxes] = {};
    // Paddle only: the ball is pressing the paddle (the contact pushes), or flying free.
    bool pressed = false;
    // Paddle only: time spent pressing the paddle since the event began, s (>= 0). A
    // diagnostic: an elastic bounce off a still paddle lasts π/ω.
    double contact_s = 0;
};

struct BallState {
    BallMotion now{};  // at the current tick
    // The handle at the current tick, per device axis: where the sensor saw it (position
    // units) and the velocity the engine estimated (position units/s). The next tick
    // advances the ball from here.
    double handle[kMaxAxes] = {};
    double handle_velocity[kMaxAxes] = {};
};

}  // namespace feel::detail
