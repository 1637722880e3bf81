// Custom force profiles (§4.3.a, §6.6.d): sampled forces, each held for one sample period.
//
// Samples are interleaved by channel: frame k holds samples[k·channels + c] for c in
// 0..channels-1. A profile shorter than the duration repeats from its first frame, as a
// DirectInput custom force does; an endless duration loops it forever. One channel plays
// along the effect's direction (or its single axis); several channels drive the effect's
// axes in order, each with its physical sign.
#include "../envelope.hpp"
#include "../time_division.hpp"
#include "wave.hpp"

namespace feel::detail {

namespace {

// The frame playing at τ.
const int16_t* frame_at(const SlotCustomBlock& c, const int16_t* samples, int64_t tau_us) noexcept {
    const int32_t frames = c.sample_count / c.channels;  // ≥ 1: the validator's sample count
    const int64_t played = time_quotient(tau_us, c.sample_period_us);  // frames since τ = 0
    const int64_t frame = played - time_quotient(played, frames) * frames;
    return samples + frame * c.channels;
}

float shaped(const SlotParams& p, float v, int64_t tau_us) noexcept {
    return shape_outside_steady(p, p.custom.steady, v, tau_us);
}

}  // namespace

float force_profile_value(const SlotParams& p, const int16_t* samples, int64_t tau_us) noexcept {
    return shaped(p, frame_at(p.custom, samples, tau_us)[0], tau_us);
}

void force_profile_wave(const SlotParams& p, const int16_t* samples, const float* direction,
                        int64_t tau_us, float force[kMaxAxes]) noexcept {
    const SlotCustomBlock& c = p.custom;
    if (c.channels == 1) {
        const float v = force_profile_value(p, samples, tau_us);
        for (int a = 0; a < kMaxAxes; ++a) force[a] += direction[a] * v;
        return;
    }
    const int16_t* row = frame_at(c, samples, tau_us);
    for (int ch = 0; ch < c.channels; ++ch) {
        force[axis_index(p.axes[ch])] += shaped(p, row[ch], tau_us);
    }
}

}  // namespace feel::detail
