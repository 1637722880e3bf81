// vector_force, constant (§6.6.c) and smart_pop.
#include <cmath>
#include <numbers>

#include "../envelope.hpp"
#include "wave.hpp"

namespace feel::detail {

double constant_wave(const EffectParams& p, int64_t tau_us) noexcept {
    const double m = p.constant.magnitude;
    return p.has_envelope ? shape_by_envelope(p.envelope, m, tau_us, p.duration_us) : m;
}

// The primer lists Smart Pop (§6.4.b) with a Constant Struct and no envelope but does not
// define its shape. feel renders it as one smooth pop: a half sine of the magnitude over the
// duration, M·sin(π·τ/duration), so it starts and ends at zero force and has no step to ring
// the mechanism. The validator requires a finite duration.
double smart_pop_wave(const EffectParams& p, int64_t tau_us) noexcept {
    const double progress = static_cast<double>(tau_us) / static_cast<double>(p.duration_us);
    return p.constant.magnitude * std::sin(std::numbers::pi * progress);
}

}  // namespace feel::detail
