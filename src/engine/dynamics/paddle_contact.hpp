// The ball against the paddle along the paddle's normal: a one-sided spring-damper contact
// (§5.9's compression and rebound stages), integrated exactly.
//
// Coordinates. y is the ball's distance in front of the paddle's rest plane along its
// normal n (which faces the incoming ball), in position units: y > 0 the ball is in front
// of the paddle, y < 0 it has pressed the paddle's surface in by −y. v = dy/dt is taken
// against the handle, which moves at constant velocity over a step (ball_tick.hpp), so
// the frame is inertial and no fictitious force appears.
//
// The contact is a Kelvin-Voigt element (spring k, damper b) that can only push:
//
//     F = max(0, −k·y − b·(v + δ))   while y < 0,   0 otherwise          (on the ball, along n)
//
// δ reconciles two views of the handle's speed (ball_tick.hpp): the spring sees the
// handle's path, but the damper reads the engine's smoothed velocity estimate, which is
// the path's speed minus δ along n (δ constant over a step; 0 when they agree).
//
// "Pushes only" decides when the ball leaves. On the way out the damper opposes the
// rebound, and the spring-damper force reaches zero while the surface is still pressed in
// (y < 0): from then on a real paddle's surface, relaxing at its own rate, cannot keep up
// with the ball, which flies free. So the ball is pressing exactly while F would be
// positive. For a ball of speed V meeting a still paddle (no gravity), with ω² = k/m,
// ζ = b/(2√(km)), ω_d = ω√(1 − ζ²), this gives the contact time and the coefficient of
// restitution
//
//     t_c = (π − 2·asin ζ) / ω_d,    e = exp(−ζ·(π − 2·asin ζ) / √(1 − ζ²))      (ζ < 1)
//
// (e → e⁻² at ζ = 1; beyond, e = r^((1 + r)/(1 − r)) with r = (ζ − √(ζ² − 1))/(ζ + √(ζ² − 1))).
// A contact allowed to pull until y = 0 would last π/ω_d and return exp(−ζπ/√(1 − ζ²)); the
// two agree to first order in ζ, and the pushes-only rebound is the slightly livelier.
//
// Gravity g (position units/s², any sign) pulls the ball toward the paddle, along −n,
// in both stages: a ball can rest on a paddle (pressed in by m·g/k).
//
// Integration. Between changes of stage the motion is linear with constant coefficients,
// so it is advanced with its exact solution (tether_step.hpp): a damped oscillation (all
// three damping regimes) while pressing, a parabola while free. The instants the stage
// changes are found by bisection on that exact solution, within the tick, so the rebound
// does not depend on where the ticks fall. The tick is cut into pieces short enough
// (ω·h ≤ 1/2) that a stage cannot begin and end unseen inside one.
//
// Precision: float, on every build (issue 14: a Cortex-M4F has a single-precision FPU
// only). The exact step is tether_step's float instantiation, the control laws' (its
// increments keep a piece's rounding that of the change, not of the state, and near
// critical damping it takes its series); the bisection stops where float cannot split the
// bracket further (2^-24 of the piece). A bounce's velocity comes out within a few tens of
// float's 2^-24 of the closed form (tests/engine/dynamics/paddle_test.cpp).
//
// Real-time safe: no allocation; a bounded number of steps per tick.
#pragma once

namespace feel::detail {

struct PaddleContactParams {
    float mass = 1;           // m, force units per (position unit/s²), > 0
    float stiffness = 1;      // k, force units per position unit, > 0
    float damping = 0;        // b, force units per (position unit/s), >= 0
    float gravity = 0;        // g, position units/s² toward the paddle (along −n), any sign
    float damper_offset = 0;  // δ, position units/s: the damper reads v + δ
};

struct PaddleContact {
    float y = 0;           // position units, along n from the paddle's rest plane
    float v = 0;           // position units/s, dy/dt
    bool pressed = false;  // the ball is pressing the paddle (F > 0)
    float contact_s = 0;   // time spent pressing, s, accumulated
};

// The contact's push on the ball along n in state (y, v), force units, >= 0.
[[nodiscard]] float paddle_contact_force(const PaddleContactParams& p, float y, float v) noexcept;

// Whether a ball in state (y, v) presses the paddle: y < 0 and the push is positive.
[[nodiscard]] bool paddle_presses(const PaddleContactParams& p, float y, float v) noexcept;

// Advances the contact exactly by dt_s (>= 0), stage changes included. Returns the impulse
// the paddle gave the ball along n over the step, force units·s (>= 0), from the momentum
// balance m·Δv = J − m·g·dt.
float advance_paddle_contact(PaddleContact& c, const PaddleContactParams& p, float dt_s) noexcept;

}  // namespace feel::detail
