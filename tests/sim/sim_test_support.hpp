// Helpers for the simulated-device tests: hand-built profiles with only the physics a test
// wants, and a loop that drives a device with a constant force.
#pragma once

#include <cmath>

#include "feel/sim/sim_device.hpp"

namespace feel::sim::test {

// Normalized position units per physical unit of an axis.
inline double per_unit(const AxisModel& a) { return 10000.0 / a.half_travel; }

// One linear axis with the given mass and friction. The travel is long enough (±100 m)
// that the stops never matter unless a test wants them.
inline DeviceProfile bare_profile(double mass, double viscous, double coulomb,
                                  double max_force = 1.0, double half_travel = 100.0) {
    DeviceProfile p;
    p.name = "bare";
    p.description = "test profile";
    p.axis_count = 1;
    p.velocity_ref = 1e5;
    AxisModel& a = p.axes[0];
    a.axis = Axis::x;
    a.kind = AxisKind::linear;
    a.half_travel = half_travel;
    a.max_force = max_force;
    a.mass = mass;
    a.viscous = viscous;
    a.coulomb = coulomb;
    a.end_stop_stiffness = 1.0;
    a.end_stop_damping = 0.0;
    a.sensor_counts = 4096;
    return p;
}

// A copy of a built-in profile with different mechanism friction on every axis.
inline DeviceProfile with_friction(const DeviceProfile& base, double viscous, double coulomb) {
    DeviceProfile p = base;
    for (int i = 0; i < p.axis_count; ++i) {
        p.axes[i].viscous = viscous;
        p.axes[i].coulomb = coulomb;
    }
    return p;
}

inline const GripModel& grip_of(const DeviceProfile& p, Grip g) {
    return g == Grip::loose ? p.loose : g == Grip::firm ? p.firm : p.stiff;
}

// Steps `device` for `steps` ticks of dt with the same normalized force on every axis.
inline void run(SimDevice& device, float force, double dt, int steps) {
    float f[kMaxAxes];
    for (float& v : f) v = force;
    for (int i = 0; i < steps; ++i) device.step(f, dt);
}

}  // namespace feel::sim::test
