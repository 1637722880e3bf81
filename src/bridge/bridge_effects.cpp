#include "bridge_effects.hpp"

#include <cerrno>
#include <utility>

#include "evdev_units.hpp"
#include "ff_translation.hpp"

namespace feel::bridge {

int errno_of(const host::Status& status) noexcept {
    switch (status.kind) {
        case host::ErrorKind::ok: return 0;
        case host::ErrorKind::invalid_parameter:
        case host::ErrorKind::not_supported:
        case host::ErrorKind::invalid_handle: return -EINVAL;
        case host::ErrorKind::device_full: return -ENOSPC;
        case host::ErrorKind::disconnected: return -ENODEV;
        case host::ErrorKind::timeout:
        case host::ErrorKind::protocol: return -EIO;
    }
    return -EIO;
}

BridgeEffects::BridgeEffects(host::Device& device, Log log) : device_(device), log_(std::move(log)) {}

int BridgeEffects::fail(const std::string& what, const host::Status& status) {
    log_(what + ": " + status.message);
    return errno_of(status);
}

int BridgeEffects::upload(const ff_effect& effect) {
    const std::string name = "upload of effect " + std::to_string(effect.id);
    const Translation t = translate_effect(effect, device_.capabilities());
    if (t.error != 0) {
        log_(name + " refused: " + t.message);
        return t.error;
    }
    auto it = effects_.find(effect.id);
    if (it != effects_.end() && it->second.size() == t.effects.size()) {
        // A change of an effect the device holds: in place when its feel types stay (a
        // playing effect plays on with the new parameters, as evdev wants).
        bool same_types = true;
        for (std::size_t i = 0; i < t.effects.size(); ++i) same_types = same_types && it->second[i].type() == t.effects[i].type;
        if (same_types) {
            for (std::size_t i = 0; i < t.effects.size(); ++i) {
                const host::Status s = it->second[i].set_parameters(t.effects[i], effect_field::kAll, false);
                if (!s.ok()) return fail(name + " (a change) refused", s);
            }
            return 0;
        }
    }
    // New, or a change to other feel types (a saw turned upside down is the other saw):
    // the new effects are made first, so a refusal leaves the old ones as they were.
    std::vector<host::Effect> made;
    for (const EffectParams& p : t.effects) {
        host::Result<host::Effect> e = device_.create_effect(p);
        if (!e) return fail(name + " refused by the device", e.status());
        made.push_back(std::move(e.value()));
    }
    bool was_playing = false;
    if (it != effects_.end()) {
        for (host::Effect& old : it->second) {
            if (auto s = old.status(); s && s->state != runtime::ReportedEffectState::stopped) was_playing = true;
        }
    }
    effects_[effect.id] = std::move(made);  // frees the old ones, if any
    if (was_playing) {
        for (host::Effect& e : effects_[effect.id]) {
            if (const host::Status s = e.start(); !s.ok()) log_(name + ": restarting it failed: " + s.message);
        }
    }
    return 0;
}

int BridgeEffects::erase(int16_t id) {
    auto it = effects_.find(id);
    if (it == effects_.end()) {
        log_("erase of effect " + std::to_string(id) + " refused: the bridge holds no such effect");
        return -EINVAL;
    }
    int result = 0;
    for (host::Effect& e : it->second) {
        if (const host::Status s = e.unload(); !s.ok()) result = fail("erase of effect " + std::to_string(id), s);
    }
    effects_.erase(it);
    return result;
}

void BridgeEffects::play(uint16_t id, int32_t count) {
    auto it = effects_.find(static_cast<int16_t>(id));
    const std::string name = (count > 0 ? "play of effect " : "stop of effect ") + std::to_string(id);
    if (it == effects_.end()) {
        log_(name + " ignored: the bridge holds no such effect");
        return;
    }
    if (count > 254) log_(name + ": " + std::to_string(count) + " times is more than a device counts (1..254): until stopped");
    for (host::Effect& e : it->second) {
        const host::Status s = count > 0 ? e.start(iterations_of_count(count)) : e.stop();
        if (!s.ok()) log_(name + " failed: " + s.message);
    }
}

void BridgeEffects::set_gain(uint16_t gain) {
    if (const host::Status s = device_.set_gain(evdev_unsigned_level(gain)); !s.ok()) log_("gain failed: " + s.message);
}

void BridgeEffects::set_autocenter(uint16_t strength) {
    if (strength == 0) {
        autocenter_.reset();  // frees the spring
        return;
    }
    const EffectParams spring = autocenter_spring(strength, device_.capabilities());
    if (autocenter_) {
        if (const host::Status s = autocenter_->set_parameters(spring, effect_field::kTypeSpecific, false); !s.ok()) {
            log_("autocenter failed: " + s.message);
        }
        return;
    }
    host::Result<host::Effect> e = device_.create_effect(spring);
    if (!e) {
        log_("autocenter failed: " + e.status().message);
        return;
    }
    if (const host::Status s = e->start(); !s.ok()) {
        log_("autocenter failed: " + s.message);
        return;
    }
    autocenter_ = std::move(e.value());
}

std::vector<const host::Effect*> BridgeEffects::feel_effects(int16_t id) const {
    std::vector<const host::Effect*> out;
    if (auto it = effects_.find(id); it != effects_.end()) {
        for (const host::Effect& e : it->second) out.push_back(&e);
    }
    return out;
}

}  // namespace feel::bridge
