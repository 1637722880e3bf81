// feel::host::emulation — TriggerWatch: reflexes run by the host (§1.2.c).
//
// A reflex is an effect with a trigger: it starts when its button (or hat) is pressed and,
// with a repeat interval, again every interval while the button is held. A device runs them
// itself when it can (feel's runtime; a standard PID device that maps Set Effect's Trigger
// Button). When it cannot (an effect the host renders; a PID device whose descriptor has no
// Trigger Button, or a hat trigger, which PID cannot name), the host runs them on the buttons
// and hats each Input report carries: a press is an edge between two reports, so a reflex
// starts within one report period of the press (plus the link's trip down), and a repeat is
// due at press + k·interval, fired by the first report at or after it.
//
// Pure: no clock, no I/O, no lock (the owner locks). Target is what the owner starts: the
// host engine's EffectId, or a device block.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "feel/effect.hpp"

namespace feel::host::emulation {

// Whether trigger `t` is pressed in this reading (bit n-1 of buttons or hats).
[[nodiscard]] inline bool trigger_pressed(const Trigger& t, uint32_t buttons, uint32_t hats) noexcept {
    if (t.kind == TriggerKind::none || t.index < 1 || t.index > 32) return false;
    const uint32_t bits = t.kind == TriggerKind::hat ? hats : buttons;
    return ((bits >> (t.index - 1)) & 1u) != 0;
}

template <class Target>
class TriggerWatch {
public:
    // Arms (or re-arms) `key`'s trigger. A trigger already held when armed is not a press
    // (the device's rule). A trigger of kind none disarms.
    void arm(uint64_t key, Target target, const Trigger& trigger, int64_t repeat_us, uint32_t buttons,
             uint32_t hats) {
        if (trigger.kind == TriggerKind::none) {
            armed_.erase(key);
            return;
        }
        armed_[key] = Armed{target, trigger, repeat_us, trigger_pressed(trigger, buttons, hats), 0};
    }
    void disarm(uint64_t key) { armed_.erase(key); }
    void clear() noexcept { armed_.clear(); }
    [[nodiscard]] bool empty() const noexcept { return armed_.empty(); }
    [[nodiscard]] bool armed(uint64_t key) const noexcept { return armed_.count(key) != 0; }

    // One reading at host time t_us: appends the targets to start to `fire`.
    void update(int64_t t_us, uint32_t buttons, uint32_t hats, std::vector<Target>& fire) {
        for (auto& [key, a] : armed_) {
            const bool down = trigger_pressed(a.trigger, buttons, hats);
            if (down && !a.down) {
                fire.push_back(a.target);
                a.next_repeat_us = t_us + a.repeat_us;
            } else if (down && a.repeat_us > 0 && t_us >= a.next_repeat_us) {
                fire.push_back(a.target);
                a.next_repeat_us += a.repeat_us;
                if (a.next_repeat_us <= t_us) a.next_repeat_us = t_us + a.repeat_us;  // skip missed repeats
            }
            a.down = down;
        }
    }

private:
    struct Armed {
        Target target{};
        Trigger trigger{};
        int64_t repeat_us = 0;
        bool down = false;
        int64_t next_repeat_us = 0;
    };
    std::map<uint64_t, Armed> armed_;
};

}  // namespace feel::host::emulation
