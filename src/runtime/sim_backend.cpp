// The simulated device behind the runtime's backend contract (runtime_backend.hpp).
//
// The handle's physics advance lazily, at the next sense(), by exactly the device time
// that passed: the force of the last actuate() held over [previous tick, this tick). That
// is what a motor driver does between two updates, and it keeps the simulated handle on
// the loop's own clock, overruns included (a tick skipped by the loop is time the handle
// spends under the last force, as real hardware would).
#include <algorithm>
#include <utility>

#include "feel/runtime/runtime_backend.hpp"

namespace feel::runtime {

SimBackend::SimBackend(const sim::DeviceProfile& profile, sim::Grip grip, sim::TargetMotion motion,
                       std::optional<sim::InputSchedule> schedule)
    : device_(profile, grip, std::move(motion)), schedule_(std::move(schedule)) {}

int32_t SimBackend::axis_count() const noexcept { return device_.profile().axis_count; }

int32_t SimBackend::button_count() const noexcept { return device_.profile().button_count; }

void SimBackend::sense(int64_t t_us, TickInput& in) noexcept {
    if (sensed_ && t_us > t_us_) {
        // SimDevice::step takes at most kMaxStepS at a time; a loop's ticks are far apart
        // less than that, but a long pause of a stopped runtime is not.
        double remaining_s = static_cast<double>(t_us - t_us_) * 1e-6;
        while (remaining_s > 0) {
            const double dt_s = std::min(remaining_s, sim::kMaxStepS);
            device_.step(force_, dt_s);
            remaining_s -= dt_s;
        }
    }
    if (!sensed_ || t_us > t_us_) t_us_ = t_us;
    sensed_ = true;
    if (schedule_) (void)schedule_->apply(device_, t_us);
    // Masks handed over by set_buttons/set_hats (checked there, so the device accepts them).
    if (const uint64_t b = pending_buttons_.exchange(0, std::memory_order_acquire); b & kPendingBit) {
        (void)device_.set_buttons(static_cast<uint32_t>(b));
    }
    if (const uint64_t h = pending_hats_.exchange(0, std::memory_order_acquire); h & kPendingBit) {
        (void)device_.set_hats(static_cast<uint32_t>(h));
    }
    device_.sense(in);
}

bool SimBackend::set_buttons(uint32_t pressed) noexcept {
    const int32_t count = device_.profile().button_count;  // 0..32
    const uint32_t allowed = count >= 32 ? 0xFFFFFFFFu : (uint32_t{1} << count) - 1u;
    if ((pressed & ~allowed) != 0) return false;
    pending_buttons_.store(kPendingBit | pressed, std::memory_order_release);
    return true;
}

bool SimBackend::set_hats(uint32_t pushed) noexcept {
    const uint32_t allowed = (uint32_t{1} << device_.profile().hat_count) - 1u;  // 0..4 hats
    if ((pushed & ~allowed) != 0) return false;
    pending_hats_.store(kPendingBit | pushed, std::memory_order_release);
    return true;
}

void SimBackend::actuate(const float force[kMaxAxes]) noexcept { std::copy(force, force + kMaxAxes, force_); }

}  // namespace feel::runtime
