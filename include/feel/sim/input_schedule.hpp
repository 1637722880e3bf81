// feel::sim — a script of what the hand, the buttons and the hat switches do over time.
//
// The simulated device's hand can let go of the handle and grab it again, and its buttons
// and hat switches can be pressed (SimDevice::set_hand_present, set_buttons, set_hats). An
// InputSchedule
// lists such events at given times; the loop that steps the device applies the ones that
// are due before it reads the sensors:
//
//   schedule.apply(device, t_us);  in.t_us = t_us;  device.sense(in);  ...  device.step(...)
//
// so an event at t_us is seen by the tick at t_us. The schedule is built before the loop
// (building allocates); apply() never allocates, locks or throws.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "feel/sim/device_profile.hpp"

namespace feel::sim {

class SimDevice;

class InputSchedule {
public:
    // The schedule is for a device with this profile: press() and release() accept its
    // buttons, 1..button_count; push_hat() and center_hat() its hats, 1..hat_count.
    explicit InputSchedule(const DeviceProfile& profile);

    // Each adds one event at t_us (>= 0) and returns *this. Events may be added in any
    // order; events at the same time apply in the order they were added. They throw
    // std::invalid_argument naming the bad value and the allowed range for t_us < 0, a
    // button outside 1..button_count, or a button mask with bits beyond button_count.
    InputSchedule& let_go(int64_t t_us);
    InputSchedule& grab(int64_t t_us);
    InputSchedule& press(int64_t t_us, int32_t button);
    InputSchedule& release(int64_t t_us, int32_t button);
    InputSchedule& set_buttons(int64_t t_us, uint32_t pressed);  // bit i = button i+1
    // Pushes hat `hat` off center (any direction: reflexes trigger on "off center") or
    // lets it return. Throw for a hat outside 1..hat_count.
    InputSchedule& push_hat(int64_t t_us, int32_t hat);
    InputSchedule& center_hat(int64_t t_us, int32_t hat);

    // Applies to `device`, in time order, every event at or before t_us that has not been
    // applied yet, and returns how many it applied. An event the device refuses (a button
    // it lacks: the schedule was built for another profile) is skipped and counted in
    // rejected(). Never allocates.
    int32_t apply(SimDevice& device, int64_t t_us) noexcept;
    // Makes every event pending again, for a second run from t = 0.
    void rewind() noexcept { next_ = 0; }

    // What the script says at t_us, from a device that starts held with no button down:
    // the ground truth for tests, without a device.
    [[nodiscard]] bool hand_present_at(int64_t t_us) const noexcept;
    [[nodiscard]] uint32_t buttons_at(int64_t t_us) const noexcept;
    [[nodiscard]] uint32_t hats_at(int64_t t_us) const noexcept;  // bit h-1 = hat h

    [[nodiscard]] std::size_t size() const noexcept { return events_.size(); }
    [[nodiscard]] std::size_t pending() const noexcept { return events_.size() - next_; }
    [[nodiscard]] int64_t rejected() const noexcept { return rejected_; }

private:
    enum class Kind : uint8_t { let_go, grab, press, release, set_buttons, push_hat, center_hat };
    struct Event {
        int64_t t_us = 0;    // µs, >= 0
        Kind kind = Kind::grab;
        uint32_t bits = 0;   // press/release: the button's bit; set_buttons: the mask; hats: the hat's bit
    };
    InputSchedule& add(Event event);
    // The buttons after event e (unchanged by hand events).
    static uint32_t buttons_after(uint32_t buttons, const Event& e) noexcept;
    // The hats after event e (unchanged by other events).
    static uint32_t hats_after(uint32_t hats, const Event& e) noexcept;
    [[nodiscard]] uint32_t button_bit(const char* what, int32_t button) const;
    [[nodiscard]] uint32_t hat_bit(const char* what, int32_t hat) const;

    int32_t button_count_;      // 0..32
    int32_t hat_count_;         // 0..4
    std::vector<Event> events_;  // sorted by t_us, stable
    std::size_t next_ = 0;       // the first event not applied yet
    int64_t rejected_ = 0;
};

}  // namespace feel::sim
