// Per-effect state of the sling and paddle balls, kept in the effect's slot between ticks.
//
// The engine zeroes it when the effect is created and every time it starts; the model
// fills it on its first playing tick (DynamicState::initialized). Plain data, fixed size.
// ball_tick.hpp explains how a tick uses it.
//
// Float, and relative to the handle (issue 14: no double on the Cortex-M4F's tick; docs/
// dynamics.md "Sling and paddle", precision). The handle's sensed position is float
// already; the ball is kept as its offset from the handle, as the control law keeps its
// stretch, so its resolution is that of the string's or the paddle's reach (a string of
// 10000 units: 2^-10 of a unit), not of where on the travel the handle happens to be.
#pragma once

#include <cstdint>
#include <limits>

#include "feel/axis.hpp"

namespace feel::detail {

// The ball at one instant.
struct BallMotion {
    // Per DEVICE axis (only the effect's axes are used): the ball minus the handle sensed at
    // the same tick (BallState::handle), position units, and the ball's velocity in the
    // fixed frame, position units/s (the air and the paddle's impact speed are in the fixed
    // frame).
    float offset[kMaxAxes] = {};
    float velocity[kMaxAxes] = {};
    // Paddle only: the ball is pressing the paddle (the contact pushes), or flying free.
    bool pressed = false;
    // Paddle only: time spent pressing the paddle since the event began, s (>= 0). A
    // diagnostic: an elastic bounce off a still paddle lasts π/ω.
    float contact_s = 0;
};

// Sling only: the constants of a run of Verlet steps over one advance (sling_dynamic.cpp's
// Sling::VerletRun says what each is for). No initializers: a run's own are set before
// they are read, and the form's are zeroed with the ball (BallState{}).
struct SlingSteps {
    int32_t count;       // the steps
    float h;             // their length, s
    float half_h;        // h/2
    float half_drag;     // D = e^(−c·h/2m), the air over half a step
    float drag_squared;  // D²
    float kick_gain;     // (h/2)·(1 + D²)
    float move_pull;     // h·kick_gain·k·L/m
    float move_rate;     // h·kick_gain·k/m
};

// Sling only: its parameters in float, and the steps of an advance of advance_s seconds,
// worked out again when the parameters change (DynamicState::prepared) or the tick's length
// does, not every tick (sling_dynamic.cpp).
struct SlingForm {
    float advance_s = 0;     // the advance steps is for; 0: none yet
    float mass = 1;          // m
    float length = 0;        // L
    float drag = 0;          // c
    float rate_squared = 0;  // ω² = k/m
    float rate_length = 0;   // ω²·L
    float rate = 0;          // ω
    SlingSteps steps{};
    // The string's pull (per unit mass and of r) at the squared distance end_r2, as the
    // last advance ended: the next advance starting there (this tick's prediction, the next
    // tick's catch-up) starts at the same pull. NaN: none (a new law, work_out_law).
    float end_r2 = std::numeric_limits<float>::quiet_NaN();
    float end_pull = 0;
};

struct BallState {
    BallMotion now{};  // at the current tick
    // The handle at the current tick, per device axis: where the sensor saw it (position
    // units) and the velocity the engine estimated (position units/s). The next tick
    // advances the ball from here.
    float handle[kMaxAxes] = {};
    float handle_velocity[kMaxAxes] = {};
    SlingForm sling{};  // the sling's constants (the paddle keeps none)
};

}  // namespace feel::detail
