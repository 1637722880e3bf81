// Closed-loop rigs for walls and barriers: the engine and SimDevice tick together at 1 kHz
// exactly as feel::render::render() runs them (sense, tick, step), so that a test can
// change the hand in the middle of a run (a hand that lets go) and read the engine's
// output, including the reported position, every tick.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::test::loop {

inline constexpr int64_t kTickUs = 1000;
inline constexpr double kTickS = 1e-3;

class ClosedLoop {
public:
    explicit ClosedLoop(const EngineConfig& config) : engine_(config) {}

    EffectId play(const EffectParams& p) {
        const CreateResult r = engine_.create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(engine_.start(r.id).ok());
        return r.id;
    }

    // One tick: the engine reads the device's sensors and its force then drives the
    // device for one tick. Returns the engine's output for the tick.
    TickOutput tick(sim::SimDevice& device) {
        TickInput in;
        in.t_us = t_us_;
        device.sense(in);
        TickOutput out;
        engine_.tick(in, out);
        device.step(out.force, kTickS);
        t_us_ += kTickUs;
        return out;
    }

    Engine& engine() { return engine_; }

private:
    Engine engine_;
    int64_t t_us_ = 0;
};

// The hand lets go: a free handle (no grip) in the held handle's state.
inline sim::SimDevice let_go(const sim::SimDevice& held) {
    sim::SimDevice free(held.profile(), sim::Grip::none, sim::TargetMotion::hold_at({0.0}));
    for (int a = 0; a < held.profile().axis_count; ++a) {
        free.set_position(a, held.position(a));
        free.set_velocity(a, held.velocity(a));
    }
    return free;
}

// Largest minus smallest of x[from, to).
inline double peak_to_peak(const std::vector<double>& x, size_t from, size_t to) {
    const auto [lo, hi] = std::minmax_element(x.begin() + static_cast<std::ptrdiff_t>(from),
                                              x.begin() + static_cast<std::ptrdiff_t>(to));
    return *hi - *lo;
}

// A constant force on one axis, forever: the "gravity" that keeps a let-go handle on the wall.
inline EffectParams constant_push(Axis axis, int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::constant;
    p.axis_count = 1;
    p.axes[0] = axis;
    p.constant.magnitude = magnitude;
    return p;
}

// The naive passivity bound of a device, K = 2b/T with T = 1 ms, normalized units.
inline double naive_bound(const EngineConfig& c) { return 2.0 * c.device_damping / kTickS; }

// One sensor count of axis 0, normalized units.
inline double sensor_count(const sim::DeviceProfile& p) { return 20000.0 / p.axes[0].sensor_counts; }

inline std::string profile_name(const ::testing::TestParamInfo<const char*>& info) {
    std::string name = info.param;
    std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

}  // namespace feel::test::loop
