// Temporal Waves (§4): forces that are predefined functions of time.
//
// Each wave type renders, for its wave time τ within one play, a force on each device
// axis before gains. The engine has already resolved the clock (start delay, iterations)
// and the direction; a wave only knows its own shape.
#pragma once

#include <cstdint>

#include "feel/effect.hpp"
#include "slot_params.hpp"
#include "feel/effect_type.hpp"

namespace feel::detail {

struct WaveInput {
    const SlotParams* params = nullptr;
    const float* direction = nullptr;     // factors per device axis (direction.hpp)
    const int16_t* samples = nullptr;     // force_profile only
    int64_t tau_us = 0;                   // time into this play
    Waveform waveform = Waveform::sine;   // periodic and sweep types: waveform_of(type), kept per slot
    int axes = kMaxAxes;                  // the device's axes: forces beyond them are 0 (kMaxAxes is 6)
};

// Adds the wave's force (±10000 units, before effect and device gain) into force[].
void render_wave(const WaveInput& in, float force[kMaxAxes]) noexcept;

// Most waves push along their fixed direction: force = value · direction. These two let the
// tick add value · (direction · gain), worked out once per command, instead. True for every
// wave type but the sweeps (their direction turns) and force profiles of several channels.
[[nodiscard]] bool is_scalar_wave(const SlotParams& p) noexcept;
// The value of such a wave (±10000 units, before gains).
[[nodiscard]] float scalar_wave_value(const WaveInput& in) noexcept;

// One scalar per wave family; the envelope is applied inside when the effect has one.
// Single precision (issue 14): forces are within ±10000, time is integer µs.
[[nodiscard]] float constant_wave(const SlotParams& p, int64_t tau_us) noexcept;
[[nodiscard]] float smart_pop_wave(const SlotParams& p, int64_t tau_us) noexcept;
[[nodiscard]] float periodic_wave(const SlotParams& p, Waveform waveform, int64_t tau_us) noexcept;
[[nodiscard]] float ramp_wave(const SlotParams& p, int64_t tau_us) noexcept;
// The compass direction of a sweep at τ, in turns clockwise from north (may be any value;
// direction.hpp's polar_factors_turns takes it).
[[nodiscard]] float sweep_turns(const SlotParams& p, int64_t tau_us) noexcept;
// A one-channel force profile's value at τ.
[[nodiscard]] float force_profile_value(const SlotParams& p, const int16_t* samples, int64_t tau_us) noexcept;
// Adds a force profile's channels into force[].
void force_profile_wave(const SlotParams& p, const int16_t* samples, const float* direction,
                        int64_t tau_us, float force[kMaxAxes]) noexcept;

}  // namespace feel::detail
