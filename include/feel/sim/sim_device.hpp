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

class SimDevice {
public:
    // Throws std::invalid_argument if the profile is unusable (check_device_profile) or
    // the motion names more axes than the device has. The handle starts where the motion
    // starts: at rest for Grip::none, moving with the target otherwise. The profile must
    // outlive the device.
    SimDevice(const DeviceProfile& profile, Grip grip, TargetMotion motion);

    // Fills the sensor fields of `in` (quantized positions, buttons) from the current
    // state. The caller sets in.t_us. Positions are rounded to the sensor's step,
    // 20000 / sensor_counts, and read at most ±10000 (a handle pressed into an end stop
    // reads the end of the travel). Axes the device does not have read 0; no button is
    // ever pressed.
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

    // The substeps step(dt_s) will take; h = dt_s / substeps(dt_s).
    [[nodiscard]] int32_t substeps(double dt_s) const noexcept;
    // Diagnostics for the robustness rules of step().
    [[nodiscard]] int64_t nonfinite_forces() const noexcept { return nonfinite_forces_; }
    [[nodiscard]] int64_t rejected_steps() const noexcept { return rejected_steps_; }

private:
    void step_tethered(const double motor[kMaxAxes], double dt_s) noexcept;
    void step_kinematic(const double motor[kMaxAxes], double dt_s) noexcept;

    const DeviceProfile* profile_;
    Grip grip_;
    TargetMotion motion_;
    GripModel grip_model_{};  // zero for Grip::none and Grip::kinematic
    double rate_ = 0;         // 1/s: the fastest spring ω or damping b/m of any axis
    double t_s_ = 0;
    double x_[kMaxAxes] = {};  // physical position
    double v_[kMaxAxes] = {};  // physical velocity
    double hand_force_[kMaxAxes] = {};
    int64_t nonfinite_forces_ = 0;
    int64_t rejected_steps_ = 0;
};

}  // namespace feel::sim
