// Dispatch from an effect type to the wave that renders it.
#include "wave.hpp"

#include "../direction.hpp"

namespace feel::detail {
namespace {

// Over the device's axes only: the direction factors of the others are 0.
void add_along(const float* direction, int axes, float value, float force[kMaxAxes]) noexcept {
    for (int a = 0; a < axes; ++a) force[a] += direction[a] * value;
}

}  // namespace

void render_wave(const WaveInput& in, float force[kMaxAxes]) noexcept {
    const EffectParams& p = *in.params;
    switch (p.type) {
        case EffectType::vector_force:
        case EffectType::constant:
            add_along(in.direction, in.axes, constant_wave(p, in.tau_us), force);
            return;
        case EffectType::smart_pop:
            add_along(in.direction, in.axes, smart_pop_wave(p, in.tau_us), force);
            return;
        case EffectType::sine:
        case EffectType::square:
        case EffectType::triangle:
        case EffectType::saw_up:
        case EffectType::saw_down:
            add_along(in.direction, in.axes, periodic_wave(p, in.waveform, in.tau_us), force);
            return;
        case EffectType::sweep_sine:
        case EffectType::sweep_square:
        case EffectType::sweep_triangle:
        case EffectType::sweep_saw_up:
        case EffectType::sweep_saw_down: {
            float swept[kMaxAxes];
            polar_factors_turns(sweep_turns(p, in.tau_us), swept);
            add_along(swept, in.axes, periodic_wave(p, in.waveform, in.tau_us), force);
            return;
        }
        case EffectType::ramp:
            add_along(in.direction, in.axes, ramp_wave(p, in.tau_us), force);
            return;
        case EffectType::force_profile:
            force_profile_wave(p, in.samples, in.direction, in.tau_us, force);
            return;
        default:
            return;  // not a wave: the engine never routes other classes here
    }
}

}  // namespace feel::detail
