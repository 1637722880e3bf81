// A time-sorted list of hand and button events, applied to a SimDevice as they fall due.
#include "feel/sim/input_schedule.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "feel/sim/sim_device.hpp"

namespace feel::sim {
namespace {

uint32_t all_buttons(int32_t count) noexcept {
    return count >= 32 ? 0xFFFFFFFFu : (uint32_t{1} << count) - 1u;
}

}  // namespace

uint32_t InputSchedule::buttons_after(uint32_t buttons, const Event& e) noexcept {
    switch (e.kind) {
    case Kind::press:
        return buttons | e.bits;
    case Kind::release:
        return buttons & ~e.bits;
    case Kind::set_buttons:
        return e.bits;
    case Kind::let_go:
    case Kind::grab:
    case Kind::push_hat:
    case Kind::center_hat:
        break;
    }
    return buttons;
}

uint32_t InputSchedule::hats_after(uint32_t hats, const Event& e) noexcept {
    if (e.kind == Kind::push_hat) return hats | e.bits;
    if (e.kind == Kind::center_hat) return hats & ~e.bits;
    return hats;
}

InputSchedule::InputSchedule(const DeviceProfile& profile)
    : button_count_(profile.button_count), hat_count_(profile.hat_count) {
    if (button_count_ < 0 || button_count_ > 32) {
        throw std::invalid_argument("input schedule: button_count = " +
                                    std::to_string(button_count_) +
                                    " is out of range (allowed 0..32)");
    }
    if (hat_count_ < 0 || hat_count_ > 4) {
        throw std::invalid_argument("input schedule: hat_count = " + std::to_string(hat_count_) +
                                    " is out of range (allowed 0..4)");
    }
}

InputSchedule& InputSchedule::add(Event event) {
    if (event.t_us < 0) {
        throw std::invalid_argument("input schedule: t_us = " + std::to_string(event.t_us) +
                                    " is out of range (allowed >= 0, µs)");
    }
    // After every event at the same time: same-time events keep the order they were added.
    const auto at = std::upper_bound(events_.begin(), events_.end(), event.t_us,
                                     [](int64_t t, const Event& e) { return t < e.t_us; });
    const auto index = static_cast<std::size_t>(at - events_.begin());
    if (index < next_) {
        throw std::invalid_argument("input schedule: t_us = " + std::to_string(event.t_us) +
                                    " is before events already applied (rewind() first)");
    }
    events_.insert(at, event);
    return *this;
}

uint32_t InputSchedule::button_bit(const char* what, int32_t button) const {
    if (button < 1 || button > button_count_) {
        throw std::invalid_argument(std::string("input schedule: ") + what + " button = " +
                                    std::to_string(button) + " is out of range (allowed 1.." +
                                    std::to_string(button_count_) + ", the device's buttons)");
    }
    return uint32_t{1} << (button - 1);
}

uint32_t InputSchedule::hat_bit(const char* what, int32_t hat) const {
    if (hat < 1 || hat > hat_count_) {
        throw std::invalid_argument(std::string("input schedule: ") + what + " hat = " +
                                    std::to_string(hat) + " is out of range (allowed 1.." +
                                    std::to_string(hat_count_) + ", the device's hat switches)");
    }
    return uint32_t{1} << (hat - 1);
}

InputSchedule& InputSchedule::push_hat(int64_t t_us, int32_t hat) {
    return add({t_us, Kind::push_hat, hat_bit("push_hat", hat)});
}

InputSchedule& InputSchedule::center_hat(int64_t t_us, int32_t hat) {
    return add({t_us, Kind::center_hat, hat_bit("center_hat", hat)});
}

InputSchedule& InputSchedule::let_go(int64_t t_us) { return add({t_us, Kind::let_go, 0}); }

InputSchedule& InputSchedule::grab(int64_t t_us) { return add({t_us, Kind::grab, 0}); }

InputSchedule& InputSchedule::press(int64_t t_us, int32_t button) {
    return add({t_us, Kind::press, button_bit("press", button)});
}

InputSchedule& InputSchedule::release(int64_t t_us, int32_t button) {
    return add({t_us, Kind::release, button_bit("release", button)});
}

InputSchedule& InputSchedule::set_buttons(int64_t t_us, uint32_t pressed) {
    if ((pressed & ~all_buttons(button_count_)) != 0) {
        throw std::invalid_argument("input schedule: set_buttons mask = " +
                                    std::to_string(pressed) +
                                    " names a button the device lacks (it has " +
                                    std::to_string(button_count_) +
                                    " buttons; bit i is button i+1)");
    }
    return add({t_us, Kind::set_buttons, pressed});
}

int32_t InputSchedule::apply(SimDevice& device, int64_t t_us) noexcept {
    int32_t applied = 0;
    while (next_ < events_.size() && events_[next_].t_us <= t_us) {
        const Event& e = events_[next_++];
        ++applied;
        switch (e.kind) {
        case Kind::let_go:
            device.set_hand_present(false);
            break;
        case Kind::grab:
            device.set_hand_present(true);
            break;
        case Kind::press:
        case Kind::release:
        case Kind::set_buttons:
            if (!device.set_buttons(buttons_after(device.buttons(), e))) ++rejected_;
            break;
        case Kind::push_hat:
        case Kind::center_hat:
            if (!device.set_hats(hats_after(device.hats(), e))) ++rejected_;
            break;
        }
    }
    return applied;
}

bool InputSchedule::hand_present_at(int64_t t_us) const noexcept {
    bool present = true;
    for (const Event& e : events_) {
        if (e.t_us > t_us) break;
        if (e.kind == Kind::let_go) present = false;
        if (e.kind == Kind::grab) present = true;
    }
    return present;
}

uint32_t InputSchedule::buttons_at(int64_t t_us) const noexcept {
    uint32_t buttons = 0;
    for (const Event& e : events_) {
        if (e.t_us > t_us) break;
        buttons = buttons_after(buttons, e);
    }
    return buttons;
}

uint32_t InputSchedule::hats_at(int64_t t_us) const noexcept {
    uint32_t hats = 0;
    for (const Event& e : events_) {
        if (e.t_us > t_us) break;
        hats = hats_after(hats, e);
    }
    return hats;
}

}  // namespace feel::sim
