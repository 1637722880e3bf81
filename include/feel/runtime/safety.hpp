// feel::runtime — the local safety features of the primer's devices (§2.2).
//
// "If a user is not holding the device properly, the hardware will not produce forces.
// This prevents the device from moving around when not being attended." And: forces are
// "faded-in rather than abruptly returned when the safety feature is engaged", so that
// the handle does not "jump out of the user's hand before he or she firmly grasped it".
//
// The SafetyMonitor is the last stage before the motors. Each tick it takes the engine's
// forces and scales them, in place, by one factor, the output scale:
//
//   * Dead-man switch. While the switch says the handle is not held, the scale is 0.
//   * Safety fade-in. From the tick the handle is held again the scale rises linearly from
//     0 to 1 over fade_in_us. The same ramp follows power-on, re-enabling the actuators and
//     the end of a hands-off episode.
//   * Hands-off protection. A device without a switch (wheels, desktop 3-axis devices), or
//     with one that lies, cannot say that nobody holds the handle. The monitor then tells
//     from the motion: a free handle moves exactly as the motor force alone accelerates the
//     bare handle; a hand adds mass, a spring and a damper, and the motion stops matching.
//     When it matches for long enough under a strong force, or the handle runs away faster
//     than a hand would move it with the force pushing it on, the monitor latches
//     "hands off" and fades the forces out over fade_out_us. It re-arms when a hand is
//     seen: motion the force cannot explain, or a new grab on the switch. src/runtime/
//     safety.cpp explains the detector; docs/runtime.md ("Safety") gives its thresholds per
//     profile.
//   * Host-link watchdog. When the host has been silent for longer than host_timeout_us,
//     or the device released it (release_host(): it disconnected), the host is lost: the
//     forces fade from where they are to 0 over host_fade_out_us, and on the tick they
//     reach 0 state().host_lost_event is set: the runtime must then stop all effects
//     (Engine::stop_all). Forces pass again as soon as the host is heard; a host heard
//     within the fade finds its effects still playing, one heard later finds them stopped
//     and starts what it wants.
//   * Host control: the host may disable the actuators (scale 0) and enable them again
//     (a fade-in). Engine::set_actuators_enabled cuts and restores at once; the runtime
//     passes the host's command to both, so that forces come back faded in.
//
// Every force also leaves clamped to ±10000 (the motor limit) and a non-finite one as 0.
//
// Per tick, after the engine:
//
//   float force[kMaxAxes] = out.force ...;
//   const SafetyState& s = safety.process(safety_input(in, out, applied, host_heard_us), force);
//   if (s.host_lost_event) engine.stop_all();
//   backend.write(force);  applied = force;   // s.output_scale is the factor IDF scales by
//
// Time is an argument: the monitor reads no clock. Real-time safety: process(),
// set_actuators_enabled(), reset() and state() never allocate, lock or throw;
// configure() does not either, but belongs to initialization.
#pragma once

#include <cstdint>

#include "feel/axis.hpp"
#include "feel/engine.hpp"
#include "feel/status.hpp"
#include "feel/units.hpp"

namespace feel::sim {
struct DeviceProfile;
}

namespace feel::runtime {

// How the bare handle of one axis moves when nothing but its motor and its own friction
// act on it, in normalized units (docs/conventions.md):
//   a = accel_per_force·F − damping_rate·v − friction_accel·sign(v)
struct FreeHandleModel {
    // > 0, finite: position units/s² per force unit; max_force / (mass · half_travel) of
    // the axis (4.45 N / (0.15 kg · 0.05 m) = 593 on the joystick).
    float accel_per_force = 593.3f;
    // >= 0, finite, 1/s: viscous damping / mass.
    float damping_rate = 3.33f;
    // >= 0, finite, position units/s²: Coulomb friction / mass, in position units.
    float friction_accel = 2.0e5f;
};

// The hands-off detector (safety.cpp explains it). The defaults are the joystick's,
// rounded; safety_config_for(profile) derives every profile's (docs/runtime.md, "Safety").
struct HandsOffConfig {
    bool enabled = true;           // false: no detector (the dead-man switch alone)
    FreeHandleModel axes[kMaxAxes] = {};  // per axis, the first axis_count are used
    // The evidence window: the speed the handle gained over the last window_us, measured
    // and as the bare handle would have gained it, µs, 1000..100000.
    int64_t window_us = 10'000;
    // The detector judges an axis only when the force over the window would accelerate the
    // bare handle at least as hard as this force does (force units, 1..10000): weaker
    // forces cannot make a free handle dangerous.
    float min_force = 2500;
    // A match: |measured − predicted| <= max_mismatch · |predicted| (0 < max_mismatch < 1).
    float max_mismatch = 0.15f;
    // Only a push that lasts can throw a free handle across its travel: the prediction
    // must have kept its sign for sustain_us (µs, 0..1000000). Vibrations faster than
    // about 1/(2·sustain_us) never pass, however hard they shake.
    int64_t sustain_us = 58'000;
    // A match must last this long before hands-off latches, µs, 0..1000000.
    int64_t confirm_us = 5'000;
    // Runaway: a speed beyond this, position units/s (> 0, finite), while a sustained push
    // of at least min_force drives the handle on in the direction it moves and it keeps
    // gaining speed, latches at once.
    float runaway_speed = 3e5f;
    // Below this speed the handle counts as at rest for dry friction, position units/s
    // (>= 0, finite).
    float rest_speed = 1000;
    // Re-arm: motion the motor cannot explain is a hand: an unexplained acceleration of
    // at least hand_accel (position units/s², > 0, finite), and more than twice the match
    // tolerance, lasting hand_confirm_us (µs, 0..1000000).
    float hand_accel = 2e5f;
    int64_t hand_confirm_us = 20'000;
    // At |position| >= stop_zone (position units, 1..10000) the handle is at an end stop,
    // whose impact the model does not know: the detector forgets its evidence there and
    // for stop_holdoff_us (µs, 0..1000000) after leaving it.
    float stop_zone = 9800;
    int64_t stop_holdoff_us = 30'000;
    // Once latched, the forces fade from where they are to 0 over this time, µs,
    // 0..kMaxTimeUs (0: cut at once).
    int64_t fade_out_us = 10'000;
};

struct SafetyConfig {
    int32_t axis_count = 2;                // 1..6, as the engine's
    // The safety fade-in: forces ramp from 0 to full over this time after a grab, µs,
    // 0..kMaxTimeUs (0: at once).
    int64_t fade_in_us = 500'000;
    // The host-link watchdog, µs: 1..kMaxTimeUs, or kInfiniteUs for none.
    int64_t host_timeout_us = 1'000'000;
    // A lost host's forces fade from where they are to 0 over this time, µs, 0..kMaxTimeUs
    // (0: cut at once); its effects are stopped when the fade ends. 50 ms: gone well within
    // a hand's reaction time, yet no step a hand feels as a jolt.
    int64_t host_fade_out_us = 50'000;
    HandsOffConfig hands_off{};
};

// What the monitor needs each tick.
struct SafetyInput {
    int64_t t_us = 0;                     // time of this tick, µs, non-decreasing
    bool handle_held = true;              // the dead-man switch (TickInput::handle_held)
    float position[kMaxAxes] = {};        // sensed, normalized ±10000
    float velocity[kMaxAxes] = {};        // estimated, position units/s (TickOutput::velocity)
    // The force written to the motors at the previous tick, normalized: what acted on the
    // handle between that tick and this one (the previous process() output).
    float applied_force[kMaxAxes] = {};
    // When the host was last heard from, µs on the same clock as t_us. Before the first
    // command, the time the runtime started: the host gets host_timeout_us to connect.
    int64_t host_heard_us = 0;
};

struct SafetyState {
    bool actuators_enabled = true;  // the host's enable/disable (set_actuators_enabled)
    bool handle_held = false;       // the dead-man switch at the last tick
    // The safety fade: 0 (no force) .. 1 (full force). Follows the fade-in and fade-out
    // ramps; 0 while the handle is not held or the actuators are disabled.
    float fade_level = 0;
    // What multiplied the forces at the last tick: fade_level times the host-loss fade
    // (1 while the host is present, falling to 0 over host_fade_out_us once lost).
    float output_scale = 0;
    bool hands_off = false;         // latched: a free handle was detected; forces fade out
    uint32_t hands_off_axes = 0;    // bit i: axis i showed the free-handle evidence
    bool host_lost = false;         // the host is silent past host_timeout_us, or released
    // True for the one tick a lost host's fade reaches 0: stop all effects now.
    bool host_lost_event = false;
    bool host_faded = false;        // the host is lost and its fade has ended
    int64_t t_us = 0;               // the last tick's time, µs
    // Counters since configure() or reset().
    uint32_t hands_off_trips = 0;   // times hands-off latched
    uint32_t hand_rearms = 0;       // times a hand was seen and the latch released
    uint32_t host_losses = 0;       // times the watchdog tripped
    uint32_t nonfinite_forces = 0;  // non-finite forces replaced by 0
};

// Checks a configuration; the error names the first bad field and its allowed range.
[[nodiscard]] Error check_safety_config(const SafetyConfig& config) noexcept;

// The safety configuration of a simulated device: its axes and the free-handle model of
// each (from mass, friction, travel and motor limit), a runaway speed of 3 times the
// profile's velocity_ref, a rest speed of 1% of it, and a hand acceleration of
// 2·velocity_ref per second (a tenth of a brisk hand's speed gained in 50 ms); the rest
// are the defaults.
[[nodiscard]] SafetyConfig safety_config_for(const sim::DeviceProfile& profile) noexcept;

// Builds the monitor's input from the tick's engine input and output.
[[nodiscard]] SafetyInput safety_input(const TickInput& in, const TickOutput& out,
                                       const float applied_force[kMaxAxes],
                                       int64_t host_heard_us) noexcept;

class SafetyMonitor {
public:
    // Configured with the defaults; call configure() before use.
    SafetyMonitor() noexcept;
    // Validates and takes a configuration, and resets (power-on: fade level 0, no latch,
    // actuators enabled). A bad configuration changes nothing and is returned.
    [[nodiscard]] Error configure(const SafetyConfig& config) noexcept;

    // Scales force[0..kMaxAxes) in place for this tick (axes beyond axis_count leave 0)
    // and returns the new state. Real-time safe. A t_us earlier than the last one restarts
    // the detector's evidence (a clock reset), keeping the fade where it is.
    const SafetyState& process(const SafetyInput& in, float force[kMaxAxes]) noexcept;

    // The host's device control: disabled actuators produce no force; enabling them fades
    // the forces in. Takes effect at the next process().
    void set_actuators_enabled(bool enabled) noexcept;
    // The host is gone (it disconnected): lost from the next process() on, as if the
    // watchdog had tripped, until it is heard after t_us (the time of the tick that
    // releases it). Real-time safe.
    void release_host(int64_t t_us) noexcept;
    // Back to power-on: fade level 0, no latch, the watchdog and the counters cleared.
    // Keeps the actuators' enable.
    void reset() noexcept;

    [[nodiscard]] const SafetyState& state() const noexcept { return state_; }
    [[nodiscard]] const SafetyConfig& config() const noexcept { return config_; }

private:
    enum class Phase : uint8_t { off, rising, falling };
    // Per axis evidence of the hands-off detector: a short history of the measured speed
    // and of the bare handle's predicted speed gain, thinned so that kHistory samples
    // always span the window whatever the loop rate.
    static constexpr int kHistory = 64;
    struct Sample {
        int64_t t_us = 0;
        double velocity = 0;   // measured, units/s
        double predicted = 0;  // the bare handle's speed gain since the history began, units/s
    };
    struct AxisEvidence {
        Sample history[kHistory] = {};
        int count = 0;               // samples held, 0..kHistory
        int newest = 0;              // index of the newest
        double predicted = 0;        // running sum of the bare handle's speed gain, units/s
        double last_velocity = 0;    // units/s, the previous tick's
        int8_t push_sign = 0;        // sign of the predicted gain over the window: -1, 0, +1
        int64_t push_since = -1;     // µs: since when it has kept that sign
        int64_t match_since = -1;    // µs, start of the current match, -1: none
        int64_t hand_since = -1;     // µs, start of the current unexplained motion, -1: none
        int64_t holdoff_until = -1;  // µs: evidence ignored until then (end stop)

        // Forgets the history and the timers, keeping the end-stop holdoff.
        void clear() noexcept {
            count = 0;
            newest = 0;
            predicted = 0;
            last_velocity = 0;
            push_sign = 0;
            push_since = -1;
            match_since = -1;
            hand_since = -1;
        }
    };

    void update_watchdog(const SafetyInput& in) noexcept;
    // The host-loss fade: 1 while the host is present, a ramp to 0 from host_anchor_us_.
    double host_level_ = 1;
    double host_anchor_level_ = 1;
    int64_t host_anchor_us_ = 0;
    bool released_ = false;
    int64_t released_at_us_ = 0;
    void update_detector(const SafetyInput& in, double dt_s) noexcept;
    void update_fade(const SafetyInput& in) noexcept;
    void forget_evidence() noexcept;
    static void restart(AxisEvidence& e, int64_t t_us, double velocity) noexcept;
    [[nodiscard]] double free_acceleration(int axis, double force, double v) const noexcept;

    SafetyConfig config_{};
    SafetyState state_{};
    AxisEvidence evidence_[kMaxAxes] = {};
    bool have_last_tick_ = false;
    bool was_held_ = false;
    Phase phase_ = Phase::off;
    int64_t quiet_since_us_ = -1;  // since when the output has been 0 while latched, -1: not
    int64_t anchor_us_ = 0;     // when the current ramp started
    double anchor_level_ = 0;   // the level it started from
};

}  // namespace feel::runtime
