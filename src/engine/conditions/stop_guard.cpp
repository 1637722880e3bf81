// The stop guard of friction; stop_guard.hpp has the reasoning. Single precision (issue 14).
#include "conditions/stop_guard.hpp"

#include <cmath>

#include "float_exp.hpp"

namespace feel::detail {

StopGuardTick stop_guard_tick(const EngineConfig& config, float dt_s) noexcept {
    StopGuardTick t;
    if (!(config.device_mass > 0) || !(dt_s > 0)) return t;
    t.on = true;
    t.mass = config.device_mass;
    t.damping = config.device_damping;
    t.dt = dt_s;
    t.inverse_dt = 1.0f / t.dt;
    t.dt_per_mass = t.dt / t.mass;
    const float theta = float_exp(-t.dt / kStopGuardTime);
    const float one = 1.0f - theta;
    t.gain_position = 1.0f - theta * theta * theta;
    t.gain_velocity = 1.5f * one * one * (1.0f + theta);
    t.gain_external = t.mass * one * one * one * t.inverse_dt * t.inverse_dt;
    t.count = config.sensor_step;
    t.min_speed = t.gain_velocity * t.count * t.inverse_dt;
    t.quick_stop = 2.0f * fast_speed(t);
    // (A tick is at least 1 µs, so both fit in 16 bits: at most 3τ/T + 1 = 9001.)
    t.hold_off = static_cast<int16_t>(static_cast<int32_t>(3.0f * kStopGuardTime * t.inverse_dt) + 1);
    t.settle = static_cast<int16_t>(static_cast<int32_t>(kStopGuardTime * t.inverse_dt) + 1);
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

void observe_axes(AxisObservers& observers, const EngineConfig& config, float dt_s, int64_t t_us,
                  int64_t previous_t_us, const float* position, const float* velocity, const float* applied,
                  int axes) noexcept {
    if (observers.tick_dt_s != dt_s) {
        observers.tick = stop_guard_tick(config, dt_s);
        observers.inverse_fade_speed = 1.0f / (kBristleDampingFade * config.velocity_ref);
        observers.tick_dt_s = dt_s;
    }
    // Only the device's axes: a friction acts on no other (the rest stay as constructed).
    const int count = axes < kMaxAxes ? axes : kMaxAxes;
    for (int a = 0; a < count; ++a) {
        // A handle at rest (v = 0 exactly, the estimator's answer to a still sensor) has no
        // bristle rate to damp: no exponential.
        const float fade =
            velocity[a] != 0 ? bristle_damping_fade(velocity[a], observers.inverse_fade_speed) : 0.0f;
        observers.fade[a] = fade;
        observers.damped_velocity[a] = fade != 0 ? velocity[a] : 0.0f;
        observers.damped_way[a] = observers.damped_velocity[a] > 0 ? 1.0f : -1.0f;
    }
    const bool continuing = observers.last_t_us == previous_t_us && previous_t_us != t_us;
    observers.last_t_us = t_us;
    const StopGuardTick& tick = observers.tick;
    for (int a = 0; a < count; ++a) {
        if (!continuing) observers.axis[a] = HandleObserver{};
        // Without the guard (no device mass) no friction reads the views: they are not
        // worked out (issue 14, thirteenth pass). The tick that turns it on writes them.
        if (!tick.on) continue;
        const bool observed = observe(observers.axis[a], tick, position[a], applied[a]);
        observers.view[a] = view_of(observers.axis[a], observed, tick);
    }
}


}  // namespace feel::detail
