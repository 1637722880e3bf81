// The stop guard of friction (§3.5: friction "always resists the direction of motion"): it
// lets a free handle that friction slows down come to rest and stay there, instead of being
// thrown back by the force that stopped it.
//
// The problem. A Dahl bristle (friction_model.hpp) is a spring. A free handle coasting
// against friction stops with the bristle fully deflected, the force still f, and nothing
// else on it: that stored force throws it back the way it came (the joystick, f = 8000,
// 1 kHz: 971 units back after 1720 forward), and it rings. Real Coulomb friction lets go
// the instant the handle stops. The engine sees the handle only once a tick and through a
// sensor of a few µm per count, so it has to know, one tick ahead, that the force it is
// about to apply would reverse the handle, and apply instead only what brings it to rest.
//
// Why an observer with the device's mass. Two things were ruled out by measurement
// (docs/conditions.md, "Friction", "Limits"). The velocity estimate (FOAW) lags a stop by
// ~1.5 ms, and on the joystick at 1 kHz the force must be gone within 2 ticks of a free
// stop. And no rule on the positions alone tells a free stop from a firm hand reversing:
// a firm hand stops the wheel 2.5 to 9 times faster than friction stops it free, while a
// firm reversal must change the force by at most 5-10% of 2f a tick. What tells them apart
// is the force on the handle: free, the only forces are the engine's own (which it knows)
// and the mechanism's small dry friction; held, the hand pushes. With the mechanism's mass
// m (EngineConfig::device_mass) the engine can watch for that force:
//
//   predict  x' = x + v·T + (F + d − b·v)·T²/(2m),   v' = v + (F + d − b·v)·T/m
//   correct  e = sensed − x',  x = x' + g·e,  v = v' + h·e/T,  d = d + m·k·e/T²
//
// F the force the motors applied last tick (the engine's total), b the mechanism's damping,
// d the force on the handle the engine did not command (hand, dry friction). g, h, k are the
// gains of a critically damped α-β-γ tracker with its three poles at θ = e^(−T/τ), τ = 3 ms:
// g = 1 − θ³, h = 1.5(1 − θ)²(1 + θ), k = (1 − θ)³. With the known force as its input the
// observer has no lag for a free handle (its prediction is exact but for the mechanism's
// dry friction, which d learns), so its velocity is good to a fraction of a count a tick
// at the very tick the handle comes to rest.
//
// The rule. While the handle slides (|v| above the observer's noise, h·count/T), the
// observer has predicted the sensed position within a count for the last τ (its model
// holds: no sudden push, no hand yanking the handle), the force on it besides the engine's
// is small (|d| <= f/4: nobody holds it) and does not push it along its motion (d·sign(v)
// <= f/16: a hand pushing lightly is not free; the guard would let go of its push at every
// stop and the handle would ratchet after the hand), and the handle slid faster than 2
// counts per τ no longer ago than the friction's force could have stopped it (a free stop
// is quick; a hand dragging the handle under a count a tick is not one, but its slow travel
// agrees with the observer's prediction of a stop within a count), if the friction
// force about to be applied would bring the velocity to zero or past it within the tick,
// the guard applies instead exactly what brings it to rest at the tick's end:
//
//   F_stop = −m·v/T − F_others − d + b·v          (capped at the friction's magnitude,
//                                                  and 0 if it would push along the motion)
//
// F_others the other effects' force of this tick (friction renders after them). The next
// tick, if the handle did come to rest (within a count of where the guard expected), the
// bristle is set to hold what the other effects push with (nothing for a free handle): its anchor is where the handle
// stopped, and it holds it there with the bristle's own stiction. If it went on, something
// the observer had not learned yet pushes it: the guard stands aside for 3τ.
//
// What it does not touch: a handle held by a hand (d is the hand's push, larger than f/4),
// a handle at rest or turning slowly (it never slid faster than the observer's noise), and
// a friction pushing along the motion (negative coefficients) or with an offset or a
// deadband (those move the surface or free a band of speed: they are not a stop). There
// the bristle renders friction exactly as before. Real-time: a few float operations per
// block, no allocation; deterministic. With device_mass 0 (unknown) it is off. The observer
// of a device axis is the engine's, shared by every friction on it (AxisObservers).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "conditions/friction_model.hpp"
#include "feel/engine.hpp"

namespace feel::detail {

// The observer's time constant, s.
inline constexpr float kStopGuardTime = 0.003f;
// The guard acts only while the force on the handle besides the engine's is at most this
// fraction of the friction's magnitude.
inline constexpr float kStopGuardFreeFraction = 0.25f;
// ... and pushes it along its motion by at most this fraction (a hand pushing lightly is not
// free: the guard would release its push at every stop, and the handle ratchets).
inline constexpr float kStopGuardAlongFraction = 0.0625f;

// The observer of the handle along one line: a device axis (the engine keeps one per axis,
// shared by every friction on it: AxisObservers) or the line of a texture or of a friction
// with a direction (each keeps its own in its StopGuard).
struct HandleObserver {
    float position = 0.0f;  // observed position, position units
    float velocity = 0.0f;  // observed velocity, units/s
    float external = 0.0f;  // d: the force on the handle the engine did not command, force units
    int16_t agreed = 0;     // ticks in a row the sensed position agreed with the prediction (<= settle)
    bool primed = false;
};

// Per block: the guard's memory (and its own observer where the line is not a device axis).
struct StopGuard {
    HandleObserver observer{};  // used only off the device's axes (guard_stop_on_line)
    float own = 0.0f;       // this friction's share of the engine's last force, force units
    float stop_at = 0.0f;   // where the handle was to come to rest
    float direction = 0.0f; // +1 or -1: the way it slides
    float decelerated = 0.0f; // what the friction's force alone could have taken off the velocity
                              // since the handle last slid faster than fast_speed(), units/s
    int16_t hold_off = 0;   // ticks the guard stands aside (it was wrong)
    bool sliding = false;   // it moved faster than the observer's noise since it last stopped
    bool stopping = false;  // the last force was the one that brings it to rest
};

// What every guard of a tick shares: the observer's gains for this tick period.
struct StopGuardTick {
    float mass = 0.0f, damping = 0.0f, dt = 0.0f, inverse_dt = 0.0f, dt_per_mass = 0.0f;
    float gain_position = 0.0f, gain_velocity = 0.0f, gain_external = 0.0f;
    float min_speed = 0.0f;  // the observer's velocity noise: h·count/T
    float count = 0.0f;
    float quick_stop = 0.0f; // 2·fast_speed(): how much a free stop may have slowed the handle since
    // (16-bit, issue 14's RAM: at most 3τ/T + 1 = 9001 at the shortest tick, 1 µs.)
    int16_t hold_off = 0;
    int16_t settle = 0;      // ticks of agreement before the guard trusts the observer (τ)
    bool on = false;         // device_mass known and a tick to observe over
};

[[nodiscard]] StopGuardTick stop_guard_tick(const EngineConfig& config, float dt_s) noexcept;

// 2 counts over the observer's time constant: the speed at which its prediction has bite.
// (Worked out where it is read, once per line and tick, rather than kept: issue 14's RAM.)
[[nodiscard]] inline float fast_speed(const StopGuardTick& t) noexcept { return 2.0f * t.count / kStopGuardTime; }

// Advances the observer by one tick: `position` sensed, `applied` the engine's force of the
// last tick along the line. Returns whether it has a state to judge by (false at its first
// tick and after a non-finite input or state, when it starts afresh).
[[nodiscard]] bool observe(HandleObserver& o, const StopGuardTick& t, float position, float applied) noexcept;

// What the guard reads of a line's observer at this tick: the tests on the observer alone,
// made once per line (for a device axis once for every friction on it, issue 14).
struct ObserverView {
    float velocity = 0.0f;
    float external = 0.0f;
    float abs_external = 0.0f;
    float direction = 0.0f;  // the way the observer moves: +1 (v > 0) or -1
    // What the guard tests, as bits of one byte (one load for every block, issue 14).
    static constexpr uint8_t kUsable = 1;   // the guard is on and observe() had a state to judge by
    static constexpr uint8_t kMoving = 2;   // |v| >= min_speed: faster than the observer's noise
    static constexpr uint8_t kFast = 4;     // |v| >= fast_speed
    static constexpr uint8_t kSettled = 8;  // it agreed with the sensor for τ
    uint8_t flags = 0;
};

[[nodiscard]] inline ObserverView view_of(const HandleObserver& o, bool observed, const StopGuardTick& t) noexcept {
    ObserverView view;
    view.velocity = o.velocity;
    view.external = o.external;
    view.abs_external = std::fabs(o.external);
    const float speed = std::fabs(o.velocity);
    view.direction = o.velocity > 0 ? 1.0f : -1.0f;
    view.flags = static_cast<uint8_t>((t.on && observed ? ObserverView::kUsable : 0) |
                                      (speed >= t.min_speed ? ObserverView::kMoving : 0) |
                                      (speed >= fast_speed(t) ? ObserverView::kFast : 0) |
                                      (o.agreed >= t.settle ? ObserverView::kSettled : 0));
    return view;
}

// The engine's observers, one per device axis, shared by every friction on the axis (issue
// 14: the observer is most of the guard's cost, and every friction on an axis sees the same
// handle and the same engine force). Advanced once a tick before the frictions render;
// observe_axes restarts them when the previous tick was not observed (no friction played).
struct AxisObservers {
    // Every member 0 but the two marked -1: one zero fill, where default member initialisers
    // had the engine's constructor write each field out by itself (issue 14's flash). Every
    // member is a number: zero bytes are 0.
    AxisObservers() noexcept {
        std::memset(static_cast<void*>(this), 0, sizeof *this);
        tick_dt_s = -1.0f;
        last_t_us = -1;
    }

    HandleObserver axis[kMaxAxes];
    ObserverView view[kMaxAxes];  // what the guards read of axis[] at this tick
    // The bristles' microdamping at the axis' estimated velocity v, shared by every friction
    // without a velocity offset (friction_model.hpp, bristle_damping): the fade
    // exp(-(v/v_d)²), 0 where there is nothing to damp (v = 0 or not finite) or beyond the
    // cutoff; v where the fade is not 0, else 0; and its way, +1 (> 0) or -1.
    float fade[kMaxAxes];
    float damped_velocity[kMaxAxes];
    float damped_way[kMaxAxes];
    float inverse_fade_speed;
    StopGuardTick tick;
    float tick_dt_s;    // the tick length tick and inverse_fade_speed are for (-1)
    int64_t last_t_us;  // the tick last observed (-1)
};
static_assert(std::is_trivially_copyable_v<AxisObservers>, "its constructor fills it with zero bytes");

// `t_us` this tick's time, `previous_t_us` the previous tick's (equal at the first tick),
// `velocity` the engine's estimate.
void observe_axes(AxisObservers& observers, const EngineConfig& config, float dt_s, int64_t t_us,
                  int64_t previous_t_us, const float* position, const float* velocity, const float* applied,
                  int axes) noexcept;

// Sets the bristle to hold against `others` (within ±1) and returns that force.
inline float hold_against(Bristle& bristle, float others, float pos_coefficient, float neg_coefficient) noexcept {
    return set_bristle_force(bristle, -others, pos_coefficient, neg_coefficient);
}

// What the guard compares with for a friction of magnitude f and these coefficients.
struct GuardLimits {
    float f = 0.0f;       // the most the stop may apply
    float free = 0.0f;    // kStopGuardFreeFraction·f: the most that may hold a free handle
    float along = 0.0f;   // kStopGuardAlongFraction·f: the most that may push it along its motion
    bool resists = false; // both coefficients >= 0 (a negative one pushes along the motion: no guard)
};

[[nodiscard]] inline GuardLimits guard_limits(float f, float pos_coefficient, float neg_coefficient) noexcept {
    return {f, kStopGuardFreeFraction * f, kStopGuardAlongFraction * f, pos_coefficient >= 0 && neg_coefficient >= 0};
}

// One block's friction along its line, with `o` what the guard reads of the line's observer
// after this tick's observe(): `position` sensed, `others` the other effects' force this tick
// (ConditionContext::others_force; without it, the last tick's: applied less this
// friction's share), `force` the friction about to be applied (after its saturation), `limits`
// those of its magnitude. Returns `force`, or the force that brings the handle to rest. May set the
// bristle's deflection (after a stop). Call remember_output with what was finally applied.
// Inline: it runs for every block of every friction, and most ticks it returns `force` after
// a few tests (issue 14: friction's cost per effect).
[[nodiscard, gnu::always_inline]] inline float guard_stop(StopGuard& g, const ObserverView& o, Bristle& bristle, const StopGuardTick& t,
                                      float position, float others, float force, const GuardLimits& limits,
                                      float pos_coefficient, float neg_coefficient) noexcept {
    const unsigned flags = o.flags;  // (read once, into a register)
    if (!(flags & ObserverView::kUsable) || !std::isfinite(others)) return force;
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
    if (flags & ObserverView::kMoving) {
        g.sliding = true;
        g.direction = o.direction;
    }
    // A free stop is quick: the handle slid faster than fast_speed (2 counts over τ, where
    // the observer's prediction can be refuted by the sensor) no longer ago than the
    // friction's force alone could have stopped it. A hand dragging the handle slower than
    // that, whose travel the sensor cannot tell from the observer's prediction of a stop,
    // is left to the bristle.
    // (Fast, it is 0, which the test below passes: quick_stop is positive, the sensor's step
    // being so. So the test runs only where it can fail.)
    if ((flags & ObserverView::kFast) != 0) {
        g.decelerated = 0.0f;
    } else {
        g.decelerated += std::fabs(force) * t.dt_per_mass;
        if (!(g.decelerated <= t.quick_stop)) return force;
    }
    // Free means nothing pushes the handle along its motion (a hand pushing lightly, below
    // f/4, is not free: d is its push, along the motion) and nothing holds it beyond f/4
    // against it (the mechanism's dry friction is below that).
    if (!(flags & ObserverView::kSettled) || o.abs_external > limits.free || !g.sliding || g.hold_off > 0 || !limits.resists ||
        o.external * g.direction > limits.along) {
        return force;
    }
    if (force * g.direction > 0 && (force + others) * g.direction > limits.free) {
        // The bristle pushes the free handle along its motion: it gives back what a push
        // stored in it. Friction only resists: the anchor follows the handle, and the bristle
        // holds no more than what the other effects push with.
        return hold_against(bristle, others, pos_coefficient, neg_coefficient);
    }
    if (!(force * g.direction < 0)) return force;
    const float v = o.velocity;
    const float v_next = v + (force + others + o.external - t.damping * v) * t.dt_per_mass;
    if (v_next * g.direction > 0) return force;  // still sliding at the tick's end
    // It comes to rest within the tick (or already has): apply what stops it there.
    float stop = -t.mass * v * t.inverse_dt - others - o.external + t.damping * v;
    const float f = limits.f;
    stop = stop > f ? f : (stop < -f ? -f : stop);
    // Friction only resists: where the force on the handle besides the engine's (the
    // mechanism's dry friction) stops it by itself, it gets no push along its motion.
    if (stop * g.direction > 0) stop = 0.0f;
    g.stopping = true;
    g.stop_at = position + 0.5f * v * t.dt;
    return stop;
}

// The same on a line that is not a device axis, with the block's own observer.
[[nodiscard]] inline float guard_stop_on_line(StopGuard& g, Bristle& bristle, const StopGuardTick& t,
                                              float position, float applied, float others, float force, float f,
                                              float pos_coefficient, float neg_coefficient) noexcept {
    const bool observed = t.on && observe(g.observer, t, position, applied);
    return guard_stop(g, view_of(g.observer, observed, t), bristle, t, position, others, force,
                      guard_limits(f, pos_coefficient, neg_coefficient), pos_coefficient, neg_coefficient);
}

// The friction's share of the engine's force this tick: its force times the effect's and
// the device's gain.
inline void remember_output(StopGuard& g, float force, float gain) noexcept { g.own = force * gain; }

}  // namespace feel::detail
