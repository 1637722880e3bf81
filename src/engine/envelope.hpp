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

namespace feel::detail {

// The envelope level in [0, 10000] for a steady-state level `steady` (≥ 0) at wave time
// tau_us of a play lasting duration_us (kInfiniteUs for endless).
// Single precision (issue 14): levels are within ±10000, times stay integer µs.
[[nodiscard]] float envelope_level(const Envelope& env, float steady, int64_t tau_us,
                                   int64_t duration_us) noexcept;

// Applies the envelope to a signed value: sign(value) · envelope_level(|value|).
[[nodiscard]] float shape_by_envelope(const Envelope& env, float value, int64_t tau_us,
                                      int64_t duration_us) noexcept;

}  // namespace feel::detail
