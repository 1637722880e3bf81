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
    device_.sense(in);
}

void SimBackend::actuate(const float force[kMaxAxes]) noexcept { std::copy(force, force + kMaxAxes, force_); }

}  // namespace feel::runtime
