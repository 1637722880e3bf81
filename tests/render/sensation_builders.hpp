// Small builders for sensations in tests, so that each test states only what it is about.
#pragma once

#include <string>
#include <utility>

#include "feel/format/sensation_file.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::render::testing {

inline format::Sensation single(std::string name, const EffectParams& params) {
    format::Sensation s;
    s.name = std::move(name);
    s.effects.push_back(format::EffectSpec{params, {}, {}});
    return s;
}

// A constant-source wave (vector_force or constant) on x and y from a polar direction.
inline EffectParams constant_wave(EffectType type, int32_t magnitude, int32_t gain,
                                  int32_t polar, int64_t duration_us) {
    EffectParams p;
    p.type = type;
    p.duration_us = duration_us;
    p.gain = gain;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = polar;
    p.constant.magnitude = magnitude;
    return p;
}

// A constant force on one axis with the physical sign of its magnitude (no direction).
inline EffectParams axis_constant(Axis axis, int32_t magnitude, int64_t duration_us) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = duration_us;
    p.axis_count = 1;
    p.axes[0] = axis;
    p.direction.kind = DirectionKind::none;
    p.constant.magnitude = magnitude;
    return p;
}

inline const sim::DeviceProfile& profile(const char* name) {
    const sim::DeviceProfile* p = sim::find_device_profile(name);
    if (p == nullptr) throw std::runtime_error(std::string("no device profile ") + name);
    return *p;
}

}  // namespace feel::render::testing
