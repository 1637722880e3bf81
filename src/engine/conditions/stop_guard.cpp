// The stop guard of friction; stop_guard.hpp has the reasoning.
#include "conditions/stop_guard.hpp"

#include <cmath>

namespace feel::detail {

namespace {

// Sets the bristle to hold against `others` (within ±1) and returns that force.
float hold_against(Bristle& bristle, float others, float pos_coefficient, float neg_coefficient) noexcept {
    return set_bristle_force(bristle, -others, pos_coefficient, neg_coefficient);
}

}  // namespace

StopGuardTick stop_guard_tick(const EngineConfig& config, double dt_s) noexcept {
    StopGuardTick t;
    if (!(config.device_mass > 0) || !(dt_s > 0)) return t;
    t.on = true;
    t.mass = config.device_mass;
    t.damping = config.device_damping;
    t.dt = static_cast<float>(dt_s);
    t.inverse_dt = 1.0f / t.dt;
    t.dt_per_mass = t.dt / t.mass;
    const float theta = std::exp(-t.dt / kStopGuardTime);
    const float one = 1.0f - theta;
    t.gain_position = 1.0f - theta * theta * theta;
    t.gain_velocity = 1.5f * one * one * (1.0f + theta);
    t.gain_external = t.mass * one * one * one * t.inverse_dt * t.inverse_dt;
    t.count = config.sensor_step;
    t.min_speed = t.gain_velocity * t.count * t.inverse_dt;
    t.fast_speed = 2.0f * t.count / kStopGuardTime;
    t.hold_off = static_cast<int32_t>(3.0f * kStopGuardTime * t.inverse_dt) + 1;
    t.settle = static_cast<int32_t>(kStopGuardTime * t.inverse_dt) + 1;
    return t;
}

bool observe(HandleObserver& o, const StopGuardTick& t, float position, float applied) noexcept {
    if (!std::isfinite(position) || !std::isfinite(applied)) return false;
    if (!o.primed) {
        o = HandleObserver{};
        o.position = position;
        o.primed = true;
        return false;
    }
    // Predict with the force the motors applied, then correct with the sensed position.
    const float acceleration = (applied + o.external - t.damping * o.velocity) / t.mass;
    const float predicted = o.position + o.velocity * t.dt + 0.5f * acceleration * t.dt * t.dt;
    const float e = position - predicted;
    o.position = predicted + t.gain_position * e;
    o.velocity += acceleration * t.dt + t.gain_velocity * e * t.inverse_dt;
    o.external += t.gain_external * e;
    if (!std::isfinite(o.position) || !std::isfinite(o.velocity) || !std::isfinite(o.external)) {
        o = HandleObserver{};  // start observing afresh rather than act on a non-finite state
        return false;
    }
    if (std::fabs(e) < t.count) {
        if (o.agreed < t.settle) ++o.agreed;
    } else {
        o.agreed = 0;
    }
    return true;
}

void observe_axes(AxisObservers& observers, const EngineConfig& config, double dt_s, int64_t t_us,
                  int64_t previous_t_us, const float* position, const float* velocity, const float* applied,
                  int axes) noexcept {
    if (observers.tick_dt_s != dt_s) {
        observers.tick = stop_guard_tick(config, dt_s);
        observers.inverse_fade_speed = 1.0f / (static_cast<float>(kBristleDampingFade) * config.velocity_ref);
        observers.tick_dt_s = dt_s;
    }
    for (int a = 0; a < kMaxAxes; ++a) {
        observers.fade[a] = a < axes ? bristle_damping_fade(velocity[a], observers.inverse_fade_speed) : 0.0f;
    }
    const bool continuing = observers.last_t_us == previous_t_us && previous_t_us != t_us;
    observers.last_t_us = t_us;
    for (int a = 0; a < kMaxAxes; ++a) {
        if (!continuing) observers.axis[a] = HandleObserver{};
        observers.observed[a] = observers.tick.on && a < axes && observe(observers.axis[a], observers.tick, position[a], applied[a]);
    }
}

float guard_stop(StopGuard& g, const HandleObserver& o, bool observed, Bristle& bristle, const StopGuardTick& t,
                 float position, float others, float force, float f, float pos_coefficient,
                 float neg_coefficient) noexcept {
    if (!t.on || !observed || !std::isfinite(others)) return force;
    if (g.hold_off > 0) --g.hold_off;
    if (g.stopping) {
        g.stopping = false;
        g.sliding = false;
        if (std::fabs(position - g.stop_at) < t.count) {
            // At rest: the bristle, anchored here, holds against the other effects (nothing
            // for a free handle).
            return hold_against(bristle, others, pos_coefficient, neg_coefficient);
        }
        if ((position - g.stop_at) * g.direction < 0) {
            // It went back: the stop overshot (the observer's velocity within its noise of a
            // slow handle). Friction may not push it on: anchor here, holding the others.
            g.direction = -g.direction;
            return hold_against(bristle, others, pos_coefficient, neg_coefficient);
        }
        g.hold_off = t.hold_off;  // it went on: a push the observer has not learned yet
    }
    const float v = o.velocity;
    if (std::fabs(v) >= t.min_speed) {
        g.sliding = true;
        g.direction = v > 0 ? 1.0f : -1.0f;
    }
    // A free stop is quick: the handle slid faster than fast_speed (2 counts over τ, where
    // the observer's prediction can be refuted by the sensor) no longer ago than the
    // friction's force alone could have stopped it. A hand dragging the handle slower than
    // that, whose travel the sensor cannot tell from the observer's prediction of a stop,
    // is left to the bristle.
    g.decelerated = std::fabs(v) >= t.fast_speed ? 0.0f : g.decelerated + std::fabs(force) * t.dt_per_mass;
    if (!(g.decelerated <= 2.0f * t.fast_speed)) return force;
    // Free means nothing pushes the handle along its motion (a hand pushing lightly, below
    // f/4, is not free: d is its push, along the motion) and nothing holds it beyond f/4
    // against it (the mechanism's dry friction is below that).
    if (!g.sliding || g.hold_off > 0 || o.agreed < t.settle || std::fabs(o.external) > kStopGuardFreeFraction * f ||
        o.external * g.direction > kStopGuardAlongFraction * f || pos_coefficient < 0 || neg_coefficient < 0) {
        return force;
    }
    if (force * g.direction > 0 && (force + others) * g.direction > kStopGuardFreeFraction * f) {
        // The bristle pushes the free handle along its motion: it gives back what a push
        // stored in it. Friction only resists: the anchor follows the handle, and the bristle
        // holds no more than what the other effects push with.
        return hold_against(bristle, others, pos_coefficient, neg_coefficient);
    }
    if (!(force * g.direction < 0)) return force;
    const float v_next = v + (force + others + o.external - t.damping * v) * t.dt_per_mass;
    if (v_next * g.direction > 0) return force;  // still sliding at the tick's end
    // It comes to rest within the tick (or already has): apply what stops it there.
    float stop = -t.mass * v * t.inverse_dt - others - o.external + t.damping * v;
    stop = stop > f ? f : (stop < -f ? -f : stop);
    // Friction only resists: where the force on the handle besides the engine's (the
    // mechanism's dry friction) stops it by itself, it gets no push along its motion.
    if (stop * g.direction > 0) stop = 0.0f;
    g.stopping = true;
    g.stop_at = position + 0.5f * v * t.dt;
    return stop;
}

}  // namespace feel::detail
