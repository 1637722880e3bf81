// Engine::activity(): what the last tick played, for Intelligent Disturbance Filtering.
//
// The tick keeps no per-effect force, and it must not pay for a query few devices make, so
// this file re-renders each playing wave at the last tick's time. Waves are pure functions
// of their params and their wave time τ (waves/, effect_clock.hpp), so the force found here
// is the force the tick summed, to the rounding of the gain products. Conditions are not listed: their force answers
// the handle's motion, so to a filter they are part of the mechanism it identifies.
// Dynamics are not listed either: their force comes out of a simulated mass whose state the
// tick has already advanced, and cannot be recomputed afterwards.
//
// The class of a wave follows the primer's two disturbances (§1.2.d): vibrations are
// periodic (periodic and sweep waves, force profiles that loop), jolts are impulses (short
// one-shot pushes: constant, vector force, smart pop, ramp, a one-shot profile). A push
// longer than kImpulseMaxUs is a steady force the player is meant to fight: `other`.
#include "feel/engine.hpp"

#include "effect_clock.hpp"
#include "engine_impl.hpp"
#include "waves/wave.hpp"

namespace feel {
namespace {

struct Classification {
    DisturbanceClass kind = DisturbanceClass::other;
    int64_t period_us = 0;
};

// One play of a push that lasts at most kImpulseMaxUs is a jolt.
Classification by_duration(int64_t duration_us) noexcept {
    const bool short_play = duration_us != kInfiniteUs && duration_us <= kImpulseMaxUs;
    return {short_play ? DisturbanceClass::impulse : DisturbanceClass::other, 0};
}

// A force profile loops when its duration outlasts the samples (they repeat from the first
// frame) or when it plays several iterations; its period is the length of one loop.
Classification classify_profile(const detail::SlotParams& p) noexcept {
    const detail::SlotCustomBlock& c = p.custom;
    const int64_t loop_us = static_cast<int64_t>(c.sample_count / c.channels) * c.sample_period_us;
    if (p.duration_us == kInfiniteUs || p.duration_us > loop_us) {
        return {DisturbanceClass::periodic, loop_us};
    }
    if (p.iterations != 1) return {DisturbanceClass::periodic, p.duration_us};
    return by_duration(p.duration_us);
}

Classification classify(const detail::SlotParams& p) noexcept {
    if (is_periodic(p.type) || is_sweep(p.type)) {
        return {DisturbanceClass::periodic, p.periodic.period_us};
    }
    if (p.type == EffectType::force_profile) return classify_profile(p);
    return by_duration(p.duration_us);
}

}  // namespace

void Engine::activity(EngineActivity& out) const noexcept {
    const Impl& m = *impl_;
    out.t_us = m.have_previous ? m.previous_t_us : 0;
    out.count = 0;
    out.omitted = 0;
    for (auto& per_class : out.class_force) {
        for (float& f : per_class) f = 0.0f;
    }
    // Paused or with the actuators off, the tick put no force on the handle.
    if (!m.have_previous || m.config_invalid || m.paused || !m.actuators_enabled) return;

    const int axes = m.config.axis_count;
    constexpr float kPerFullScale = 1.0f / static_cast<float>(kFullScale);
    const float device_gain = static_cast<float>(m.device_gain) * kPerFullScale;
    for (int32_t i = 0; i < m.slot_count; ++i) {
        const detail::Slot& s = m.slots[i];
        // `playing` is what the last tick found: the effect put force on the handle then.
        if (s.state != EffectState::playing) continue;
        if (effect_class(s.params.type) != EffectClass::wave) continue;
        const detail::ClockReading clock =
            detail::read_clock(s.params, s.play_iterations(), s.elapsed_us, s.completed_iterations);
        if (clock.phase != detail::ClockPhase::playing) continue;

        float force[kMaxAxes] = {};
        const detail::WaveInput wave{&s.params, s.direction,
                                     s.params.type == EffectType::force_profile ? m.samples.data(i) : nullptr,
                                     clock.tau_us, s.waveform, axes};
        detail::render_wave(wave, force);
        const float effect_gain = s.gain_factor;

        const Classification c = classify(s.params);
        float* class_sum = out.class_force[static_cast<int>(c.kind)];
        EffectActivity* entry = nullptr;
        if (out.count < kMaxActivityEffects) {
            entry = &out.effects[out.count++];
            entry->id = EffectId{static_cast<uint16_t>(i), s.generation};
            entry->type = s.params.type;
            entry->kind = c.kind;
            entry->period_us = c.period_us;
        } else {
            ++out.omitted;
        }
        for (int a = 0; a < kMaxAxes; ++a) {
            const float f = a < axes ? force[a] * effect_gain * device_gain : 0.0f;
            const float value = std::isfinite(f) ? f : 0.0f;
            class_sum[a] += value;
            if (entry) entry->force[a] = value;
        }
    }
}

}  // namespace feel
