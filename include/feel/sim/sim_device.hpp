// feel::sim — the simulated device: handle physics, motors, sensors and the hand.
//
// This is feel's embedded default device. Each axis is a mass with viscous and Coulomb
// friction, end stops at ±half_travel, a motor that can push at most max_force, and a
// quantizing position sensor. A hand may hold it (see hand.hpp). The integration method
// and its accuracy are described in src/sim/sim_device.cpp and docs/simulated-device.md.
#pragma once

#include <cstdint>

#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"

namespace feel::sim {

// The longest step() accepts, s. A loop runs at 100 Hz..10 kHz; a longer step is a bug.
inline constexpr double kMaxStepS = 1.0;
// Substeps keep rate·h at or below this (rate: the stiffest spring's ω or the largest
// damping rate b/m of the device with its grip), so that the integrator's frequency error
// stays below (ω·h)²/24 ≈ 1e-4 and its energy ripple below ω·h/2 = 2.5%.
inline constexpr double kSubstepRateH = 0.05;
// At most this many substeps per step(); only an absurd profile or dt reaches it.
inline constexpr int32_t kMaxSubsteps = 4096;
// Limits of the test hooks set_position (one travel past either end) and set_velocity
// (normalized units/s: ten thousand travels a second, far beyond any hand).
inline constexpr double kMaxTeleport = 20000;
inline constexpr double kMaxSetSpeed = 1e8;
// How long a hand that grabs the handle takes to bring it back to its target motion, s:
// the time constant of the return (most of the way in 3τ, 0.6 s), an unhurried reach.
inline constexpr double kRegrabReturnS = 0.2;

class SimDevice {
public:
    // Throws std::invalid_argument if the profile is unusable (check_device_profile) or
    // the motion names more axes than the device has. The handle starts where the motion
    // starts: at rest for Grip::none, moving with the target otherwise. The profile must
    // outlive the device.
    SimDevice(const DeviceProfile& profile, Grip grip, TargetMotion motion);

    // Fills the sensor fields of `in` (quantized positions, buttons, the dead-man switch)
    // from the current state. The caller sets in.t_us. Positions are rounded to the
    // sensor's step, 20000 / sensor_counts, and read at most ±10000 (a handle pressed into
    // an end stop reads the end of the travel). Axes the device does not have read 0.
    // buttons is what set_buttons() last set. handle_held is handle_held() on a profile
    // with a dead-man switch, and always true on one without.
    void sense(TickInput& in) const noexcept;

    // Applies the motor forces (normalized, ±10000, clamped again to the motor limit) for
    // dt seconds and advances the handle and the hand. Never allocates.
    // A non-finite force (NaN, ±inf) drives its motor with 0 and is counted in
    // nonfinite_forces(). A dt that is not finite or not in (0, kMaxStepS] moves nothing,
    // does not advance time and is counted in rejected_steps().
    void step(const float force[kMaxAxes], double dt_s) noexcept;

    [[nodiscard]] double time_s() const noexcept { return t_s_; }
    // The true state in normalized units (not quantized). 0 for an axis the device lacks.
    [[nodiscard]] double position(int axis) const noexcept;
    [[nodiscard]] double velocity(int axis) const noexcept;  // normalized units / s
    // The true state in physical units (m or rad, m/s or rad/s).
    [[nodiscard]] double physical_position(int axis) const noexcept { return x_[axis]; }
    [[nodiscard]] double physical_velocity(int axis) const noexcept { return v_[axis]; }
    // The force the hand applied over the last step, physical units (mean over the step).
    [[nodiscard]] double hand_force(int axis) const noexcept { return hand_force_[axis]; }

    // For tests and scripted starts. set_position teleports the handle (v = 0) to
    // |normalized| <= kMaxTeleport; set_velocity sets |normalized_per_s| <= kMaxSetSpeed
    // and keeps x. Both return false and change nothing for a bad axis or value.
    bool set_position(int axis, double normalized) noexcept;
    bool set_velocity(int axis, double normalized_per_s) noexcept;
    [[nodiscard]] const DeviceProfile& profile() const noexcept { return *profile_; }
    [[nodiscard]] Grip grip() const noexcept { return grip_; }
    [[nodiscard]] const TargetMotion& motion() const noexcept { return motion_; }

    // The hand lets go (false) or grabs the handle again (true); it starts present. While
    // it is away the grip's spring, damper and added mass vanish and the handle moves
    // freely, as with Grip::none, and the target motion keeps running. A hand grabs the
    // handle where it finds it: its target becomes the motion's plus the offset d0 of the
    // handle from it at the grab, and it brings the handle back to the motion smoothly,
    // the offset decaying as d0·(1 + s/τ)·e^(−s/τ), τ = kRegrabReturnS, s the time since
    // the grab (critically damped: it starts and ends at rest relative to the motion). A
    // grab is an inelastic collision: the hand's added mass, moving with the motion, joins
    // the handle and momentum is conserved. With Grip::none there is no hand, and this
    // only records the flag. Real-time safe; call it between steps.
    void set_hand_present(bool present) noexcept;
    [[nodiscard]] bool hand_present() const noexcept { return hand_present_; }
    // A hand holds the handle: a grip other than none, and the hand present.
    [[nodiscard]] bool handle_held() const noexcept {
        return grip_ != Grip::none && hand_present_;
    }
    // The buttons pressed from now on, bit i = button i+1 (TickInput::buttons). Returns
    // false and changes nothing when a bit names a button the profile lacks (bit i with
    // i >= button_count). Real-time safe.
    bool set_buttons(uint32_t pressed) noexcept;
    [[nodiscard]] uint32_t buttons() const noexcept { return buttons_; }
    // The hat switches pushed off center from now on, bit h-1 = hat h (TickInput::hats).
    // Returns false and changes nothing when a bit names a hat the profile lacks.
    // Real-time safe.
    bool set_hats(uint32_t pushed) noexcept;
    [[nodiscard]] uint32_t hats() const noexcept { return hats_; }
    // A live target (the Studio's pointer): from now on the hand wants the handle at these
    // normalized positions (at rest) instead of its target motion, until
    // clear_live_target(). Returns false and changes nothing for a position outside
    // -10000..10000 or not finite. Axes past `count` hold 0. Real-time safe.
    bool set_live_target(const double* positions, int count) noexcept;
    // Another hand takes the handle (the Studio's hand menu): the tether's spring, damper
    // and added mass become the new grip's from the next step on; the handle keeps its
    // position and velocity. Real-time safe.
    void set_grip(Grip grip) noexcept;
    void clear_live_target() noexcept { live_target_ = false; }
    [[nodiscard]] bool has_live_target() const noexcept { return live_target_; }

    // The substeps step(dt_s) will take now (they depend on whether the hand is present);
    // h = dt_s / substeps(dt_s).
    [[nodiscard]] int32_t substeps(double dt_s) const noexcept;
    // Diagnostics for the robustness rules of step().
    [[nodiscard]] int64_t nonfinite_forces() const noexcept { return nonfinite_forces_; }
    [[nodiscard]] int64_t rejected_steps() const noexcept { return rejected_steps_; }

private:
    // Where the hand wants the handle at t_s: the motion plus what is left of the offset
    // of the last grab. Normalized units.
    [[nodiscard]] TargetMotion::Sample hand_target(double t_s) const noexcept;
    void update_rates() noexcept;  // rate_ and rate_free_ from the profile and the grip
    void step_tethered(const double motor[kMaxAxes], double dt_s) noexcept;
    void step_kinematic(const double motor[kMaxAxes], double dt_s) noexcept;

    const DeviceProfile* profile_;
    Grip grip_;
    TargetMotion motion_;
    GripModel grip_model_{};  // zero for Grip::none and Grip::kinematic
    double rate_ = 0;         // 1/s: the fastest spring ω or damping b/m of any axis, held
    double rate_free_ = 0;    // 1/s: the same for the handle without its hand
    bool hand_present_ = true;
    uint32_t buttons_ = 0;    // bit i = button i+1 pressed
    uint32_t hats_ = 0;       // bit h-1 = hat h pushed off center
    bool live_target_ = false;               // set_live_target() replaces the motion
    double live_position_[kMaxAxes] = {};    // normalized
    // The last grab: when, and the handle's offset from the motion then (normalized).
    double grab_t_s_ = 0;
    double grab_offset_[kMaxAxes] = {};
    double t_s_ = 0;
    double x_[kMaxAxes] = {};  // physical position
    double v_[kMaxAxes] = {};  // physical velocity
    double hand_force_[kMaxAxes] = {};
    int64_t nonfinite_forces_ = 0;
    int64_t rejected_steps_ = 0;
};

}  // namespace feel::sim
