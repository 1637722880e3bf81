// The bridge's effects: evdev's effect ids on one side, feel's Effects on the other.
//
// What a force-feedback driver does for the kernel, with the host API as its hardware:
// upload (create, or change an effect in place), erase, play with a count, stop, the
// device gain and autocenter. Each call answers 0 or a negative errno, which the uinput
// backend hands back to the kernel (and so to the game's ioctl), and logs one line for
// anything refused. Portable: the unit tests drive it on the in-process simulated device.
//
// evdev's effect id is the kernel's (ff-core picks it, 0..ff_effects_max-1); an FF_RUMBLE
// id holds two feel effects (ff_translation.hpp). FF_AUTOCENTER is a spring the bridge
// owns, created on the first non-zero strength, changed in place after, and freed at 0.
#pragma once

#include <linux/input.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "feel/host/device.hpp"

namespace feel::bridge {

class BridgeEffects {
public:
    using Log = std::function<void(const std::string&)>;
    BridgeEffects(host::Device& device, Log log);

    // UI_FF_UPLOAD: `effect` new (the kernel gave it its id) or a change of the effect with
    // that id. 0, or -EINVAL (the ff_effect is invalid or unsupported: logged, naming the
    // field), -ENOSPC (the device is full), -EIO (the device did not answer).
    [[nodiscard]] int upload(const ff_effect& effect);
    // UI_FF_ERASE: 0, or -EINVAL for an id the bridge does not hold.
    [[nodiscard]] int erase(int16_t id);
    // EV_FF on an effect id: count > 0 plays it count times (more than 254: until stopped),
    // 0 stops it. Errors are logged (an event has no reply).
    void play(uint16_t id, int32_t count);
    // EV_FF FF_GAIN, 0..0xFFFF.
    void set_gain(uint16_t gain);
    // EV_FF FF_AUTOCENTER, 0..0xFFFF (0: off).
    void set_autocenter(uint16_t strength);

    [[nodiscard]] std::size_t size() const noexcept { return effects_.size(); }
    // The feel effects behind an evdev id (empty if none): for tests and logs.
    [[nodiscard]] std::vector<const host::Effect*> feel_effects(int16_t id) const;

private:
    int fail(const std::string& what, const host::Status& status);
    host::Device& device_;
    Log log_;
    std::map<int16_t, std::vector<host::Effect>> effects_;
    std::optional<host::Effect> autocenter_;
};

// The negative errno a host Status becomes in the kernel's reply.
[[nodiscard]] int errno_of(const host::Status& status) noexcept;

}  // namespace feel::bridge
