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
template <typename Model>
void ball_tick(const Model& model, const int* axes, int count, const DynamicContext& c, double force[kMaxAxes]) noexcept {
    BallState& ball = c.state->ball;
    const bool fresh = !c.state->initialized || !(c.dt_s > 0);  // no line through two positions yet
    const double step = std::min(c.dt_s, kBallMaxAdvanceS);     // how far the ball advances
    if (!c.state->initialized) {
        c.state->ball = BallState{};  // the union member (DynamicState) begins here
        model.start(ball.now, c);
        c.state->initialized = true;
    } else if (c.dt_s > 0) {
        BallHandlePath seen;
        for (int i = 0; i < count; ++i) {
            const int a = axes[i];
            seen.from[a] = ball.handle[a];
            seen.velocity[a] = (c.position[a] - ball.handle[a]) / step;
            seen.damper_velocity[a] = ball.handle_velocity[a];
        }
        double ignored[kMaxAxes] = {};
        model.advance(ball.now, seen, step, ignored);
    }

    BallHandlePath expected;
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        expected.from[a] = c.position[a];
        expected.velocity[a] = fresh ? c.velocity[a] : (c.position[a] - ball.handle[a]) / c.dt_s;
        expected.damper_velocity[a] = c.velocity[a];
        ball.handle[a] = c.position[a];
        ball.handle_velocity[a] = c.velocity[a];
    }
    if (step > 0) {
        BallMotion ahead = ball.now;
        double impulse[kMaxAxes] = {};
        model.advance(ahead, expected, step, impulse);
        for (int i = 0; i < count; ++i) {
            const int a = axes[i];
            const double pull = -impulse[a] / step;
            force[a] += std::isfinite(pull) ? pull : 0.0;
        }
    } else {
        model.reaction(ball.now, c, force);
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
