// Custom force profiles (§4.3.a, §6.6.d): sampled forces, each held for one sample period.
//
// Samples are interleaved by channel: frame k holds samples[k·channels + c] for c in
// 0..channels-1. A profile shorter than the duration repeats from its first frame, as a
// DirectInput custom force does; an endless duration loops it forever. One channel plays
// along the effect's direction (or its single axis); several channels drive the effect's
// axes in order, each with its physical sign.
#include "../envelope.hpp"
#include "wave.hpp"

namespace feel::detail {

void force_profile_wave(const EffectParams& p, const int16_t* samples, const float* direction,
                        int64_t tau_us, float force[kMaxAxes]) noexcept {
    const CustomBlock& c = p.custom;
    const int64_t frames = c.sample_count / c.channels;
    const int64_t frame = (tau_us / c.sample_period_us) % frames;
    const int16_t* row = samples + frame * c.channels;
    auto shaped = [&](float v) {
        return p.has_envelope ? shape_by_envelope(p.envelope, v, tau_us, p.duration_us) : v;
    };
    if (c.channels == 1) {
        const float v = shaped(row[0]);
        for (int a = 0; a < kMaxAxes; ++a) force[a] += direction[a] * v;
        return;
    }
    for (int ch = 0; ch < c.channels; ++ch) {
        force[axis_index(p.axes[ch])] += shaped(row[ch]);
    }
}

}  // namespace feel::detail
