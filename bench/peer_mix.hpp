// The 40-effect mix of issue 14, the one OpenFFBoard's EffectsCalculator was measured
// against: on 2 axes, 10 periodics with envelopes, 10 springs, 10 dampers, 5 frictions,
// 3 ramps and 2 constants, with the handle moving in a slow circle.
//
// Used by bench/bench_tick.cpp (the cost of a tick on this machine) and by the firmware
// test program (firmware/, the instructions of a tick on the emulated Cortex-M4). Header
// only, no exceptions and no heap, so the bare-metal build can include it.
#pragma once

#include <cmath>
#include <cstdint>

#include "feel/engine.hpp"

namespace feel::bench {

inline constexpr int kPeerMixEffects = 40;

// Effect i (0..39) of the mix. Every effect acts on x and y; the waves through a polar
// direction, the conditions with one block per axis.
inline EffectParams peer_mix_effect(int i) {
    EffectParams p;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.duration_us = kInfiniteUs;
    if (i < 10) {  // periodics with envelopes: sine, square, triangle, saw up, saw down
        constexpr EffectType kWaves[] = {EffectType::sine, EffectType::square, EffectType::triangle,
                                         EffectType::saw_up, EffectType::saw_down};
        p.type = kWaves[i % 5];
        p.duration_us = 2'000'000;
        p.iterations = kInfiniteIterations;
        p.direction.kind = DirectionKind::polar;
        p.direction.value[0] = (i * 3600) % 36000;
        p.periodic = {400 + 50 * i, 20 * i, 10'000 + 3'000 * i, (i * 1500) % 36000, 0, 0, SweepSense::clockwise};
        p.has_envelope = true;
        p.envelope = {1000, 200'000, 200, 300'000};
        return p;
    }
    if (i < 35) {  // 10 springs, 10 dampers, 5 frictions
        p.type = i < 20 ? EffectType::spring : i < 30 ? EffectType::damper : EffectType::friction;
        const int k = i % 10;
        for (int a = 0; a < 2; ++a) {
            p.conditions[a] = {500 + 300 * k, 400 + 300 * k, (k - 5) * 200 * (a == 0 ? 1 : -1), 8000, 7000, 50 * k,
                               OffsetMode::absolute};
        }
        if (p.type == EffectType::friction) {
            for (int a = 0; a < 2; ++a) p.conditions[a].offset = 0;
        }
        return p;
    }
    if (i < 38) {  // ramps
        p.type = EffectType::ramp;
        p.duration_us = 3'000'000;
        p.iterations = kInfiniteIterations;
        p.direction.kind = DirectionKind::polar;
        p.direction.value[0] = 9000 + 4000 * (i - 35);
        p.ramp = {-1500 + 500 * (i - 35), 1500};
        return p;
    }
    p.type = EffectType::constant;  // constants
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = 27000 + 5000 * (i - 38);
    p.constant.magnitude = 700 - 300 * (i - 38);
    return p;
}

// Creates and starts the whole mix; false if the engine refused any effect.
inline bool load_peer_mix(Engine& engine) {
    for (int i = 0; i < kPeerMixEffects; ++i) {
        const CreateResult r = engine.create(peer_mix_effect(i), {});
        if (!r.error.ok() || !engine.start(r.id).ok()) return false;
    }
    return true;
}

// The handle of tick n at 1 kHz: a slow circle (radius 6000 units, one turn in 2 s),
// quantized to 4096 counts like the joystick's sensor.
inline void move_handle_in_slow_circle(TickInput& in, int64_t n) {
    constexpr double kTwoPi = 2 * 3.141592653589793;
    const double t = static_cast<double>(n) * 1e-3;
    const double step = 20000.0 / 4096.0;
    in.t_us = n * 1000;
    in.position[0] = static_cast<float>(std::round(6000 * std::cos(kTwoPi * 0.5 * t) / step) * step);
    in.position[1] = static_cast<float>(std::round(6000 * std::sin(kTwoPi * 0.5 * t) / step) * step);
}

}  // namespace feel::bench
