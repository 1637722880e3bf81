// How a tick of the sling (§5.8) or the paddle (§5.9) goes: the scheme of the control-law
// dynamics (control_law_dynamic.cpp, docs/dynamics.md "The tick, and why it is stable"),
// for a ball that moves in several axes.
//
// The engine computes a force once per tick and the motor holds it until the next. A
// string or paddle force sampled at the tick and held lags the real one by half a tick,
// and a lagging spring between the handle and a mass pumps energy into the pair: a heavy
// ball on a stiff string, coupled to a free handle that way, rings. So each tick:
//
//   1. Catch up: the ball is advanced from the previous tick to this one against the path
//      the sensor saw, the handle moving in a straight line from where it was sensed then
//      to where it is sensed now, so the string or paddle never sees the handle jump. A
//      damper between ball and handle (the paddle's) measures against the velocity the
//      engine estimated, not the slope of that line: a sensor count crossed in one tick
//      would read as a velocity spike.
//   2. Predict: a copy of the ball is advanced one more tick (as long as the last one)
//      against the handle going on along that line from where it is now. The impulse the
//      string or paddle gives the ball over that tick, divided by its length, is the mean
//      force over the tick the motor is about to hold; the handle gets its reaction.
//
// The handle thus receives, over every tick, the reaction impulse of what the ball
// receives if the hand carries on as it was going: ball and handle exchange momentum
// without the half-tick lag of a held sample (exactly, while the handle moves at a steady
// velocity), and a contact shorter than a tick still hands over its whole impulse. Before
// there are two sensed positions (the effect's first tick) the handle is expected to move
// at its estimated velocity; on the engine's very first tick there is no tick length to
// predict over, and the force is the instantaneous reaction.
//
// A gap between ticks longer than kBallMaxAdvanceS is a stall (the host stopped ticking),
// not motion: one tick advances the ball by at most that much (the handle covering the
// whole line in it), so the ball's world pauses instead of leaping the stall in one step.
#pragma once

#include <algorithm>
#include <cmath>

#include "dynamics/dynamic.hpp"

namespace feel::detail {

// 100 ms: a hundred ticks of the 1 kHz loop.
inline constexpr double kBallMaxAdvanceS = 0.1;

// The handle over a step, per device axis: moving at constant velocity from `from`.
struct BallHandlePath {
    double from[kMaxAxes] = {};             // position units, at the start of the step
    double velocity[kMaxAxes] = {};         // position units/s, the path's
    double damper_velocity[kMaxAxes] = {};  // position units/s, what a damper to the handle reads
};

// One tick of a ball model. Model provides
//   void start(BallMotion&, const DynamicContext&): the ball on the effect's first tick;
//   void advance(BallMotion&, const BallHandlePath&, double h, double impulse[kMaxAxes]):
//       the ball after h seconds, exactly or to its integrator's accuracy, and the impulse
//       the string or paddle gave it (force units·s, per device axis);
//   void reaction(const BallMotion&, const DynamicContext&, double force[kMaxAxes]): the
//       instantaneous force on the handle (the engine's first tick only).
// Adds the force on the handle to force[], on the device axes the model moves in (axes[0 ..
// count-1]): the handle's other axes never reach the model, so the tick reads and divides
// only these (a double division each, and the other axes' force is 0 either way).
// A tick in three parts, so that ball_tick_pair can run two balls' advances side by side.
// The first: the ball on its first tick, or the handle's sensed path to catch up along
// (returns true when there is one, with the advance's length in *step).
template <typename Model>
bool ball_catch_up_path(const Model& model, const int* axes, int count, const DynamicContext& c,
                        BallHandlePath& seen, double& step) noexcept {
    BallState& ball = c.state->ball;
    step = std::min(c.dt_s, kBallMaxAdvanceS);  // how far the ball advances
    if (!c.state->initialized) {
        c.state->ball = BallState{};  // the union member (DynamicState) begins here
        model.start(ball.now, c);
        c.state->initialized = true;
        return false;
    }
    if (!(c.dt_s > 0)) return false;
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        seen.from[a] = ball.handle[a];
        seen.velocity[a] = (c.position[a] - ball.handle[a]) / step;
        seen.damper_velocity[a] = ball.handle_velocity[a];
    }
    return true;
}

// The second: the path the handle is expected to take over the next tick (the handle's
// state moves to now). `fresh`: no line through two positions yet, read before the first part.
inline void ball_expected_path(const int* axes, int count, const DynamicContext& c, bool fresh,
                               BallHandlePath& expected) noexcept {
    BallState& ball = c.state->ball;
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        expected.from[a] = c.position[a];
        expected.velocity[a] = fresh ? c.velocity[a] : (c.position[a] - ball.handle[a]) / c.dt_s;
        expected.damper_velocity[a] = c.velocity[a];
        ball.handle[a] = c.position[a];
        ball.handle_velocity[a] = c.velocity[a];
    }
}

// The third: the predicted impulse's mean force over the tick, the handle's reaction.
inline void ball_add_reaction(const int* axes, int count, const double impulse[kMaxAxes], double step,
                              double force[kMaxAxes]) noexcept {
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        const double pull = -impulse[a] / step;
        force[a] += std::isfinite(pull) ? pull : 0.0;
    }
}

template <typename Model>
void ball_tick(const Model& model, const int* axes, int count, const DynamicContext& c, double force[kMaxAxes]) noexcept {
    BallState& ball = c.state->ball;
    const bool fresh = !c.state->initialized || !(c.dt_s > 0);  // no line through two positions yet
    BallHandlePath seen;
    double step = 0;
    if (ball_catch_up_path(model, axes, count, c, seen, step)) {
        double ignored[kMaxAxes] = {};
        model.advance(ball.now, seen, step, ignored);
    }
    BallHandlePath expected;
    ball_expected_path(axes, count, c, fresh, expected);
    if (step > 0) {
        BallMotion ahead = ball.now;
        double impulse[kMaxAxes] = {};
        model.advance(ahead, expected, step, impulse);
        ball_add_reaction(axes, count, impulse, step, force);
    } else {
        model.reaction(ball.now, c, force);
    }
}

// Two balls' ticks, each exactly as ball_tick's, with their advances run side by side by
// Model::advance_pair(model_a, ball, path, h, impulse, model_b, ...) (sling_dynamic.cpp
// says why). The balls' states are separate, so the parts' order between them is free.
template <typename Model>
void ball_tick_pair(const Model& model_a, const DynamicContext& a, double force_a[kMaxAxes], const Model& model_b,
                    const DynamicContext& b, double force_b[kMaxAxes]) noexcept {
    BallState& ball_a = a.state->ball;
    BallState& ball_b = b.state->ball;
    const bool fresh_a = !a.state->initialized || !(a.dt_s > 0);
    const bool fresh_b = !b.state->initialized || !(b.dt_s > 0);
    BallHandlePath seen_a;
    BallHandlePath seen_b;
    double step_a = 0;
    double step_b = 0;
    const bool catch_up_a = ball_catch_up_path(model_a, model_a.axes, model_a.count, a, seen_a, step_a);
    const bool catch_up_b = ball_catch_up_path(model_b, model_b.axes, model_b.count, b, seen_b, step_b);
    double ignored_a[kMaxAxes] = {};
    double ignored_b[kMaxAxes] = {};
    if (catch_up_a && catch_up_b) {
        Model::advance_pair(model_a, ball_a.now, seen_a, step_a, ignored_a, model_b, ball_b.now, seen_b, step_b,
                            ignored_b);
    } else if (catch_up_a) {
        model_a.advance(ball_a.now, seen_a, step_a, ignored_a);
    } else if (catch_up_b) {
        model_b.advance(ball_b.now, seen_b, step_b, ignored_b);
    }
    BallHandlePath expected_a;
    BallHandlePath expected_b;
    ball_expected_path(model_a.axes, model_a.count, a, fresh_a, expected_a);
    ball_expected_path(model_b.axes, model_b.count, b, fresh_b, expected_b);
    BallMotion ahead_a = ball_a.now;
    BallMotion ahead_b = ball_b.now;
    double impulse_a[kMaxAxes] = {};
    double impulse_b[kMaxAxes] = {};
    if (step_a > 0 && step_b > 0) {
        Model::advance_pair(model_a, ahead_a, expected_a, step_a, impulse_a, model_b, ahead_b, expected_b, step_b,
                            impulse_b);
    } else if (step_a > 0) {
        model_a.advance(ahead_a, expected_a, step_a, impulse_a);
    } else if (step_b > 0) {
        model_b.advance(ahead_b, expected_b, step_b, impulse_b);
    }
    if (step_a > 0) {
        ball_add_reaction(model_a.axes, model_a.count, impulse_a, step_a, force_a);
    } else {
        model_a.reaction(ball_a.now, a, force_a);
    }
    if (step_b > 0) {
        ball_add_reaction(model_b.axes, model_b.count, impulse_b, step_b, force_b);
    } else {
        model_b.reaction(ball_b.now, b, force_b);
    }
}

// The ball relative to the handle, per device axis, for the engine's reports.
inline void report_ball(const BallMotion& ball, const DynamicContext& c, const int* axes, int count,
                        DynamicResult& result) noexcept {
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        result.mass_position[a] = static_cast<float>(ball.position[a] - c.position[a]);
        result.mass_velocity[a] = static_cast<float>(ball.velocity[a] - c.velocity[a]);
    }
}

}  // namespace feel::detail
