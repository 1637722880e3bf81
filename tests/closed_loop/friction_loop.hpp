// A closed loop of the engine and the simulated device, tick by tick as feel::render runs
// it (sense, engine tick, motors push for one tick), recording what the friction and
// damper tests look at.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::test {

struct LoopRow {
    double t_s = 0;
    double x[kMaxAxes] = {};        // true handle position, normalized
    double v[kMaxAxes] = {};        // true handle velocity, units/s
    double sensed[kMaxAxes] = {};   // what the engine saw
    double force[kMaxAxes] = {};    // what the engine commanded
};

// Runs `effects` on `profile_name` held by `grip` following `motion` for duration_s at
// rate_hz. set_velocity, if nonzero, is the handle's velocity on x at the start. With
// mass_known false the engine is told no device_mass, as a device that does not say it.
inline std::vector<LoopRow> run_loop(const char* profile_name, sim::Grip grip, const std::string& motion,
                                     std::initializer_list<EffectParams> effects, double duration_s,
                                     double rate_hz = 1000, double set_velocity = 0, bool mass_known = true) {
    const sim::DeviceProfile& profile = *sim::find_device_profile(profile_name);
    sim::SimDevice device(profile, grip, sim::TargetMotion::parse(motion, duration_s, profile.axis_count));
    if (set_velocity != 0) device.set_velocity(0, set_velocity);
    EngineConfig config = sim::engine_config_for(profile);
    if (!mass_known) config.device_mass = 0.0f;
    Engine engine(config);
    for (const EffectParams& p : effects) {
        const CreateResult r = engine.create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(engine.start(r.id).ok());
    }
    const int64_t rate = static_cast<int64_t>(rate_hz);
    const int64_t ticks = static_cast<int64_t>(std::llround(duration_s * rate_hz));
    std::vector<LoopRow> rows(static_cast<size_t>(ticks));
    for (int64_t n = 0; n < ticks; ++n) {
        TickInput in;
        in.t_us = (n * 1'000'000 + rate / 2) / rate;
        device.sense(in);
        TickOutput out;
        engine.tick(in, out);
        LoopRow& row = rows[static_cast<size_t>(n)];
        row.t_s = static_cast<double>(in.t_us) * 1e-6;
        for (int a = 0; a < profile.axis_count; ++a) {
            row.x[a] = device.position(a);
            row.v[a] = device.velocity(a);
            row.sensed[a] = in.position[a];
            row.force[a] = out.force[a];
        }
        const int64_t next_us = ((n + 1) * 1'000'000 + rate / 2) / rate;
        device.step(out.force, static_cast<double>(next_us - in.t_us) * 1e-6);
    }
    return rows;
}

// Sign changes of the force on `axis` from row `from` on, counting only changes between
// forces larger than `floor` in magnitude (a force hovering at 0.0 is not a chatter).
inline int force_sign_changes(const std::vector<LoopRow>& rows, size_t from, int axis, double floor = 1.0) {
    int changes = 0;
    double last = 0;
    for (size_t i = from; i < rows.size(); ++i) {
        const double f = rows[i].force[axis];
        if (std::fabs(f) <= floor) continue;
        if (last != 0 && (f > 0) != (last > 0)) ++changes;
        last = f;
    }
    return changes;
}

inline double largest_force_step(const std::vector<LoopRow>& rows, size_t from, int axis) {
    double largest = 0;
    for (size_t i = from + 1; i < rows.size(); ++i) {
        largest = std::max(largest, std::fabs(rows[i].force[axis] - rows[i - 1].force[axis]));
    }
    return largest;
}

inline EffectParams friction_on(std::initializer_list<Axis> axes, int32_t coefficient) {
    EffectParams p;
    p.type = EffectType::friction;
    p.duration_us = kInfiniteUs;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) {
        p.axes[i] = a;
        p.conditions[i].pos_coefficient = coefficient;
        p.conditions[i].neg_coefficient = coefficient;
        ++i;
    }
    return p;
}

inline EffectParams constant_force_on_x(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = kInfiniteUs;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.constant.magnitude = magnitude;
    return p;
}

// Dynamic Inertia (§5.6) on `axes`, forever.
inline EffectParams dynamic_inertia_on(std::initializer_list<Axis> axes, int32_t inertia, int32_t play = 0) {
    EffectParams p;
    p.type = EffectType::dynamic_inertia;
    p.duration_us = kInfiniteUs;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) p.axes[i++] = a;
    p.dynamic.inertia = inertia;
    p.dynamic.play = play;
    return p;
}

// A texture (§3.6) on x.
inline EffectParams texture_on_x(int32_t pos_roughness, int32_t neg_roughness, int32_t spacing, int32_t density) {
    EffectParams p;
    p.type = EffectType::texture;
    p.duration_us = kInfiniteUs;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.texture.pos_roughness = pos_roughness;
    p.texture.neg_roughness = neg_roughness;
    p.texture.spacing = spacing;
    p.texture.density = density;
    return p;
}

}  // namespace feel::test
