// feel::sim — device profiles: the physical facts of each simulated device.
//
// A profile maps feel's normalized units onto physical ones for each axis:
//   position  ±10000  <->  ±half_travel   (m for linear axes, rad for rotary axes)
//   force     ±10000  <->  ±max_force     (N or N·m; the motor's limit)
// and velocity 10000 <-> velocity_ref (normalized position units per second); see
// docs/conventions.md and, for the numbers of every profile and where they come from,
// docs/simulated-device.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "feel/axis.hpp"
#include "feel/engine.hpp"

namespace feel::sim {

enum class AxisKind : uint8_t { linear, rotary };

// One axis of the handle's mechanism. Every field must be finite; check_device_profile()
// states the allowed range of each.
struct AxisModel {
    Axis axis = Axis::x;
    AxisKind kind = AxisKind::linear;
    double half_travel = 0.05;         // m or rad, > 0: position +10000 is +half_travel
    double max_force = 4.45;           // N or N·m, > 0: the motor limit, force 10000
    double mass = 0.1;                 // kg or kg·m², > 0: moving mass of the handle
    double viscous = 0.2;              // N·s/m or N·m·s/rad, >= 0: the mechanism's damping b
    double coulomb = 0.05;             // N or N·m, >= 0: the mechanism's dry friction
    double end_stop_stiffness = 2e3;   // N/m or N·m/rad, > 0, beyond ±half_travel
    double end_stop_damping = 5.0;     // N·s/m or N·m·s/rad, >= 0, while pressing into a stop
    int32_t sensor_counts = 4096;      // 2..16777216: encoder steps across the full travel
};

// How a hand holds the handle: a spring-damper tether to the target motion, plus the
// part of the hand's mass that moves with the handle. All fields finite and >= 0.
struct GripModel {
    double stiffness = 0;   // N/m or N·m/rad
    double damping = 0;     // N·s/m or N·m·s/rad
    double added_mass = 0;  // kg or kg·m²
};

// The generation of the device's local processor (§2.2, §5.1, §6.1). An I-FORCE 1.x-class
// core plays Conditions and Waves but no Dynamics, holds fewer effects and does not run
// reflexes (the host emulates them, §1.2.c); an I-FORCE 2.0-class core plays the whole
// master set of §6.4 and runs reflexes. docs/runtime.md, "Capabilities and device classes".
// The numbers are the class's generation, the same in C++, in C (FEEL_DEVICE_CLASS_*) and
// on the wire (Device Info's device_class); 0 is no class, so a zeroed report is refused.
enum class DeviceClass : uint8_t { iforce1 = 1, iforce2 = 2 };
// "I-FORCE 1.x", "I-FORCE 2.0".
[[nodiscard]] std::string_view device_class_name(DeviceClass c) noexcept;

// The longest texts a device tells its host in its device-info report (docs/protocol.md):
// a profile's name and firmware version, and its description, in bytes.
inline constexpr std::size_t kMaxProfileNameBytes = 23;
inline constexpr std::size_t kMaxProfileDescriptionBytes = 191;

struct DeviceProfile {
    std::string_view name;         // "joystick", "wheel", "3axis", "iforce1", "iforce2"; 1..23 bytes
    std::string_view description;  // one line, 0..191 bytes
    int32_t axis_count = 0;        // 1..6; axes[i].axis must be axis i (x, y, z, rx, ry, rz)
    AxisModel axes[kMaxAxes] = {};
    int32_t button_count = 0;      // 0..32
    // Whether the handle has a dead-man switch (§2.2) that senses the hand. Without one,
    // sense() reports handle_held = true whatever the hand does, and only the runtime's
    // hands-off detector can tell a free handle.
    bool dead_man_switch = true;
    double velocity_ref = 1e5;     // normalized position units/s that read as velocity 10000
    GripModel loose{}, firm{}, stiff{};  // per axis, same on every axis of the device

    // The local processor (§2.2): what it plays and how much it holds. The defaults are the
    // I-FORCE 2.0 class; check_device_profile() states each range.
    DeviceClass device_class = DeviceClass::iforce2;
    int32_t hat_count = 0;            // 0..4 hat switches (TickInput::hats, reflex triggers)
    int32_t effect_slots = 32;        // 1..65535: effects resident at once
    int32_t pool_bytes = 16 * 1024;   // 1..2^30: parameter memory, bytes (engine.hpp pool_cost)
    int32_t sample_memory = 8 * 1024; // 0..2^24: force-profile sample storage, samples
    // The effect types it plays: effect_type_bit(t) for each (engine.hpp); no bit beyond
    // the kEffectTypeCount types.
    uint64_t supported_types = kAllEffectTypes;
    bool local_reflexes = true;       // runs trigger-button reflexes itself (§1.2.c)
    int32_t default_loop_rate_hz = 1000;  // Hz, 100..max_loop_rate_hz: the control loop (§2.2)
    int32_t max_loop_rate_hz = 20000;     // Hz, 100..20000 (the runtime's loop limits)
    std::string_view firmware_version = "feel-sim 0.1.0";  // 1..23 bytes
};

// The built-in profiles, in the order "joystick", "wheel", "3axis", "iforce1", "iforce2".
[[nodiscard]] std::span<const DeviceProfile> device_profiles() noexcept;
// nullptr when no built-in profile has this name.
[[nodiscard]] const DeviceProfile* find_device_profile(std::string_view name) noexcept;

// What the engine needs to know of a device, in normalized units: its axes, velocity and
// acceleration scales, sensor resolution and mechanical damping (from axis 0, the profiles'
// axes share them), and its local processor's budgets and effect types (effect_slots,
// pool_bytes, sample_memory, supported_types, device_class). See docs/conventions.md.
[[nodiscard]] EngineConfig engine_config_for(const DeviceProfile& profile) noexcept;

// Empty when the profile is usable by SimDevice; otherwise a sentence naming the first bad
// field, its value and the allowed range, e.g.
//   "axes[1].mass = 0 is out of range (allowed a finite value > 0, kg or kg·m²)".
[[nodiscard]] std::string check_device_profile(const DeviceProfile& profile);

}  // namespace feel::sim
