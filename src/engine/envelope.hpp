// The impulse envelope (§4.2.a): how a wave's magnitude is shaped over one play.
//
//   level
//   impulse_level ●
//                   ╲
//                    ●──────────────────────●     steady state S (the wave's magnitude)
//                                            ╲
//                                             ● fade_level
//   |<-  settle  ->|                 |<-fade->|
//   0 ─────────────────────────────────────────► τ (wave time, µs), ends at the duration
//
// During the settle time the level moves linearly from impulse_level to S; during the
// last fade_time of the duration it moves linearly from where it is to fade_level. If the
// two windows overlap, the fade starts from the settling level. An endless wave has no
// fade. S may itself vary with time (a ramp, a force profile): the envelope then shapes
// |value(τ)| and keeps its sign.
#pragma once

#include <cstdint>

#include "feel/effect.hpp"
#include "slot_params.hpp"

namespace feel::detail {

// A wave time that lies within a finite duration (at most 65e6 µs: range::kDurationUs) as
// 32 bits. A float of it is then one instruction on a Cortex-M4 where a float of an int64
// is a library call, and the same float: the integer is the same.
[[nodiscard]] constexpr int32_t finite_tau(int64_t tau_us) noexcept { return static_cast<int32_t>(tau_us); }

// The envelope level in [0, 10000] for a steady-state level `steady` (≥ 0) at wave time
// tau_us of a play lasting duration_us (kInfiniteUs for endless).
// Single precision (issue 14): levels are within ±10000, times stay integer µs. Inline, as
// the rest of this header: every wave with an envelope calls it every tick.
[[nodiscard]] inline float envelope_level(const SlotEnvelope& env, float steady, int64_t tau_us,
                                          int64_t duration_us) noexcept {
    float level = steady;
    if (env.settle_time_us > 0 && tau_us < env.settle_time_us) {
        // τ is below the settle time here, and after the fade's start below the duration.
        const float progress = static_cast<float>(finite_tau(tau_us)) / static_cast<float>(env.settle_time_us);
        const float impulse = static_cast<float>(env.impulse_level);
        level = impulse + (steady - impulse) * progress;
    }
    if (duration_us != kInfiniteUs && env.fade_time_us > 0) {
        const int64_t fade_start = duration_us - env.fade_time_us;
        if (tau_us > fade_start) {
            const float progress =
                static_cast<float>(finite_tau(tau_us - fade_start)) / static_cast<float>(env.fade_time_us);
            level = level + (static_cast<float>(env.fade_level) - level) * progress;
        }
    }
    return level;
}

// Applies the envelope to a signed value: sign(value) · envelope_level(|value|).
[[nodiscard]] inline float shape_by_envelope(const SlotEnvelope& env, float value, int64_t tau_us,
                                             int64_t duration_us) noexcept {
    if (value < 0) return -envelope_level(env, -value, tau_us, duration_us);
    return envelope_level(env, value, tau_us, duration_us);
}

// envelope_level's windows: the attack while τ < settle_time, the fade while τ > the duration
// − fade_time; between them (or with no envelope) it returns the level unchanged, and
// shape_by_envelope the value (−(−v) is v to the bit). The header's fields must be set.
[[nodiscard]] inline SteadyWindow steady_window(const SlotParams& s) noexcept {
    const SlotEnvelope& env = s.envelope;
    SteadyWindow w;
    w.from_us = s.has_envelope && env.settle_time_us > 0 ? env.settle_time_us : 0;
    w.until_us = s.has_envelope && s.duration_us != kInfiniteUs && env.fade_time_us > 0
                     ? s.duration_us - env.fade_time_us
                     : INT32_MAX;
    return w;
}

// A wave's value shaped by its envelope, if it has one: the value itself inside its steady
// window (worked out with the command), so the envelope is evaluated in the attack and
// fade only.
[[nodiscard]] inline float shape_outside_steady(const SlotParams& p, const SteadyWindow& steady, float value,
                                                int64_t tau_us) noexcept {
    if (steady.holds(tau_us) || !p.has_envelope) return value;
    return shape_by_envelope(p.envelope, value, tau_us, p.duration_us);
}

}  // namespace feel::detail
