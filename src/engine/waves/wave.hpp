// Temporal Waves (§4): forces that are predefined functions of time.
//
// Each wave type renders, for its wave time τ within one play, a force on each device
// axis before gains. The engine has already resolved the clock (start delay, iterations)
// and the direction; a wave only knows its own shape.
#pragma once

#include <cstdint>

#include "feel/effect.hpp"

namespace feel::detail {

struct WaveInput {
    const EffectParams* params = nullptr;
    const float* direction = nullptr;     // factors per device axis (direction.hpp)
    const int16_t* samples = nullptr;     // force_profile only
    int64_t tau_us = 0;                   // time into this play
};

// Adds the wave's force (±10000 units, before effect and device gain) into force[].
void render_wave(const WaveInput& in, double force[kMaxAxes]) noexcept;

// One scalar per wave family; the envelope is applied inside when the effect has one.
[[nodiscard]] double constant_wave(const EffectParams& p, int64_t tau_us) noexcept;
[[nodiscard]] double smart_pop_wave(const EffectParams& p, int64_t tau_us) noexcept;
[[nodiscard]] double periodic_wave(const EffectParams& p, int64_t tau_us) noexcept;
[[nodiscard]] double ramp_wave(const EffectParams& p, int64_t tau_us) noexcept;
// The compass angle of a sweep at τ, hundredths of a degree (may be fractional).
[[nodiscard]] double sweep_angle(const EffectParams& p, int64_t tau_us) noexcept;
// Adds a force profile's channels into force[].
void force_profile_wave(const EffectParams& p, const int16_t* samples, const float* direction,
                        int64_t tau_us, double force[kMaxAxes]) noexcept;

}  // namespace feel::detail
