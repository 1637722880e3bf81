// feel::runtime — reflexes: effects the device starts by itself on a button press (§1.2.c).
//
// The primer's knee jerk: rather than send every trigger pull up to the host and wait for
// it to command a recoil back, the local processor keeps a table that ties local controls
// to effects and starts them itself (§1.2.c, §2.2 "Local Triggers"). DirectInput sets one
// up with an effect's Trigger Button and Trigger Repeat Interval (§6.3); assign_from()
// turns those fields into a reflex.
//
// Each tick the table looks at the buttons and hat switches the loop just read:
//  - a press edge (released at the previous tick, pressed now) starts the reflex's effect
//    from its beginning, restarting it if it plays: one start per observed press. At the
//    loop's 1 kHz every press longer than a millisecond is seen, however fast the presses
//    come; a host relaying them at its ~100 Hz game loop (§2.2) would miss short ones.
//  - while it stays held, the effect restarts every repeat interval (an automatic weapon):
//    at press + k·interval, k = 1, 2, ..., each at the first tick at or after that time.
//    A tick that comes more than an interval late restarts once and skips the missed
//    repeats (the effect would only restart over itself). Interval 0 never repeats.
//  - release ends the repeats; the effect itself plays on to its end, as a recoil must.
// Inputs: TickInput::buttons bit i = button i+1; TickInput::hats bit h-1 = hat switch h
// pushed off center (any direction). A button already held when the table first ticks, or
// when its reflex is assigned, is not a press: the reflex waits for the next one.
//
// While the engine is paused (Engine::pause) presses are ignored and the repeat schedule
// of a held button stands still, like the effects' own clocks: a reflex never queues a
// start that would fire when play resumes. A reflex whose effect has been freed (its
// handle went stale) removes itself at its next press and is counted in dropped_stale().
//
// Capacity is fixed at construction; nothing allocates afterwards. The table belongs to
// the loop thread: assign/remove arrive through the command queue between ticks. Every
// method is noexcept and lock-free; on_tick() costs O(reflexes) and is real-time safe;
// assign/remove/assign_from cost O(capacity), assign_all O(capacity + n²) for n effects.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/status.hpp"

namespace feel::runtime {

// One resident reflex.
struct Reflex {
    EffectId effect{};
    Trigger trigger{};               // button 1..32 or hat 1..4 (kind none is refused)
    int64_t repeat_interval_us = 0;  // 0 = no repeat, else 1..65e6 µs
};

class ReflexTable {
public:
    static constexpr int32_t kDefaultCapacity = 64;
    static constexpr Range kCapacity{1, 65535};

    // A capacity outside kCapacity makes a table that refuses every assign with
    // config_error().
    explicit ReflexTable(int32_t capacity = kDefaultCapacity);
    ~ReflexTable();
    ReflexTable(const ReflexTable&) = delete;
    ReflexTable& operator=(const ReflexTable&) = delete;

    [[nodiscard]] const Error& config_error() const noexcept { return config_error_; }

    // Ties `effect` to `trigger`. An effect has at most one reflex: assigning it again
    // replaces its trigger and interval. The reflex fires at the next press edge. Errors:
    // invalid_handle for an invalid id, invalid_parameter for a bad trigger or interval
    // (field "trigger_button" or "trigger_repeat_interval_us", as validate_effect names
    // them), device_full when every reflex is in use. An error changes nothing.
    Error assign(EffectId effect, Trigger trigger, int64_t repeat_interval_us) noexcept;
    // From the effect's own Trigger Button and Trigger Repeat Interval (§6.3): a reflex if
    // it has a trigger, none (any old reflex removed) if it has not.
    Error assign_from(const Engine& engine, EffectId effect) noexcept;
    // assign_from() for each effect, e.g. every effect of a sensation file just created:
    // its trigger_button fields become reflexes. All or nothing: a stale id or too little
    // room changes nothing.
    Error assign_all(const Engine& engine, std::span<const EffectId> effects) noexcept;
    // invalid_handle if the effect has no reflex.
    Error remove(EffectId effect) noexcept;
    void clear() noexcept;

    // The reflex of an effect, or nullptr.
    [[nodiscard]] const Reflex* find(EffectId effect) const noexcept;
    [[nodiscard]] int32_t size() const noexcept { return size_; }
    [[nodiscard]] int32_t capacity() const noexcept { return capacity_; }

    // Call once per loop tick, after reading the controls and before engine.tick(), so a
    // press starts its effect in the same tick (no added latency).
    void on_tick(int64_t t_us, uint32_t buttons, uint32_t hats, Engine& engine) noexcept;
    void on_tick(const TickInput& in, Engine& engine) noexcept { on_tick(in.t_us, in.buttons, in.hats, engine); }

    [[nodiscard]] uint64_t fired() const noexcept { return fired_; }                  // starts made
    [[nodiscard]] uint64_t dropped_stale() const noexcept { return dropped_stale_; }  // see above

private:
    struct Entry {
        Reflex reflex{};
        bool held = false;           // pressed since an observed press edge
        int64_t next_repeat_us = 0;  // when the next repeat is due, while held
    };

    [[nodiscard]] int32_t index_of(EffectId effect) const noexcept;
    void remove_at(int32_t index) noexcept;
    // Starts the effect of entry `index`; false when the effect was gone and the entry removed.
    bool fire(int32_t index, Engine& engine) noexcept;

    Error config_error_{};
    int32_t capacity_ = 0;
    int32_t size_ = 0;
    std::unique_ptr<Entry[]> entries_;
    bool have_previous_ = false;
    int64_t previous_t_us_ = 0;
    uint32_t previous_buttons_ = 0;
    uint32_t previous_hats_ = 0;
    uint64_t fired_ = 0;
    uint64_t dropped_stale_ = 0;
};

}  // namespace feel::runtime
