// N two-axis conditions of one type on the joystick's damping and mass, for the friction
// benchmarks (bench_friction.cpp's timings, tick_instructions.cpp's instruction counts): the
// stop guard runs, and the presliding stiffness is the passivity bound's.
#pragma once

#include "feel/engine.hpp"

namespace feel::bench {

inline EngineConfig joystick_condition_config() {
    EngineConfig config;
    config.device_damping = 0.5f * 0.05f / 4.45f;  // the joystick's (sim/device_profiles.cpp)
    config.device_mass = 0.15f * 0.05f / 4.45f;
    return config;
}

// The i-th of the benchmark's conditions: coefficients 1000 + 250·i on x and y.
inline EffectParams condition_on_xy(EffectType type, int i) {
    EffectParams p;
    p.type = type;
    p.duration_us = kInfiniteUs;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    for (int a = 0; a < 2; ++a) {
        p.conditions[a].pos_coefficient = 1000 + 250 * i;
        p.conditions[a].neg_coefficient = 1000 + 250 * i;
    }
    return p;
}

// Creates and starts `count` conditions of `type`; false if one is refused.
inline bool load_conditions(Engine& engine, EffectType type, int count) {
    for (int i = 0; i < count; ++i) {
        const CreateResult r = engine.create(condition_on_xy(type, i));
        if (!r.error.ok() || !engine.start(r.id).ok()) return false;
    }
    return true;
}

}  // namespace feel::bench
