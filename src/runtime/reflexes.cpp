// Reflexes (§1.2.c): the table of triggers and the per-tick edge detector. The header
// states the rules; this file keeps them in O(reflexes) per tick without allocating.
#include "feel/runtime/reflexes.hpp"

namespace feel::runtime {

namespace {

bool pressed(const Trigger& t, uint32_t buttons, uint32_t hats) noexcept {
    const uint32_t bits = t.kind == TriggerKind::hat ? hats : buttons;
    return t.kind != TriggerKind::none && ((bits >> (t.index - 1)) & 1u) != 0;
}

Error check_reflex(EffectId effect, Trigger trigger, int64_t repeat_interval_us) noexcept {
    if (!effect.valid()) return Error::of(ErrorCode::invalid_handle, "effect", "no such effect");
    switch (trigger.kind) {
        case TriggerKind::button:
            if (!range::kTriggerButton.contains(trigger.index)) {
                return Error::out_of_range("trigger_button", trigger.index, range::kTriggerButton);
            }
            break;
        case TriggerKind::hat:
            if (!range::kTriggerHat.contains(trigger.index)) {
                return Error::out_of_range("trigger_button", trigger.index, range::kTriggerHat);
            }
            break;
        default:
            return Error::invalid("trigger_button", "a reflex needs a trigger: a button (1..32) or a hat switch (1..4)");
    }
    if (!range::kRepeatIntervalUs.contains(repeat_interval_us)) {
        return Error::out_of_range("trigger_repeat_interval_us", repeat_interval_us, range::kRepeatIntervalUs);
    }
    return {};
}

}  // namespace

ReflexTable::ReflexTable(int32_t capacity)
    : config_error_(kCapacity.contains(capacity) ? Error{} : Error::out_of_range("capacity", capacity, kCapacity)),
      capacity_(config_error_ ? 0 : capacity),
      entries_(new Entry[static_cast<size_t>(capacity_ > 0 ? capacity_ : 1)]) {}

ReflexTable::~ReflexTable() = default;

int32_t ReflexTable::index_of(EffectId effect) const noexcept {
    for (int32_t i = 0; i < size_; ++i) {
        if (entries_[i].reflex.effect == effect) return i;
    }
    return -1;
}

const Reflex* ReflexTable::find(EffectId effect) const noexcept {
    const int32_t i = index_of(effect);
    return i < 0 ? nullptr : &entries_[i].reflex;
}

void ReflexTable::remove_at(int32_t index) noexcept {
    // The order of reflexes means nothing, so the last one fills the hole.
    entries_[index] = entries_[size_ - 1];
    --size_;
}

Error ReflexTable::assign(EffectId effect, Trigger trigger, int64_t repeat_interval_us) noexcept {
    if (config_error_) return config_error_;
    if (Error e = check_reflex(effect, trigger, repeat_interval_us)) return e;
    int32_t i = index_of(effect);
    if (i < 0) {
        if (size_ == capacity_) {
            return Error::of(ErrorCode::device_full, "reflexes", "every reflex of the table is in use");
        }
        i = size_++;
    }
    entries_[i] = Entry{Reflex{effect, trigger, repeat_interval_us}, false, 0};
    return {};
}

Error ReflexTable::assign_from(const Engine& engine, EffectId effect) noexcept {
    if (config_error_) return config_error_;
    EffectParams p;
    if (Error e = engine.params(effect, p)) return e;
    if (p.trigger.kind == TriggerKind::none) {
        const int32_t i = index_of(effect);
        if (i >= 0) remove_at(i);
        return {};
    }
    return assign(effect, p.trigger, p.trigger_repeat_interval_us);
}

Error ReflexTable::assign_all(const Engine& engine, std::span<const EffectId> effects) noexcept {
    if (config_error_) return config_error_;
    // First pass: every effect exists and the table ends up no larger than its capacity.
    int64_t final_size = size_;
    EffectParams p;
    for (size_t k = 0; k < effects.size(); ++k) {
        if (Error e = engine.params(effects[k], p)) return e;
        bool repeated = false;
        for (size_t j = 0; j < k && !repeated; ++j) repeated = effects[j] == effects[k];
        if (repeated) continue;
        const bool present = index_of(effects[k]) >= 0;
        const bool triggered = p.trigger.kind != TriggerKind::none;
        if (triggered && !present) ++final_size;
        if (!triggered && present) --final_size;
    }
    if (final_size > capacity_) {
        return Error::of(ErrorCode::device_full, "reflexes", "the table has too few free reflexes for these effects");
    }
    // Second pass cannot fail: the effects exist and their params passed validate_effect,
    // whose trigger rules are the reflex's.
    for (const EffectId id : effects) {
        if (Error e = assign_from(engine, id)) return e;
    }
    return {};
}

Error ReflexTable::remove(EffectId effect) noexcept {
    const int32_t i = index_of(effect);
    if (i < 0) return Error::of(ErrorCode::invalid_handle, "effect", "the effect has no reflex");
    remove_at(i);
    return {};
}

void ReflexTable::clear() noexcept { size_ = 0; }

bool ReflexTable::fire(int32_t index, Engine& engine) noexcept {
    const Error e = engine.start(entries_[index].reflex.effect);
    if (e.code == ErrorCode::invalid_handle) {
        // Its effect was freed; the handle can never become valid again.
        remove_at(index);
        ++dropped_stale_;
        return false;
    }
    ++fired_;
    return true;
}

void ReflexTable::on_tick(int64_t t_us, uint32_t buttons, uint32_t hats, Engine& engine) noexcept {
    if (!have_previous_) {
        // The first look at the controls: whatever is held already was pressed before.
        have_previous_ = true;
    } else {
        const bool paused = engine.paused();
        const int64_t dt_us = t_us - previous_t_us_;
        int32_t i = 0;
        while (i < size_) {
            Entry& e = entries_[i];
            const Trigger& trigger = e.reflex.trigger;
            const bool down = pressed(trigger, buttons, hats);
            const bool was_down = pressed(trigger, previous_buttons_, previous_hats_);
            const int64_t interval = e.reflex.repeat_interval_us;
            if (!down) {
                e.held = false;
            } else if (!was_down) {
                // A press edge. Ignored while paused: the start would wait for resume.
                e.held = !paused;
                if (e.held) {
                    e.next_repeat_us = t_us + interval;
                    if (!fire(i, engine)) continue;  // entry i now holds another reflex
                }
            } else if (e.held && interval > 0) {
                if (paused) {
                    e.next_repeat_us += dt_us;  // the schedule stands still with the clocks
                } else if (t_us >= e.next_repeat_us) {
                    e.next_repeat_us += interval;
                    if (e.next_repeat_us <= t_us) e.next_repeat_us = t_us + interval;
                    if (!fire(i, engine)) continue;
                }
            }
            ++i;
        }
    }
    previous_t_us_ = t_us;
    previous_buttons_ = buttons;
    previous_hats_ = hats;
}

}  // namespace feel::runtime
