// The simulated device's physics.
//
// Each axis is an independent one-dimensional body (a gimballed stick's axes each have
// their own motor, gear train and stop, so they do not share friction or mass):
//
//     m·a = F_motor + F_hand + F_stop − b·v − F_c·sign(v)
//
//   m        the handle's mass plus, while a hand holds it, the hand's added mass
//   F_motor  the commanded force, clamped to ±max_force, held for the whole step (a real
//            motor amplifier holds its last command until the next tick, too)
//   F_hand   −k_g·(x − x_t) − b_g·(v − v_t): a spring-damper to the target motion x_t(t)
//   F_stop   −k_s·p − b_s·v while the handle presses into a stop (p: penetration past
//            ±half_travel); the damping acts only while it presses deeper, so the stop
//            pushes but never pulls the handle back in
//   b, F_c   the mechanism's viscous and Coulomb friction
//
// Integration: semi-implicit (symplectic) Euler on substeps of length h.
//
//   u  = v + h·F_explicit/m                    springs, motor, target terms at x(t)
//   v' = 0                                     if |u| <= h·F_c/m   (sticks)
//   v' = (u − sign(u)·h·F_c/m) / (1 + h·B/m)   otherwise           (slides)
//   x' = x + h·v'
//
// Why this scheme:
//  * Springs explicit, velocity first: symplectic Euler does not pump or bleed energy
//    from an undamped oscillator; its energy ripples by about ω·h/2 and its frequency is
//    off by (ω·h)²/24. It is stable for ω·h < 2.
//  * All damping (B = b + b_g + b_s) implicit: stable for any b·h/m, so a heavily damped
//    stiff grip on a light handle cannot blow up, and the decay is monotone.
//  * Coulomb friction implicit, as the set-valued law it is: v' solves
//    v'·(m + h·B) = m·u − h·F_c·sign(v') with sign(0) anywhere in [−1, 1]. That equation
//    has exactly one solution, the one above. A handle pushed by less than F_c holds
//    exactly still (v' = 0, not a chatter between ±), a sliding handle stops within one
//    substep of v0·m/F_c, and there is no regularization speed to tune.
//  * Substeps keep rate·h <= kSubstepRateH, where rate is the fastest of √(k/m) (grip
//    spring plus stop spring, the stiffest spring the axis can see) and B/m, computed once
//    per device from the profile and the grip. At 1 kHz the built-in profiles take 3 to
//    12 substeps, at 10 kHz one or two, at 100 Hz up to 116: a few multiplications each,
//    0.1..0.5 µs per step.
//  * If a step is so long (or a custom profile so stiff) that kMaxSubsteps is not enough
//    and rate·h exceeds 1, the springs switch to backward Euler (their stiffness joins B
//    as h·k): unconditionally stable, over-damped, never NaN. Built-in profiles at
//    100 Hz..10 kHz never get there.
//
// Robustness: a non-finite force drives the motor with 0 (the safe output for a value
// that means a bug upstream) and is counted; a non-finite or out-of-range dt moves
// nothing. Everything else is bounded by construction: motor forces are clamped, the
// target lies within the travel, and the integrator is stable, so positions and
// velocities stay finite for any input.
//
// Hand presence: set_hand_present(false) takes the hand away (the grip's spring, damper and
// added mass vanish; the handle is free) and set_hand_present(true) brings it back. The
// free handle is lighter than the held one, so its substep rate is computed separately.
// A hand grabs the handle where it finds it rather than yanking it onto a target that may
// be the whole travel away (a firm grip stretched over the wheel's 450° would pull with
// 94 N·m): the tether's target carries the grab's offset, which decays back to the motion
// (hand_target).
//
// Kinematic grip: the hand prescribes the motion. At the end of the step the handle is at
// the target with the target's velocity, and hand_force() reports the force the hand had
// to apply to make it so (Newton's law solved for F_hand, friction included).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "feel/sim/sim_device.hpp"
#include "feel/units.hpp"

namespace feel::sim {
namespace {

constexpr double kScale = kFullScale;

// How far the handle is past an end stop: > 0 beyond +half_travel, < 0 beyond −half.
double penetration(double x, double half_travel) noexcept {
    if (x > half_travel) return x - half_travel;
    if (x < -half_travel) return x + half_travel;
    return 0;
}

GripModel grip_model(const DeviceProfile& profile, Grip grip) {
    switch (grip) {
    case Grip::none:
    case Grip::kinematic:
        return {};
    case Grip::loose:
        return profile.loose;
    case Grip::firm:
        return profile.firm;
    case Grip::stiff:
        return profile.stiff;
    }
    throw std::invalid_argument("grip = " + std::to_string(static_cast<int>(grip)) +
                                " is not a grip (allowed none, loose, firm, stiff, kinematic)");
}

}  // namespace

SimDevice::SimDevice(const DeviceProfile& profile, Grip grip, TargetMotion motion)
    : profile_(&profile), grip_(grip), motion_(std::move(motion)) {
    if (const std::string error = check_device_profile(profile); !error.empty()) {
        throw std::invalid_argument("device profile \"" + std::string(profile.name) +
                                    "\": " + error);
    }
    grip_model_ = grip_model(profile, grip);
    if (motion_.used_axes() > profile.axis_count) {
        throw std::invalid_argument("--motion \"" + motion_.spec() + "\" moves " +
                                    std::to_string(motion_.used_axes()) + " axes, but device \"" +
                                    std::string(profile.name) + "\" has " +
                                    std::to_string(profile.axis_count));
    }
    update_rates();
    // The hand puts the handle where the motion starts; a holding hand is already moving
    // with the target, so the tether starts unstretched.
    const TargetMotion::Sample start = motion_.at(0);
    for (int a = 0; a < profile.axis_count; ++a) {
        const double scale = profile.axes[a].half_travel / kScale;
        x_[a] = start.position[a] * scale;
        v_[a] = grip_ == Grip::none ? 0 : start.velocity[a] * scale;
    }
}

void SimDevice::update_rates() noexcept {
    rate_ = 0;
    rate_free_ = 0;
    for (int a = 0; a < profile_->axis_count; ++a) {
        const AxisModel& ax = profile_->axes[a];
        if (grip_ != Grip::kinematic) {
            const double m = ax.mass + grip_model_.added_mass;
            const double k = grip_model_.stiffness + ax.end_stop_stiffness;
            const double b = ax.viscous + grip_model_.damping + ax.end_stop_damping;
            rate_ = std::max({rate_, std::sqrt(k / m), b / m});
        }
        const double b_free = ax.viscous + ax.end_stop_damping;
        rate_free_ = std::max({rate_free_, std::sqrt(ax.end_stop_stiffness / ax.mass),
                               b_free / ax.mass});
    }
}

void SimDevice::set_grip(Grip grip) noexcept {
    grip_ = grip;
    grip_model_ = grip_model(*profile_, grip);
    update_rates();
}

int32_t SimDevice::substeps(double dt_s) const noexcept {
    if (!(dt_s > 0) || !(dt_s <= kMaxStepS)) return 1;
    const double rate = handle_held() ? rate_ : rate_free_;
    const double n = std::ceil(rate * dt_s / kSubstepRateH);
    return static_cast<int32_t>(std::clamp(n, 1.0, static_cast<double>(kMaxSubsteps)));
}

void SimDevice::sense(TickInput& in) const noexcept {
    std::fill(std::begin(in.position), std::end(in.position), 0.0f);
    for (int a = 0; a < profile_->axis_count; ++a) {
        const double step = 2 * kScale / profile_->axes[a].sensor_counts;
        const double reading = step * std::round(position(a) / step);
        in.position[a] = static_cast<float>(std::clamp(reading, -kScale, kScale));
    }
    in.buttons = buttons_;
    in.hats = hats_;
    in.handle_held = profile_->dead_man_switch ? handle_held() : true;
}

bool SimDevice::set_live_target(const double* positions, int count) noexcept {
    if (count < 0 || count > kMaxAxes) return false;
    for (int a = 0; a < count; ++a) {
        if (!std::isfinite(positions[a]) || std::abs(positions[a]) > kScale) return false;
    }
    for (int a = 0; a < kMaxAxes; ++a) live_position_[a] = a < count ? positions[a] : 0.0;
    live_target_ = true;
    return true;
}

TargetMotion::Sample SimDevice::hand_target(double t_s) const noexcept {
    TargetMotion::Sample target = motion_.at(t_s);
    if (live_target_) {
        // A live target is where the person's pointer is: the hand wants the handle there,
        // at rest (the pointer's own speed is not known between its events).
        for (int a = 0; a < kMaxAxes; ++a) {
            target.position[a] = live_position_[a];
            target.velocity[a] = 0;
        }
    }
    bool offset = false;
    for (int a = 0; a < profile_->axis_count; ++a) offset = offset || grab_offset_[a] != 0;
    if (!offset) return target;
    const double s = std::max(0.0, t_s - grab_t_s_) / kRegrabReturnS;
    const double decay = std::exp(-s);
    for (int a = 0; a < profile_->axis_count; ++a) {
        target.position[a] += grab_offset_[a] * (1 + s) * decay;
        target.velocity[a] -= grab_offset_[a] * s / kRegrabReturnS * decay;
    }
    return target;
}

void SimDevice::set_hand_present(bool present) noexcept {
    const bool grabs = present && !hand_present_;
    hand_present_ = present;
    if (!grabs || grip_ == Grip::none) return;
    // The hand takes the handle where it is ...
    const TargetMotion::Sample motion = motion_.at(t_s_);
    grab_t_s_ = t_s_;
    for (int a = 0; a < profile_->axis_count; ++a) {
        grab_offset_[a] = position(a) - motion.position[a];
    }
    if (grip_ == Grip::kinematic) return;
    // ... and its added mass arrives moving with the motion: an inelastic collision.
    const TargetMotion::Sample target = motion;
    for (int a = 0; a < profile_->axis_count; ++a) {
        const double m_handle = profile_->axes[a].mass;
        const double m_hand = grip_model_.added_mass;
        const double v_hand = target.velocity[a] * profile_->axes[a].half_travel / kScale;
        v_[a] = (m_handle * v_[a] + m_hand * v_hand) / (m_handle + m_hand);
    }
}

bool SimDevice::set_buttons(uint32_t pressed) noexcept {
    const int32_t count = profile_->button_count;
    const uint32_t allowed = count >= 32 ? 0xFFFFFFFFu : (uint32_t{1} << count) - 1u;
    if ((pressed & ~allowed) != 0) return false;
    buttons_ = pressed;
    return true;
}

bool SimDevice::set_hats(uint32_t pushed) noexcept {
    const int32_t count = profile_->hat_count;  // 0..4 (check_device_profile)
    const uint32_t allowed = (uint32_t{1} << count) - 1u;
    if ((pushed & ~allowed) != 0) return false;
    hats_ = pushed;
    return true;
}

void SimDevice::step(const float force[kMaxAxes], double dt_s) noexcept {
    if (!(dt_s > 0) || !(dt_s <= kMaxStepS)) {
        ++rejected_steps_;
        return;
    }
    double motor[kMaxAxes] = {};
    for (int a = 0; a < profile_->axis_count; ++a) {
        const double f = force[a];
        if (!std::isfinite(f)) {
            ++nonfinite_forces_;
            continue;
        }
        motor[a] = std::clamp(f / kScale, -1.0, 1.0) * profile_->axes[a].max_force;
    }
    if (grip_ == Grip::kinematic && hand_present_) {
        step_kinematic(motor, dt_s);
    } else {
        step_tethered(motor, dt_s);
    }
    t_s_ += dt_s;
}

void SimDevice::step_tethered(const double motor[kMaxAxes], double dt_s) noexcept {
    const int32_t n = substeps(dt_s);
    const double h = dt_s / n;
    const bool held = handle_held();
    const bool backward_springs = (held ? rate_ : rate_free_) * h > 1.0;
    const GripModel g = held ? grip_model_ : GripModel{};
    double hand_sum[kMaxAxes] = {};
    for (int32_t i = 0; i < n; ++i) {
        const TargetMotion::Sample target = held ? hand_target(t_s_ + i * h)
                                                 : TargetMotion::Sample{};
        for (int a = 0; a < profile_->axis_count; ++a) {
            const AxisModel& ax = profile_->axes[a];
            const double scale = ax.half_travel / kScale;
            const double m = ax.mass + g.added_mass;
            const double x = x_[a];
            const double v = v_[a];
            const double xt = target.position[a] * scale;
            const double vt = target.velocity[a] * scale;

            const double p = penetration(x, ax.half_travel);
            const double f_explicit =
                motor[a] - g.stiffness * (x - xt) + g.damping * vt - ax.end_stop_stiffness * p;
            const double u = v + h * f_explicit / m;

            double b = ax.viscous + g.damping;
            if (p * u > 0) b += ax.end_stop_damping;  // pressing deeper into the stop
            if (backward_springs) b += h * (g.stiffness + (p != 0 ? ax.end_stop_stiffness : 0));

            const double stop_speed = h * ax.coulomb / m;  // what friction removes in h
            const double v_next = std::fabs(u) <= stop_speed
                                      ? 0.0
                                      : (u - std::copysign(stop_speed, u)) / (1 + h * b / m);
            x_[a] = x + h * v_next;
            v_[a] = v_next;
            hand_sum[a] += -g.stiffness * (x - xt) - g.damping * (v_next - vt);
        }
    }
    for (int a = 0; a < profile_->axis_count; ++a) hand_force_[a] = hand_sum[a] / n;
}

void SimDevice::step_kinematic(const double motor[kMaxAxes], double dt_s) noexcept {
    const TargetMotion::Sample target = hand_target(t_s_ + dt_s);
    for (int a = 0; a < profile_->axis_count; ++a) {
        const AxisModel& ax = profile_->axes[a];
        const double scale = ax.half_travel / kScale;
        const double x = target.position[a] * scale;
        const double v = target.velocity[a] * scale;
        const double p = penetration(x, ax.half_travel);
        // Every force on the handle but the hand's and friction's.
        double others = motor[a] - ax.viscous * v - ax.end_stop_stiffness * p;
        if (p * v > 0) others -= ax.end_stop_damping * v;
        const double needed = ax.mass * (v - v_[a]) / dt_s - others;
        double hand = 0;
        if (v != 0) {
            hand = needed + std::copysign(ax.coulomb, v);  // sliding: friction opposes v
        } else if (std::fabs(needed) > ax.coulomb) {
            hand = needed - std::copysign(ax.coulomb, needed);  // static friction helps
        }
        x_[a] = x;
        v_[a] = v;
        hand_force_[a] = hand;
    }
}

double SimDevice::position(int axis) const noexcept {
    if (axis < 0 || axis >= profile_->axis_count) return 0;
    return x_[axis] / profile_->axes[axis].half_travel * kScale;
}

double SimDevice::velocity(int axis) const noexcept {
    if (axis < 0 || axis >= profile_->axis_count) return 0;
    return v_[axis] / profile_->axes[axis].half_travel * kScale;
}

bool SimDevice::set_position(int axis, double normalized) noexcept {
    if (axis < 0 || axis >= profile_->axis_count || !(std::fabs(normalized) <= kMaxTeleport)) {
        return false;
    }
    x_[axis] = normalized / kScale * profile_->axes[axis].half_travel;
    v_[axis] = 0;
    return true;
}

bool SimDevice::set_velocity(int axis, double normalized_per_s) noexcept {
    if (axis < 0 || axis >= profile_->axis_count ||
        !(std::fabs(normalized_per_s) <= kMaxSetSpeed)) {
        return false;
    }
    v_[axis] = normalized_per_s / kScale * profile_->axes[axis].half_travel;
    return true;
}

}  // namespace feel::sim
