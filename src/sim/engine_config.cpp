// From a device profile's physical facts to the engine's normalized view of the device.
#include <algorithm>
#include <cmath>

#include "feel/sim/device_profile.hpp"

namespace feel::sim {

// A hand reaches full speed (velocity_ref) from rest in about 50 ms in a brisk deliberate
// move, so that is the acceleration inertia conditions read as full scale.
constexpr double kTimeToFullSpeed_s = 0.05;

// Walls and barriers: hardness 10000 is this many times the device's naive passivity
// bound 2b/T (Colgate & Schenkel) at the 1 kHz loop the profiles are built for. The
// passivity controller keeps such walls stable; without it, hardness above
// 10000/kWallStiffnessOverBound rings. docs/stability.md has the numbers per profile.
constexpr double kWallStiffnessOverBound = 5.0;
constexpr double kDesignTickPeriod_s = 1e-3;
// A device without mechanical damping has no naive bound; its walls still get a usable
// stiffness (full force at a tenth of the travel) and rely on the controller.
constexpr double kMinWallStiffness = 10.0;

// Dynamic Sensations (docs/dynamics.md). Stiffness 10000 is this many times the naive
// passivity bound 2b/T: the tether's force is the mean reaction over the coming tick
// (control_law_dynamic.cpp), which removes the held sample's lag, and the sampled-data
// analysis keeps every profile, grip and mass stable at 2x with a margin (3x is marginal
// on the 3-axis device). A device without mechanical damping gets the floor instead.
constexpr double kTetherStiffnessOverBound = 2.0;
constexpr double kMinTetherStiffness = 2.0;

EngineConfig engine_config_for(const DeviceProfile& profile) noexcept {
    EngineConfig c;
    c.axis_count = profile.axis_count;
    // The local processor's memory and effect set come from the profile (device_profiles.cpp:
    // the I-FORCE 2.0 class has 32 slots and 16 KiB, the 1.x class 16 slots and 4 KiB and
    // no Dynamics), so the engine enforces what the device's capabilities report.
    c.max_effects = profile.effect_slots;
    c.pool_bytes = profile.pool_bytes;
    c.max_samples = profile.sample_memory;
    c.supported_types = profile.supported_types;
    c.device_class = device_class_name(profile.device_class);
    const AxisModel& axis = profile.axes[0];
    c.velocity_ref = static_cast<float>(profile.velocity_ref);
    c.acceleration_ref = static_cast<float>(profile.velocity_ref / kTimeToFullSpeed_s);
    c.sensor_step = static_cast<float>(2.0 * kFullScale / axis.sensor_counts);
    // F_norm = F·10000/max_force and v_phys = v_norm·half_travel/10000, so a damping b in
    // physical units is b·half_travel/max_force in normalized ones.
    c.device_damping = static_cast<float>(axis.viscous * axis.half_travel / axis.max_force);
    c.device_mass = static_cast<float>(axis.mass * axis.half_travel / axis.max_force);
    const double naive_bound = 2.0 * c.device_damping / kDesignTickPeriod_s;
    c.wall_stiffness = static_cast<float>(std::max(kWallStiffnessOverBound * naive_bound, kMinWallStiffness));
    // Dynamics: mass 10000 is what full force accelerates at acceleration_ref (the scale
    // of the inertia condition); gravity 10000 makes mass 10000 weigh full force; b 10000
    // critically damps mass 10000 on a tether of stiffness 10000 against a held handle.
    const double mass_ref = kFullScale / static_cast<double>(c.acceleration_ref);
    const double stiffness_ref = std::max(kTetherStiffnessOverBound * naive_bound, kMinTetherStiffness);
    c.dynamic_mass_ref = static_cast<float>(mass_ref);
    c.dynamic_stiffness_ref = static_cast<float>(stiffness_ref);
    c.dynamic_damping_ref = static_cast<float>(2.0 * std::sqrt(stiffness_ref * mass_ref));
    c.gravity_ref = static_cast<float>(kFullScale / mass_ref);
    return c;
}

}  // namespace feel::sim
