// vector_force, constant (§6.6.c) and smart_pop.
#include "../envelope.hpp"
#include "../turn_trig.hpp"
#include "wave.hpp"

namespace feel::detail {

float constant_wave(const SlotParams& p, int64_t tau_us) noexcept {
    const float m = static_cast<float>(p.constant.magnitude);
    return shape_outside_steady(p, p.constant.steady, m, tau_us);
}

// The primer lists Smart Pop (§6.4.b) with a Constant Struct and no envelope but does not
// define its shape. feel renders it as one smooth pop: a half sine of the magnitude over the
// duration, M·sin(π·τ/duration), so it starts and ends at zero force and has no step to ring
// the mechanism. The validator requires a finite duration.
float smart_pop_wave(const SlotParams& p, int64_t tau_us) noexcept {
    const float progress = static_cast<float>(finite_tau(tau_us)) / static_cast<float>(p.duration_us);
    return static_cast<float>(p.constant.magnitude) * sin_turns(0.5f * progress);
}

}  // namespace feel::detail
