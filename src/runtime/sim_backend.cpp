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
    if (const uint64_t g = pending_grip_.exchange(0, std::memory_order_acquire); g & kPendingBit) {
        device_.set_grip(static_cast<sim::Grip>(g & 0xFF));
    }
    if (const uint64_t t = pending_target_.exchange(0, std::memory_order_acquire); t & kTargetPendingBit) {
        if (t & kTargetClearBit) {
            device_.clear_live_target();
        } else {
            double target[3] = {};
            for (int a = 0; a < 3; ++a) target[a] = static_cast<int16_t>((t >> (16 * a)) & 0xFFFF);
            (void)device_.set_live_target(target, std::min(3, device_.profile().axis_count));
        }
        target_taken_us_.store(t_us, std::memory_order_release);
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

bool SimBackend::set_hand_target(int32_t x, int32_t y, int32_t z) noexcept {
    uint64_t packed = kTargetPendingBit;
    int shift = 0;
    for (int32_t v : {x, y, z}) {
        if (v < -kFullScale || v > kFullScale) return false;
        packed |= uint64_t{static_cast<uint16_t>(static_cast<int16_t>(v))} << shift;
        shift += 16;
    }
    pending_target_.store(packed, std::memory_order_release);
    return true;
}

void SimBackend::set_grip(sim::Grip grip) noexcept {
    pending_grip_.store(kPendingBit | static_cast<uint64_t>(grip), std::memory_order_release);
}

void SimBackend::clear_hand_target() noexcept {
    pending_target_.store(kTargetPendingBit | kTargetClearBit, std::memory_order_release);
}

bool SimBackend::set_hats(uint32_t pushed) noexcept {
    const uint32_t allowed = (uint32_t{1} << device_.profile().hat_count) - 1u;  // 0..4 hats
    if ((pushed & ~allowed) != 0) return false;
    pending_hats_.store(kPendingBit | pushed, std::memory_order_release);
    return true;
}

void SimBackend::actuate(const float force[kMaxAxes]) noexcept { std::copy(force, force + kMaxAxes, force_); }

}  // namespace feel::runtime
