// The command interface of the local processor (§2.2), beyond create/start/stop: starting
// with an iteration count and solo, partial updates, status, device control and the pool.
// The model is DirectInput's (IDirectInputEffect::Start/SetParameters/GetEffectStatus,
// SendForceFeedbackCommand with DISFFC_*), which the primer's devices implement.
//
// Every command here checks everything before it changes anything: a refused command
// leaves the engine exactly as it was. None allocates, locks or throws; all run in the
// loop thread between ticks (they arrive through the runtime's command queue).
//
// An update merges the masked fields into a copy of the effect's parameters and checks
// the copy as a whole, the way create() checks a new effect: validate_effect() for the
// ranges and the rules tying fields together, then the device's axes, then the parameter
// memory (an envelope added or a profile grown costs bytes). Only then is the copy stored.
// A playing effect keeps its clock unless it restarts: its time since it began is kept
// and re-read against the new duration, delay and iterations at the next tick, so a
// longer duration extends the play and a shorter one may end it at once.
#include "feel/engine.hpp"

#include "direction.hpp"
#include "engine_impl.hpp"
#include "feel/effect_validation.hpp"

namespace feel {

using detail::Slot;

namespace {

Error no_such_effect() noexcept { return Error::of(ErrorCode::invalid_handle, "", "no such effect"); }

// Copies the fields of `mask` from `from` into `to`.
void merge_fields(EffectParams& to, const EffectParams& from, uint32_t mask) noexcept {
    using namespace effect_field;
    if (mask & kDuration) to.duration_us = from.duration_us;
    if (mask & kStartDelay) to.start_delay_us = from.start_delay_us;
    if (mask & kGain) to.gain = from.gain;
    if (mask & kIterations) to.iterations = from.iterations;
    if (mask & kAxes) {
        to.axis_count = from.axis_count;
        for (int i = 0; i < kMaxAxes; ++i) to.axes[i] = from.axes[i];
    }
    if (mask & kDirection) to.direction = from.direction;
    if (mask & kTrigger) to.trigger = from.trigger;
    if (mask & kTriggerRepeat) to.trigger_repeat_interval_us = from.trigger_repeat_interval_us;
    if (mask & kEnvelope) {
        to.has_envelope = from.has_envelope;
        to.envelope = from.envelope;
    }
    if (mask & kTypeSpecific) {
        for (int i = 0; i < kMaxAxes; ++i) to.conditions[i] = from.conditions[i];
        to.periodic = from.periodic;
        to.constant = from.constant;
        to.ramp = from.ramp;
        to.custom = from.custom;
        to.texture = from.texture;
        to.wall = from.wall;
        to.barrier = from.barrier;
        to.dynamic = from.dynamic;
    }
}

Error check_device_axes(const EffectParams& p, int32_t device_axes) noexcept {
    for (int i = 0; i < p.axis_count; ++i) {
        if (axis_index(p.axes[i]) >= device_axes) {
            char field[16] = "axes[0]";
            field[5] = static_cast<char>('0' + i);
            return Error::invalid(field, "names an axis this device does not have");
        }
    }
    return {};
}

}  // namespace

Error detail::pool_full_error(int32_t needed, int32_t free_bytes) noexcept {
    Error e = Error::of(ErrorCode::device_full, "pool_bytes",
                        "not enough free parameter memory for the effect (value: the bytes it "
                        "needs; allowed.max: the bytes free; see Engine::pool())");
    e.value = needed;
    e.allowed = Range{0, free_bytes};
    return e;
}

Error Engine::start(EffectId id, int32_t iterations, bool solo) noexcept {
    Impl& m = *impl_;
    Slot* s = m.find(id);
    if (!s) return no_such_effect();
    if (iterations != kInfiniteIterations && !range::kIterations.contains(iterations)) {
        return Error::out_of_range("iterations", iterations, range::kIterations);
    }
    if (solo) {
        for (int32_t i = 0; i < m.slot_count; ++i) {
            if (i != id.index) Impl::stop_play(m.slots[i]);
        }
    }
    m.begin_play(*s, iterations);
    return {};
}

EffectStatus Engine::status(EffectId id) const noexcept {
    const Slot* s = impl_->find(id);
    EffectStatus st;
    if (!s) return st;
    st.state = s->state;
    st.iterations = s->play_iterations();
    st.completed_iterations = s->completed_iterations;
    st.elapsed_us = s->elapsed_us;
    st.starts = s->starts;
    st.last_end = s->last_end;
    return st;
}

Error Engine::params(EffectId id, EffectParams& out) const noexcept {
    const Slot* s = impl_->find(id);
    if (!s) return no_such_effect();
    out = detail::effect_params(s->params);
    return {};
}

Error Engine::update(EffectId id, const EffectParams& params, uint32_t field_mask, bool restart,
                     std::span<const int16_t> samples) noexcept {
    Impl& m = *impl_;
    Slot* s = m.find(id);
    if (!s) return no_such_effect();
    if ((field_mask & ~effect_field::kAll) != 0) {
        return Error::invalid("field_mask", "has bits that name no field (effect_field::k*)");
    }
    const bool type_specific = (field_mask & effect_field::kTypeSpecific) != 0;
    if (type_specific && params.type != s->params.type) {
        return Error::invalid("type", "an update cannot change an effect's type: destroy it and create one of the new type");
    }
    const bool is_profile = s->params.type == EffectType::force_profile;
    const bool new_samples = is_profile && type_specific;
    if (!new_samples && !samples.empty()) {
        return Error::invalid("custom.samples",
                              "samples come only with a force profile's type-specific block "
                              "(effect_field::kTypeSpecific)");
    }

    // The merged parameters are checked as a whole, with the samples they would play.
    EffectParams merged = detail::effect_params(s->params);
    merge_fields(merged, params, field_mask);
    const std::span<const int16_t> merged_samples =
        new_samples ? samples
        : is_profile ? std::span<const int16_t>(m.samples.data(id.index), static_cast<size_t>(s->params.custom.sample_count))
                     : std::span<const int16_t>();
    if (Error e = validate_effect(merged, merged_samples)) return e;
    if (Error e = check_device_axes(merged, m.config.axis_count)) return e;
    const int32_t bytes = effect_pool_bytes(merged);
    const int32_t held = detail::slot_pool_bytes(s->params);
    const int32_t free_after_release = m.pool_total_bytes - m.pool_used_bytes + held;
    if (bytes > free_after_release) return detail::pool_full_error(bytes, free_after_release);
    if (new_samples) {
        // The effect's own samples are released first, so the new ones fit if the free
        // memory plus the old ones holds them; the pool compacts rather than fail then.
        const int32_t count = static_cast<int32_t>(samples.size());
        if (count > m.samples.free_samples() + s->params.custom.sample_count) {
            return Error::of(ErrorCode::device_full, "custom.samples", "not enough free sample memory");
        }
        m.samples.release(id.index);
        m.samples.allocate(id.index, samples.data(), count);  // cannot fail: checked above
    }

    // Nothing can fail from here on.
    Impl::store_params(*s, merged);
    m.pool_used_bytes += bytes - held;
    m.prepare(*s);
    if (restart) m.begin_play(*s, 0);
    return {};
}

void Engine::pause() noexcept { impl_->paused = true; }
void Engine::resume() noexcept { impl_->paused = false; }
bool Engine::paused() const noexcept { return impl_->paused; }

void Engine::set_actuators_enabled(bool enabled) noexcept { impl_->actuators_enabled = enabled; }
bool Engine::actuators_enabled() const noexcept { return impl_->actuators_enabled; }

void Engine::reset() noexcept {
    Impl& m = *impl_;
    for (int32_t i = 0; i < m.slot_count; ++i) {
        Slot& s = m.slots[i];
        if (s.state != EffectState::free) m.free_slot(s, i);
    }
    m.device_gain = kFullScale;
    m.paused = false;
    m.actuators_enabled = true;
    // Queued dynamics reports name effects that no longer exist.
    m.report_head = 0;
    m.report_count = 0;
}

PoolInfo Engine::pool() const noexcept {
    const Impl& m = *impl_;
    PoolInfo p;
    p.total_bytes = m.pool_total_bytes;
    p.free_bytes = m.pool_total_bytes - m.pool_used_bytes;
    p.max_effects = m.slot_count;
    p.free_effects = 0;
    for (int32_t i = 0; i < m.slot_count; ++i) {
        if (m.slots[i].state == EffectState::free) ++p.free_effects;
    }
    p.max_dynamics = m.dynamic_pool.capacity();
    p.free_dynamics = m.dynamic_pool.free_count();
    p.max_stateful_conditions = m.condition_pool.capacity();
    p.free_stateful_conditions = m.condition_pool.free_count();
    p.total_samples = m.samples.capacity();
    p.free_samples = m.samples.free_samples();
    return p;
}

}  // namespace feel
