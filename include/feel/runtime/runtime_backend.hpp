// feel::runtime — the device backend: the sensors and motors the runtime drives.
//
// The runtime's pipeline (runtime_pipeline.hpp) talks to the hardware through two calls
// per tick: sense() before rendering and actuate() after the safety monitor. The simulated
// device is the default backend (SimBackend); real hardware plugs in behind the same
// contract: a class derived from RuntimeBackend whose sense() reads the encoders, buttons,
// hats and dead-man switch, and whose actuate() sets the motor currents.
//
// Contract. Both calls run on the loop thread, once per tick, in the order sense, actuate;
// both must be real-time safe (no allocation, lock, blocking system call or throw) and
// noexcept. The time passed to sense() is the tick's nominal time from the tick count; it
// increases from tick to tick but may jump by several periods after an overrun.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>

#include "feel/axis.hpp"
#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/sim/input_schedule.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::runtime {

class RuntimeBackend {
public:
    virtual ~RuntimeBackend() = default;

    // The device's axes, 1..kMaxAxes (x, y, z, rx, ry, rz in order). Must equal the
    // engine's axis_count; the pipeline checks it at construction.
    [[nodiscard]] virtual int32_t axis_count() const noexcept = 0;
    // The device's buttons, 0..32.
    [[nodiscard]] virtual int32_t button_count() const noexcept = 0;

    // Reads the sensors as they are at t_us into `in`: position (normalized ±10000, axes
    // the device lacks 0), buttons, hats and the dead-man switch (handle_held). in.t_us is
    // already set. Real-time safe.
    virtual void sense(int64_t t_us, TickInput& in) noexcept = 0;
    // Drives the motors with these forces (normalized ±10000, physical sign, already
    // scaled by the safety monitor) from now until the next actuate(). Real-time safe.
    virtual void actuate(const float force[kMaxAxes]) noexcept = 0;
};

// The simulated device (feel::sim::SimDevice) as a backend, with an optional script of
// grabs, let-gos and button presses (feel::sim::InputSchedule).
//
// sense(t) first advances the handle's physics from the previous sense() to t under the
// force of the last actuate() (held, as a motor driver holds it: a zero-order hold), then
// applies the script's events due at or before t, then reads the sensors. So each tick
// sees the handle one tick period after the previous one, even when ticks are skipped
// after an overrun, and an event scripted at t is seen by the tick at t.
class SimBackend final : public RuntimeBackend {
public:
    // Throws std::invalid_argument for an unusable profile or a motion with more axes than
    // the device (SimDevice's constructor). The profile must outlive the backend.
    SimBackend(const sim::DeviceProfile& profile, sim::Grip grip, sim::TargetMotion motion,
               std::optional<sim::InputSchedule> schedule = std::nullopt);

    [[nodiscard]] int32_t axis_count() const noexcept override;
    [[nodiscard]] int32_t button_count() const noexcept override;
    void sense(int64_t t_us, TickInput& in) noexcept override;
    void actuate(const float force[kMaxAxes]) noexcept override;

    // The simulated device and the script, for tests and tools (the loop thread's, or any
    // thread's while no loop runs).
    [[nodiscard]] sim::SimDevice& device() noexcept { return device_; }
    [[nodiscard]] const sim::SimDevice& device() const noexcept { return device_; }
    [[nodiscard]] sim::InputSchedule* schedule() noexcept { return schedule_ ? &*schedule_ : nullptr; }
    // The force of the last actuate(), what drives the handle now.
    [[nodiscard]] const float* force() const noexcept { return force_; }

    // The simulated hand presses buttons (bit i = button i+1) or pushes hats off center
    // (bit h-1 = hat h), from any thread while the loop runs: the next sense() applies the
    // latest mask (a lock-free handoff, no need to stop the loop). Returns false, and
    // changes nothing, for a bit naming a control the profile lacks.
    bool set_buttons(uint32_t pressed) noexcept;
    bool set_hats(uint32_t pushed) noexcept;
    // The hand's live target (a person's pointer in the Studio): the hand pulls the handle
    // toward these normalized positions of the first three axes, in whole units, from the
    // next sense() on, instead of its target motion (a lock-free handoff, any thread).
    // Returns false, and changes nothing, for a position outside -10000..10000.
    // clear_hand_target() goes back to the target motion.
    bool set_hand_target(int32_t x, int32_t y, int32_t z) noexcept;
    void clear_hand_target() noexcept;
    // Another hand grip from the next sense() on (SimDevice::set_grip), any thread.
    void set_grip(sim::Grip grip) noexcept;
    // The device time (µs) of the sense() that took the newest live target, -1 before the
    // first, any thread: splits a target's way to the handle into the wait for the loop's
    // tick and the handle's motion (the Studio's latency hops, docs/studio.md).
    [[nodiscard]] int64_t hand_target_taken_us() const noexcept {
        return target_taken_us_.load(std::memory_order_acquire);
    }

private:
    // A mask waiting for the next sense(): bit 32 set when there is one.
    static constexpr uint64_t kPendingBit = uint64_t{1} << 32;

    sim::SimDevice device_;
    std::atomic<uint64_t> pending_buttons_{0};
    std::atomic<uint64_t> pending_hats_{0};
    // A live target waiting for the next sense(): three int16 positions in bits 0..47,
    // kTargetPendingBit set when there is one, kTargetClearBit to go back to the motion.
    static constexpr uint64_t kTargetPendingBit = uint64_t{1} << 63;
    static constexpr uint64_t kTargetClearBit = uint64_t{1} << 62;
    std::atomic<uint64_t> pending_target_{0};
    std::atomic<int64_t> target_taken_us_{-1};
    std::atomic<uint64_t> pending_grip_{0};  // kPendingBit | grip
    std::optional<sim::InputSchedule> schedule_;
    float force_[kMaxAxes] = {};
    bool sensed_ = false;   // a sense() happened: t_us_ is the handle's time
    int64_t t_us_ = 0;      // device time of the handle's state, µs
};

}  // namespace feel::runtime
