// feel — the one validator of EffectParams.
//
// The file reader, the engine and the protocol decoder all call validate_effect(), so a
// value the engine would reject can never be written to a file, and vice versa. It checks
// every field of the effect's type against the ranges of units.hpp, and the rules that
// tie fields together (samples a multiple of channels, envelopes only on waves, ...).
// It does not know the device: Engine::create() adds the device checks (axes, memory).
#pragma once

#include <cstdint>
#include <span>

#include "feel/effect.hpp"
#include "feel/status.hpp"

namespace feel {

// Real-time safe: no allocation, no exceptions.
[[nodiscard]] Error validate_effect(const EffectParams& params,
                                    std::span<const int16_t> samples = {}) noexcept;

}  // namespace feel
