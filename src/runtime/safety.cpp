// The safety monitor: dead-man switch, safety fade-in, hands-off protection, watchdog.
//
// The fade. One level L in [0, 1] scales every axis, so a force keeps its direction while
// it fades. L follows piecewise-linear ramps, each anchored at the tick it began:
//   off      L = 0                                   not held, or actuators disabled
//   rising   L = min(1, L0 + (t − t0)/fade_in_us)    held and no hands-off latch
//   falling  L = max(0, L0 − (t − t0)/fade_out_us)   hands-off latched
// A ramp is computed from its anchor, not accumulated tick by tick, so it is exact at any
// loop rate and for uneven ticks: the tick at which the switch first reads "held" has
// L = 0, and L reaches 1 exactly fade_in_us later. Linear is what "faded-in" asks for and
// what a hand can anticipate; the ramp's slope, 1/fade_in_us of full force per µs, is the
// largest rate of change of the safety factor.
//
// Hands-off detection. Without a hand, the handle of an axis obeys
//     a = k·F − c·v − f_c·sign(v)        (FreeHandleModel: k = max_force/(m·half_travel),
//                                          c = b/m, f_c = F_c/m, normalized units)
// and with one it does not: the hand adds its mass (so the same force accelerates less),
// and its spring and damper hold the handle back. The speed the handle gains is then at
// most m/(m + m_hand) of what the bare handle would gain (less once the hand's spring
// takes the load): 0.75, 0.5 and 0.33 for the loose, firm and stiff grips of the joystick
// and the 3-axis device, 0.6, 0.33 and 0.23 for the wheel's.
//
// Evidence per axis, each tick, over a sliding window of window_us:
//     measured   = v(now) − v(now − W)                 the speed the handle gained
//     predicted  = Σ a_free·dt over the same ticks      what the bare handle would gain
// where a_free uses the force applied over each interval (the previous tick's output) and
// the speed at its start. A window of differences, not a filter: after a let-go the
// measured gain equals the prediction one window later, with no tail of the held past.
// A short history per axis (kHistory samples, thinned to span the window at any loop
// rate) holds what the window needs.
//
// Hands-off latches when, with the switch reading "held", on some axis:
//   * strong:    |predicted| >= k·min_force·W (a weak push cannot make a free handle
//                dangerous, and the ratio of two small noisy numbers means nothing);
//   * sustained: predicted has kept its sign for sustain_us. A free handle is dangerous
//                when a push lasts: it crosses the travel. A vibration only shakes it in
//                place (amplitude a/ω²), and the ambiguous cases, a loosely held handle
//                shaken above its grip's resonance (where the hand is little more than
//                added mass) or a hand that happens to move the handle as the motor alone
//                would, are mostly brief;
//   * with the push: at the window's start the handle was not moving against the push
//                (sign(predicted)·v >= −rest_speed);
//   * matched:   |measured − predicted| <= max_mismatch·|predicted|, the bare handle's
//                motion within 15%: a hand would take at least 25% (the loosest grip);
//   * for confirm_us without a break;
// or at once when the handle moves faster than runaway_speed while a sustained push of at
// least min_force drives it on and it gains speed as the bare handle would, within twice
// the match tolerance either way (1 ± 2·max_mismatch of the prediction): no hand lets a
// handle run that fast with the motor shoving it along, but a released wheel spinning back
// under its centring spring does. This catches a free handle whose model is off by more
// than the match allows.
//
// Both rules say what hands-off means physically: the handle moves the way the device's
// own force moves the bare handle, with the force, and at the acceleration force/mass
// gives. A hand that yanks the handle (the Studio's pointer with the stiff hand jumps the
// target by 12000 units; the handle runs at 3-5 times velocity_ref) breaks both:
//   * across a spring toward its centre the motion goes with the force, fast, but gains
//     5-10 times what the spring could give (the hand's spring pulls ~20 times harder than
//     the motor can): no runaway, the gain is bounded above as well as below. A free
//     handle gains what its motor gives it; a model error of 30% either way still passes;
//   * beyond the centre, or into a wall, the motion goes against the force: never judged;
//   * settling at the new target, the hand's spring swings the handle back and forth
//     (the stiff grip rings at 9 Hz); at each turn its acceleration sweeps through the
//     motor's for a few ms and matches the bare handle's over a window. The window then
//     starts with the handle moving against the push, which a free handle under a lasting
//     push does only if it was thrown and let go: it is judged once it has turned. The
//     cost: a handle let go while moving against the push is caught up to one window
//     after its turn instead of up to 0.85 window after the let-go; until the turn it
//     moves away from where the push throws it, and from the turn on it is caught as fast
//     as a handle let go at rest.
// tests/runtime/safety_closed_loop_test.cpp yanks the handle across springs and walls on
// every profile, every 30 to 400 ms: no trip, no fade.
//
// Time scales. safety_config_for() sets window, sustain, confirm, hand-confirm and
// fade-out times from the time the bare handle takes to cross half its travel under full
// force, sqrt(2/k): 58 ms on the joystick, 41 ms on the 3-axis device, 307 ms on the wheel.
// A slow handle can be watched longer before it is judged, which tells a hand from no hand
// better; a fast one must be judged quickly or it hits the stop first.
//
// Measured in closed loop with the simulated device (docs/runtime.md has the figures): a
// hand that lets go under a constant force of 3000..10000 is caught 12..36 ms later on the
// joystick and the 3-axis device and 75 ms later on the wheel, before the handle can reach
// its stop at speed. Firm and stiff grips never trip under constant forces, springs, or
// full-force sines and squares from 1 to 50 Hz, nor when a stiff hand yanks the handle
// across a spring or into and out of a wall; a loose grip on the 3-axis device can pass
// for free under a half-force vibration of 5..7 Hz, where the hand is barely holding. The
// cost of a false alarm is a fade-out and, as soon as the hand shows, a fade-in. A force
// that starts while the handle is already free is judged only once it has lasted
// sustain_us: by then a fast handle may have reached its stop.
//
// Re-arming. Once latched and faded out, and after one more window (while the force
// changes, the velocity estimate lags it by a few ms, and that lag would pass for a hand),
// the monitor looks for a hand: motion the bare-handle model cannot explain,
// |measured − predicted| >= hand_accel·W and more than twice the match tolerance, lasting
// hand_confirm_us. A hand that grabs the handle and moves it, or the spring of a hand that
// was holding all along (a false alarm), shows as such a mismatch; a free handle coasting
// to rest under its own friction does not. A grab on the dead-man switch re-arms at once.
// Either way the forces then fade in over fade_in_us, like any grab. A hand that grabs and
// holds the handle perfectly still, or moves it only gently, is not seen until it moves it
// deliberately (hand_accel is a tenth of a brisk hand's speed gained in 50 ms).
//
// End stops. An impact on a stop is an acceleration the model does not know (thousands of
// g for a few ms), and the velocity estimate needs a few ms to follow the rebound. Within
// stop_zone of the end of the travel, and for stop_holdoff_us after leaving it, an axis's
// evidence is cleared and nothing is judged on it.
//
// Watchdog. Lost when t − host_heard_us > host_timeout_us (exactly at the timeout the host
// still counts as present), or released until heard again. A loss fades the forces from
// where they are to 0 over host_fade_out_us, linearly like every fade here, anchored at the
// tick of the loss; the event (stop all) fires once per loss, on the tick the fade ends.
#include "feel/runtime/safety.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "feel/sim/device_profile.hpp"

namespace feel::runtime {
namespace {

constexpr Range kWindowUs{1'000, 100'000};
constexpr Range kShortTimeUs{0, 1'000'000};
constexpr Range kTimeoutUs{1, kMaxTimeUs};
constexpr double kFullScaleForce = kFullScale;
// The 3 and 1% of safety_config_for(): a brisk hand moves the handle at velocity_ref
// (docs/simulated-device.md); a hand's fastest flick is about twice that.
constexpr double kRunawayOverVelocityRef = 3.0;
constexpr double kRestOverVelocityRef = 0.01;
constexpr double kHandAccelOverVelocityRef = 2.0;  // 1/s
// The detector's times as fractions of the crossing time (safety_config_for()): on the
// joystick a 10 ms window, 58 ms of sustained push, 5 ms of confirmation, 19 ms to see a
// hand, a 10 ms fade-out.
constexpr double kWindowsPerCrossing = 6;
constexpr double kConfirmsPerCrossing = 12;
constexpr double kHandConfirmsPerCrossing = 3;

bool finite_at_least(float v, float lo, bool strict) noexcept {
    return std::isfinite(v) && (strict ? v > lo : v >= lo);
}

// "hands_off.axes[3].damping_rate" without allocating.
Error invalid_axis_field(int axis, const char* field, const char* rule) noexcept {
    char name[48];
    std::snprintf(name, sizeof name, "hands_off.axes[%d].%s", axis, field);
    return Error::invalid(name, rule);
}

Error check_hands_off(const HandsOffConfig& h, int32_t axis_count) noexcept {
    if (!h.enabled) return {};
    for (int a = 0; a < axis_count; ++a) {
        const FreeHandleModel& m = h.axes[a];
        if (!finite_at_least(m.accel_per_force, 0, true)) {
            return invalid_axis_field(a, "accel_per_force",
                                      "must be a finite value > 0 (position units/s² per force "
                                      "unit: max_force / (mass · half_travel))");
        }
        if (!finite_at_least(m.damping_rate, 0, false)) {
            return invalid_axis_field(a, "damping_rate",
                                      "must be a finite value >= 0 (1/s: viscous damping / mass)");
        }
        if (!finite_at_least(m.friction_accel, 0, false)) {
            return invalid_axis_field(a, "friction_accel",
                                      "must be a finite value >= 0 (position units/s²)");
        }
    }
    if (!kWindowUs.contains(h.window_us)) {
        return Error::out_of_range("hands_off.window_us", h.window_us, kWindowUs);
    }
    if (!(std::isfinite(h.min_force) && h.min_force >= 1 && h.min_force <= kFullScale)) {
        return Error::invalid("hands_off.min_force", "must be within 1..10000 (force units)");
    }
    if (!(std::isfinite(h.max_mismatch) && h.max_mismatch > 0 && h.max_mismatch < 1)) {
        return Error::invalid("hands_off.max_mismatch",
                              "must be within (0, 1) (a ratio of speed gains)");
    }
    if (!kShortTimeUs.contains(h.sustain_us)) {
        return Error::out_of_range("hands_off.sustain_us", h.sustain_us, kShortTimeUs);
    }
    if (!kShortTimeUs.contains(h.confirm_us)) {
        return Error::out_of_range("hands_off.confirm_us", h.confirm_us, kShortTimeUs);
    }
    if (!finite_at_least(h.runaway_speed, 0, true)) {
        return Error::invalid("hands_off.runaway_speed",
                              "must be a finite value > 0 (position units/s)");
    }
    if (!finite_at_least(h.rest_speed, 0, false)) {
        return Error::invalid("hands_off.rest_speed",
                              "must be a finite value >= 0 (position units/s)");
    }
    if (!finite_at_least(h.hand_accel, 0, true)) {
        return Error::invalid("hands_off.hand_accel",
                              "must be a finite value > 0 (position units/s²)");
    }
    if (!kShortTimeUs.contains(h.hand_confirm_us)) {
        return Error::out_of_range("hands_off.hand_confirm_us", h.hand_confirm_us, kShortTimeUs);
    }
    if (!(std::isfinite(h.stop_zone) && h.stop_zone >= 1 && h.stop_zone <= kFullScale)) {
        return Error::invalid("hands_off.stop_zone", "must be within 1..10000 (position units)");
    }
    if (!kShortTimeUs.contains(h.stop_holdoff_us)) {
        return Error::out_of_range("hands_off.stop_holdoff_us", h.stop_holdoff_us, kShortTimeUs);
    }
    if (!range::kDelayUs.contains(h.fade_out_us)) {
        return Error::out_of_range("hands_off.fade_out_us", h.fade_out_us, range::kDelayUs);
    }
    return {};
}

double sign(double v) noexcept { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }

}  // namespace

Error check_safety_config(const SafetyConfig& c) noexcept {
    if (!range::kAxisCount.contains(c.axis_count)) {
        return Error::out_of_range("axis_count", c.axis_count, range::kAxisCount);
    }
    if (!range::kDelayUs.contains(c.fade_in_us)) {
        return Error::out_of_range("fade_in_us", c.fade_in_us, range::kDelayUs);
    }
    if (c.host_timeout_us != kInfiniteUs && !kTimeoutUs.contains(c.host_timeout_us)) {
        return Error::out_of_range("host_timeout_us (or -1: no watchdog)", c.host_timeout_us,
                                   kTimeoutUs);
    }
    if (!range::kDelayUs.contains(c.host_fade_out_us)) {
        return Error::out_of_range("host_fade_out_us", c.host_fade_out_us, range::kDelayUs);
    }
    return check_hands_off(c.hands_off, c.axis_count);
}

SafetyConfig safety_config_for(const sim::DeviceProfile& profile) noexcept {
    SafetyConfig c;
    c.axis_count = profile.axis_count;  // a profile that fails its check fails configure()
    for (int a = 0; a < std::min(c.axis_count, kMaxAxes); ++a) {
        const sim::AxisModel& ax = profile.axes[a];
        // Physical a = F·max_force/(10000·m); normalized a = physical·10000/half_travel.
        FreeHandleModel& m = c.hands_off.axes[a];
        m.accel_per_force = static_cast<float>(ax.max_force / (ax.mass * ax.half_travel));
        m.damping_rate = static_cast<float>(ax.viscous / ax.mass);
        m.friction_accel = static_cast<float>(ax.coulomb / ax.mass * kFullScaleForce / ax.half_travel);
    }
    // The detector's times scale with how fast the bare handle crosses its travel under
    // full force, from the centre to a stop: t = sqrt(2·10000 / (k·10000)) (58 ms on the
    // joystick, 41 ms on the 3-axis device, 307 ms on the wheel). A slow handle can be
    // watched longer before it is judged, which tells a hand from no hand better.
    double k_max = 0;
    for (int a = 0; a < std::min(c.axis_count, kMaxAxes); ++a) {
        k_max = std::max(k_max, static_cast<double>(c.hands_off.axes[a].accel_per_force));
    }
    if (k_max > 0) {
        const double crossing_us = std::sqrt(2.0 / k_max) * 1e6;
        const auto us = [](double v) { return static_cast<int64_t>(std::llround(v)); };
        c.hands_off.window_us = std::clamp<int64_t>(us(crossing_us / kWindowsPerCrossing),
                                                    kWindowUs.min, kWindowUs.max);
        c.hands_off.sustain_us = std::min<int64_t>(us(crossing_us), kShortTimeUs.max);
        c.hands_off.confirm_us = us(crossing_us / kConfirmsPerCrossing);
        c.hands_off.hand_confirm_us = us(crossing_us / kHandConfirmsPerCrossing);
        c.hands_off.fade_out_us = us(crossing_us / kWindowsPerCrossing);
    }
    c.hands_off.runaway_speed = static_cast<float>(kRunawayOverVelocityRef * profile.velocity_ref);
    c.hands_off.rest_speed = static_cast<float>(kRestOverVelocityRef * profile.velocity_ref);
    c.hands_off.hand_accel = static_cast<float>(kHandAccelOverVelocityRef * profile.velocity_ref);
    return c;
}

SafetyInput safety_input(const TickInput& in, const TickOutput& out,
                         const float applied_force[kMaxAxes], int64_t host_heard_us) noexcept {
    SafetyInput s;
    s.t_us = in.t_us;
    s.handle_held = in.handle_held;
    for (int a = 0; a < kMaxAxes; ++a) {
        s.position[a] = in.position[a];
        s.velocity[a] = out.velocity[a];
        s.applied_force[a] = applied_force[a];
    }
    s.host_heard_us = host_heard_us;
    return s;
}

SafetyMonitor::SafetyMonitor() noexcept { reset(); }

Error SafetyMonitor::configure(const SafetyConfig& config) noexcept {
    if (Error e = check_safety_config(config)) return e;
    config_ = config;
    state_.actuators_enabled = true;
    reset();
    return {};
}

void SafetyMonitor::reset() noexcept {
    const bool enabled = state_.actuators_enabled;
    state_ = SafetyState{};
    state_.actuators_enabled = enabled;
    forget_evidence();
    have_last_tick_ = false;
    was_held_ = false;
    quiet_since_us_ = -1;
    phase_ = Phase::off;
    anchor_us_ = 0;
    anchor_level_ = 0;
    host_level_ = 1;
    host_anchor_level_ = 1;
    host_anchor_us_ = 0;
    released_ = false;
    released_at_us_ = 0;
}

void SafetyMonitor::release_host(int64_t t_us) noexcept {
    released_ = true;
    released_at_us_ = t_us;
}

void SafetyMonitor::set_actuators_enabled(bool enabled) noexcept {
    state_.actuators_enabled = enabled;
}

void SafetyMonitor::restart(AxisEvidence& e, int64_t t_us, double velocity) noexcept {
    e.clear();
    e.count = 1;
    e.history[0] = Sample{t_us, velocity, 0.0};
    e.last_velocity = velocity;
}

void SafetyMonitor::forget_evidence() noexcept {
    for (AxisEvidence& e : evidence_) {
        e.clear();
        e.holdoff_until = -1;
    }
}

double SafetyMonitor::free_acceleration(int axis, double force, double v) const noexcept {
    const FreeHandleModel& m = config_.hands_off.axes[axis];
    const double drive = m.accel_per_force * force - m.damping_rate * v;
    if (std::fabs(v) > config_.hands_off.rest_speed) return drive - m.friction_accel * sign(v);
    // At rest dry friction holds against up to friction_accel and opposes the rest.
    if (std::fabs(drive) <= m.friction_accel) return 0;
    return drive - m.friction_accel * sign(drive);
}

void SafetyMonitor::update_watchdog(const SafetyInput& in) noexcept {
    state_.host_lost_event = false;
    if (released_ && in.host_heard_us > released_at_us_) released_ = false;
    const bool timed_out =
        config_.host_timeout_us != kInfiniteUs && in.t_us - in.host_heard_us > config_.host_timeout_us;
    const bool lost = released_ || timed_out;
    if (!lost) {
        host_level_ = 1;
        state_.host_faded = false;
        state_.host_lost = false;
        return;
    }
    if (!state_.host_lost) {
        ++state_.host_losses;
        host_anchor_us_ = in.t_us;
        host_anchor_level_ = host_level_;
        state_.host_faded = false;
    }
    state_.host_lost = true;
    const double elapsed = static_cast<double>(std::max<int64_t>(0, in.t_us - host_anchor_us_));
    host_level_ = config_.host_fade_out_us == 0
                      ? 0.0
                      : std::max(0.0, host_anchor_level_ - elapsed / static_cast<double>(config_.host_fade_out_us));
    if (host_level_ == 0 && !state_.host_faded) {
        state_.host_faded = true;
        state_.host_lost_event = true;
    }
}

void SafetyMonitor::update_detector(const SafetyInput& in, double dt_s) noexcept {
    const HandsOffConfig& h = config_.hands_off;
    // A new grab on the switch is a hand, whatever the motion says.
    if (in.handle_held && !was_held_ && state_.hands_off) {
        state_.hands_off = false;
        state_.hands_off_axes = 0;
        ++state_.hand_rearms;
    }
    if (!h.enabled) return;

    const int64_t window_us = h.window_us;
    // A hand is looked for only once the forces are off and a whole window has seen the
    // forceless handle: while the force changes, the velocity estimate lags it by a few
    // ms, and that lag would pass for a hand.
    if (state_.hands_off && state_.fade_level == 0) {
        if (quiet_since_us_ < 0) quiet_since_us_ = in.t_us;
    } else {
        quiet_since_us_ = -1;
    }
    const bool quiet = quiet_since_us_ >= 0 && in.t_us - quiet_since_us_ >= window_us;
    // Samples older than the newest are kept at least this far apart, so that kHistory of
    // them span the window at any loop rate.
    const int64_t spacing_us = window_us / (kHistory - 2);
    uint32_t free_axes = 0;
    bool hand_seen = false;
    for (int a = 0; a < config_.axis_count; ++a) {
        AxisEvidence& e = evidence_[a];
        const double x = in.position[a];
        const double v = in.velocity[a];
        const double f = std::isfinite(in.applied_force[a]) ? in.applied_force[a] : 0.0;
        if (!std::isfinite(x) || !std::isfinite(v)) {
            e.clear();
            continue;
        }
        const bool at_stop = std::fabs(x) >= h.stop_zone;
        if (at_stop) e.holdoff_until = in.t_us + h.stop_holdoff_us;
        if (at_stop || in.t_us < e.holdoff_until || !have_last_tick_ || dt_s <= 0 || e.count == 0) {
            restart(e, in.t_us, v);
            continue;
        }

        // Extend the history by this tick.
        e.predicted += free_acceleration(a, f, e.last_velocity) * dt_s;
        e.last_velocity = v;
        const int second = (e.newest + kHistory - 1) % kHistory;
        if (e.count >= 2 && in.t_us - e.history[second].t_us < spacing_us) {
            e.history[e.newest] = Sample{in.t_us, v, e.predicted};  // too close: replace
        } else {
            e.newest = (e.newest + 1) % kHistory;
            e.history[e.newest] = Sample{in.t_us, v, e.predicted};
            e.count = std::min(e.count + 1, kHistory);
        }
        // The window's start: the newest sample at least window_us old.
        const Sample* start = nullptr;
        for (int i = 1; i < e.count; ++i) {
            const Sample& s = e.history[(e.newest + kHistory - i) % kHistory];
            if (in.t_us - s.t_us >= window_us) {
                start = &s;
                break;
            }
        }
        if (start == nullptr) continue;  // less than a window of history yet

        const double span_s = static_cast<double>(in.t_us - start->t_us) * 1e-6;
        const double measured = v - start->velocity;
        const double predicted = e.predicted - start->predicted;
        const double mismatch = std::fabs(measured - predicted);
        const double k = h.axes[a].accel_per_force;
        const int8_t sign = predicted > 0 ? 1 : predicted < 0 ? -1 : 0;
        if (sign != e.push_sign) {
            e.push_sign = sign;
            e.push_since = in.t_us;
        }
        const bool strong = std::fabs(predicted) >= k * h.min_force * span_s;
        const bool sustained = sign != 0 && in.t_us - e.push_since >= h.sustain_us;

        // The free-handle match, on a handle that moves with the push: one the window found
        // moving against it was being dragged (a hand's spring swinging it back is at its
        // turn briefly accelerated just as the motor would) or was let go while moving away
        // from where the push throws it; either way it is judged once it has turned.
        const bool with_push = sign * start->velocity >= -h.rest_speed;
        if (strong && sustained && with_push && mismatch <= h.max_mismatch * std::fabs(predicted)) {
            if (e.match_since < 0) e.match_since = in.t_us;
            if (in.t_us - e.match_since >= h.confirm_us) free_axes |= 1u << a;
        } else {
            e.match_since = -1;
        }
        // The runaway: fast, pushed on, and gaining speed nearly as the bare handle would
        // (a handle that the push does not speed up is being held back; one that gains far
        // more than the push can give is being thrown by a hand).
        if (sustained && std::fabs(v) > h.runaway_speed && f * v > 0 && sign * v > 0 &&
            std::fabs(f) >= h.min_force &&
            sign * measured >= (1 - 2 * h.max_mismatch) * std::fabs(predicted) &&
            sign * measured <= (1 + 2 * h.max_mismatch) * std::fabs(predicted)) {
            free_axes |= 1u << a;
        }
        // A hand: what the bare handle's model cannot explain, and well outside the
        // tolerance of a match (during a fade the prediction is still large).
        if (quiet && mismatch >= h.hand_accel * span_s &&
            mismatch > 2 * h.max_mismatch * std::fabs(predicted)) {
            if (e.hand_since < 0) e.hand_since = in.t_us;
            if (in.t_us - e.hand_since >= h.hand_confirm_us) hand_seen = true;
        } else {
            e.hand_since = -1;
        }
    }

    if (!state_.hands_off) {
        // Not held: the switch already cuts the force; nothing to protect.
        if (in.handle_held && free_axes != 0) {
            state_.hands_off = true;
            state_.hands_off_axes = free_axes;
            ++state_.hands_off_trips;
            for (AxisEvidence& e : evidence_) e.hand_since = -1;
        }
    } else if (hand_seen) {
        state_.hands_off = false;
        state_.hands_off_axes = 0;
        ++state_.hand_rearms;
        for (AxisEvidence& e : evidence_) e.match_since = -1;
    }
}

void SafetyMonitor::update_fade(const SafetyInput& in) noexcept {
    const auto level_at = [this](int64_t t_us) noexcept -> double {
        const double elapsed = static_cast<double>(std::max<int64_t>(0, t_us - anchor_us_));
        switch (phase_) {
        case Phase::off:
            return 0.0;
        case Phase::rising:
            if (config_.fade_in_us == 0) return 1.0;
            return std::min(1.0, anchor_level_ + elapsed / static_cast<double>(config_.fade_in_us));
        case Phase::falling:
            if (config_.hands_off.fade_out_us == 0) return 0.0;
            return std::max(0.0, anchor_level_ -
                                     elapsed / static_cast<double>(config_.hands_off.fade_out_us));
        }
        return 0.0;
    };
    const Phase want = !state_.actuators_enabled || !in.handle_held ? Phase::off
                       : state_.hands_off                           ? Phase::falling
                                                                    : Phase::rising;
    double level = level_at(in.t_us);  // the old ramp, continued to now
    if (want != phase_) {
        if (want == Phase::off) level = 0;
        phase_ = want;
        anchor_us_ = in.t_us;
        anchor_level_ = level;
        level = level_at(in.t_us);
    }
    state_.fade_level = static_cast<float>(level);
}

const SafetyState& SafetyMonitor::process(const SafetyInput& in, float force[kMaxAxes]) noexcept {
    double dt_s = 0;
    if (have_last_tick_) {
        if (in.t_us < state_.t_us) {
            // The clock went back: the evidence spans a gap that makes no sense. Keep the
            // fade where it is, re-anchored at the new time.
            forget_evidence();
            anchor_us_ = in.t_us;
            anchor_level_ = state_.fade_level;
        } else {
            dt_s = static_cast<double>(in.t_us - state_.t_us) * 1e-6;
        }
    }
    update_watchdog(in);
    update_detector(in, dt_s);
    update_fade(in);
    state_.handle_held = in.handle_held;
    state_.output_scale = static_cast<float>(static_cast<double>(state_.fade_level) * host_level_);
    state_.t_us = in.t_us;
    have_last_tick_ = true;
    was_held_ = in.handle_held;

    const float scale = state_.output_scale;
    for (int a = 0; a < kMaxAxes; ++a) {
        float f = a < config_.axis_count ? force[a] : 0.0f;
        if (!std::isfinite(f)) {
            f = 0;
            ++state_.nonfinite_forces;
        }
        force[a] = std::clamp(f, -static_cast<float>(kFullScale), static_cast<float>(kFullScale)) *
                   scale;
    }
    return state_;
}

}  // namespace feel::runtime
