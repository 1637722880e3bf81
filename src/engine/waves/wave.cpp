// Dispatch from an effect type to the wave that renders it.
#include "wave.hpp"

#include "../direction.hpp"
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
#if !defined(__OPTIMIZE_SIZE__)
        if (in.axes == 2) {
            // x86, the common device: polar_factors_turns's factors go straight into the
            // force, the products and sums add_along makes, without the call and the array
            // (on the board's build for size, that copy would be flash).
            const float turns = sweep_turns(p, in.tau_us);
            const float value = periodic_wave(p, in.waveform, in.tau_us);
            const float from_x = -sin_turns(turns);
            const float from_y = -cos_turns(turns);
            force[axis_index(Axis::x)] += from_x * value;
            force[axis_index(Axis::y)] += from_y * value;
            return;
        }
#endif
        float swept[kMaxAxes];
        polar_factors_turns(sweep_turns(p, in.tau_us), swept);
        add_along(swept, in.axes, periodic_wave(p, in.waveform, in.tau_us), force);
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
