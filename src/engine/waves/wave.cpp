// Dispatch from an effect type to the wave that renders it.
#include "wave.hpp"

#include "../turn_trig.hpp"

namespace feel::detail {
namespace {

// Over the device's axes only: the direction factors of the others are 0.
void add_along(const float* direction, int axes, float value, float force[kMaxAxes]) noexcept {
    for (int a = 0; a < axes; ++a) force[a] += direction[a] * value;
}

}  // namespace

bool is_scalar_wave(const SlotParams& p) noexcept {
    if (is_sweep(p.type)) return false;
    if (p.type == EffectType::force_profile) return p.custom.channels == 1;
    return effect_class(p.type) == EffectClass::wave;
}

float scalar_wave_value(const WaveInput& in) noexcept {
    const SlotParams& p = *in.params;
    switch (p.type) {
        case EffectType::vector_force:
        case EffectType::constant: return constant_wave(p, in.tau_us);
        case EffectType::smart_pop: return smart_pop_wave(p, in.tau_us);
        case EffectType::ramp: return ramp_wave(p, in.tau_us);
        case EffectType::force_profile: return force_profile_value(p, in.samples, in.tau_us);
        default: return periodic_wave(p, in.waveform, in.tau_us);  // sine..saw_down
    }
}

void render_wave(const WaveInput& in, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *in.params;
    if (is_sweep(p.type)) {
        // polar_factors_turns's factors (−sin, −cos on x, y; 0 on the others) applied here
        // without forming them: the same products, so the same bits.
        static_assert(axis_index(Axis::x) == 0 && axis_index(Axis::y) == 1);
        const float turns = sweep_turns(p, in.tau_us);
        const float value = periodic_wave(p, in.waveform, in.tau_us);
        if (in.axes > 0) force[0] += -sin_turns(turns) * value;
        if (in.axes > 1) force[1] += -cos_turns(turns) * value;
        for (int a = 2; a < in.axes; ++a) force[a] += 0.0f * value;
        return;
    }
    if (p.type == EffectType::force_profile && p.custom.channels > 1) {
        force_profile_wave(p, in.samples, in.direction, in.tau_us, force);
        return;
    }
    if (effect_class(p.type) != EffectClass::wave) return;  // the engine never routes other classes here
    add_along(in.direction, in.axes, scalar_wave_value(in), force);
}

}  // namespace feel::detail
