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
//
// Float throughout (issue 14), with the ball kept relative to the handle (ball_state.hpp):
// an advance starts from the ball's offset to the handle at the start of the line and
// ends with its offset to the line's end, which is the handle sensed now, so the ball is
// re-anchored on every sensed position and the handle's place on the travel costs it no
// resolution. Time stays the engine's: the tick's length arrives in seconds and is
// rounded to float once.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "dynamics/dynamic.hpp"
#include "feel/units.hpp"
#include "float_exp.hpp"

namespace feel::detail {

// 100 ms: a hundred ticks of the 1 kHz loop.
inline constexpr float kBallMaxAdvanceS = 0.1f;

// A Dynamic Struct integer whose 10000 means `reference` (dynamic_units.hpp's scales), in
// float: the ball models work out their constants every tick.
[[nodiscard]] inline float ball_scale(int32_t value, float reference) noexcept {
    return static_cast<float>(value) * reference / static_cast<float>(kFullScale);
}

// e^(−x) for x >= 0 (NaN gives NaN): float_exp.hpp's e^x at −x, the same code on x86 and
// the Cortex-M4F, so the same bits (within 1.1 ulps; tests/engine/dynamics/sling_test.cpp
// holds it to 2). 0 from x = 87, where e^(−x) nears float's smallest normal. It had its own
// series until issue 14's flash pass took its 164 bytes of Thumb code off the board.
[[nodiscard]] inline float ball_decay(float x) noexcept {
    return x < 87.0f ? float_exp(-x) : (x >= 87.0f ? 0.0f : x);
}

// The tick's length, s, as the balls compute with it.
[[nodiscard]] inline float ball_tick_s(const DynamicContext& c) noexcept { return c.dt_s; }

// The handle over a step, per device axis: moving at constant velocity from where it was
// at the step's start (the ball's offset is to that point).
struct BallHandlePath {
    float velocity[kMaxAxes] = {};         // position units/s, the path's
    float damper_velocity[kMaxAxes] = {};  // position units/s, what a damper to the handle reads
};

// One tick of a ball model. Model provides
//   void start(BallMotion&, const DynamicContext&): the ball on the effect's first tick;
//   void advance(BallMotion&, const BallHandlePath&, float h, float impulse[kMaxAxes]):
//       the ball after h seconds, exactly or to its integrator's accuracy, its offset now to
//       the path's end, and the impulse the string or paddle gave it (force units·s, per
//       device axis);
//   void reaction(const BallMotion&, const DynamicContext&, float force[kMaxAxes]): the
//       instantaneous force on the handle (the engine's first tick only).
// Adds the force on the handle to force[], on the device axes the model moves in (axes[0 ..
// count-1]): the handle's other axes never reach the model, so the tick reads and divides
// only these (a division each, and the other axes' force is 0 either way).
// A tick in three parts, so that ball_tick_pair can run two balls' advances side by side.
// The first: the ball on its first tick, or the handle's sensed path to catch up along
// (returns true when there is one, with the advance's length in *step).
template <typename Model>
bool ball_catch_up_path(const Model& model, const int* axes, int count, const DynamicContext& c,
                        BallHandlePath& seen, float& step) noexcept {
    BallState& ball = c.state->ball;
    const float dt = ball_tick_s(c);
    step = std::min(dt, kBallMaxAdvanceS);  // how far the ball advances
    if (!c.state->initialized) {
        c.state->ball = BallState{};  // the union member (DynamicState) begins here
        c.state->prepared = false;    // with a sling's form (BallState::sling) zeroed
        model.start(ball.now, c);
        c.state->initialized = true;
        return false;
    }
    if (!(dt > 0)) {
        // No time passed: the ball stays where it is while the handle may have jumped, so its
        // offset moves to the handle sensed now (ball_expected_path takes that as the handle).
        for (int i = 0; i < count; ++i) ball.now.offset[axes[i]] += ball.handle[axes[i]] - c.position[axes[i]];
        return false;
    }
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
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
    const float dt = ball_tick_s(c);
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        expected.velocity[a] = fresh ? c.velocity[a] : (c.position[a] - ball.handle[a]) / dt;
        expected.damper_velocity[a] = c.velocity[a];
        ball.handle[a] = c.position[a];
        ball.handle_velocity[a] = c.velocity[a];
    }
}

// The third: the predicted impulse's mean force over the tick, the handle's reaction.
inline void ball_add_reaction(const int* axes, int count, const float impulse[kMaxAxes], float step,
                              float force[kMaxAxes]) noexcept {
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        const float pull = -impulse[a] / step;
        force[a] += std::isfinite(pull) ? pull : 0.0f;
    }
}

// The impulse of an advance from `now`, which stays as it is: Model::predict where the
// model has it (the sling: it reads the ball where it lies), else an advance of a copy.
template <typename Model>
void ball_predict(const Model& model, const BallMotion& now, const BallHandlePath& expected, float step,
                  float impulse[kMaxAxes]) noexcept {
    if constexpr (requires { model.predict(now, expected, step, impulse); }) {
        model.predict(now, expected, step, impulse);
    } else {
        BallMotion ahead = now;
        model.advance(ahead, expected, step, impulse);
    }
}

template <typename Model>
void ball_tick(const Model& model, const int* axes, int count, const DynamicContext& c, float force[kMaxAxes]) noexcept {
    BallState& ball = c.state->ball;
    const bool fresh = !c.state->initialized || !(ball_tick_s(c) > 0);  // no line through two positions yet
    BallHandlePath seen;
    float step = 0;
    if (ball_catch_up_path(model, axes, count, c, seen, step)) {
        float ignored[kMaxAxes] = {};
        model.advance(ball.now, seen, step, ignored);
    }
    BallHandlePath expected;
    ball_expected_path(axes, count, c, fresh, expected);
    if (step > 0) {
        float impulse[kMaxAxes] = {};
        ball_predict(model, ball.now, expected, step, impulse);
        ball_add_reaction(axes, count, impulse, step, force);
    } else {
        model.reaction(ball.now, c, force);
    }
}

// Two balls' ticks, each exactly as ball_tick's, with their advances run side by side by
// Model::advance_pair(model_a, from, to, path, h, impulse, model_b, ...) (sling_dynamic.cpp
// says why). The balls' states are separate, so the parts' order between them is free.
template <typename Model>
void ball_tick_pair(const Model& model_a, const DynamicContext& a, float force_a[kMaxAxes], const Model& model_b,
                    const DynamicContext& b, float force_b[kMaxAxes]) noexcept {
    BallState& ball_a = a.state->ball;
    BallState& ball_b = b.state->ball;
    const bool fresh_a = !a.state->initialized || !(ball_tick_s(a) > 0);
    const bool fresh_b = !b.state->initialized || !(ball_tick_s(b) > 0);
    BallHandlePath seen_a;
    BallHandlePath seen_b;
    float step_a = 0;
    float step_b = 0;
    const bool catch_up_a = ball_catch_up_path(model_a, model_a.axes, model_a.count, a, seen_a, step_a);
    const bool catch_up_b = ball_catch_up_path(model_b, model_b.axes, model_b.count, b, seen_b, step_b);
    float ignored_a[kMaxAxes] = {};
    float ignored_b[kMaxAxes] = {};
    if (catch_up_a && catch_up_b) {
        Model::advance_pair(model_a, ball_a.now, &ball_a.now, seen_a, step_a, ignored_a, model_b, ball_b.now,
                            &ball_b.now, seen_b, step_b, ignored_b);
    } else if (catch_up_a) {
        model_a.advance(ball_a.now, seen_a, step_a, ignored_a);
    } else if (catch_up_b) {
        model_b.advance(ball_b.now, seen_b, step_b, ignored_b);
    }
    BallHandlePath expected_a;
    BallHandlePath expected_b;
    ball_expected_path(model_a.axes, model_a.count, a, fresh_a, expected_a);
    ball_expected_path(model_b.axes, model_b.count, b, fresh_b, expected_b);
    float impulse_a[kMaxAxes] = {};
    float impulse_b[kMaxAxes] = {};
    if (step_a > 0 && step_b > 0) {
        Model::advance_pair(model_a, ball_a.now, nullptr, expected_a, step_a, impulse_a, model_b, ball_b.now, nullptr,
                            expected_b, step_b, impulse_b);
    } else if (step_a > 0) {
        ball_predict(model_a, ball_a.now, expected_a, step_a, impulse_a);
    } else if (step_b > 0) {
        ball_predict(model_b, ball_b.now, expected_b, step_b, impulse_b);
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

// The ball relative to the handle, per device axis, for the engine's reports: its offset
// is to the handle sensed now (ball_expected_path has moved the handle's state here).
inline void report_ball(const BallMotion& ball, const DynamicContext& c, const int* axes, int count,
                        DynamicResult& result) noexcept {
    for (int i = 0; i < count; ++i) {
        const int a = axes[i];
        result.mass_position[a] = ball.offset[a];
        result.mass_velocity[a] = ball.velocity[a] - c.velocity[a];
    }
}

}  // namespace feel::detail
