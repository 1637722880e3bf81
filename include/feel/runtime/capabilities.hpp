// feel::runtime — what a device can do, as it tells the host (§6.1, §6.2, §7.4).
//
// DirectX 5 learns a force-feedback device's features by asking it: GetCapabilities for its
// axes, buttons and force feedback (§7.4), EnumEffects for the effect types it plays (§6.2).
// A host must not assume the full master set of §6.4: an I-FORCE 1.x-class core plays
// Conditions and Waves but no Dynamics (§5.1) and holds fewer effects, and "if programming
// for an older I-FORCE 1.x processing core, some sensation types will not be listed" (§9).
//
// Capabilities is that answer, computed from a device profile (the profile is the device's
// data sheet; capabilities are what the runtime reports of it). It is plain data, made once
// at setup; nothing here runs in the loop. docs/runtime.md, "Capabilities and device
// classes", tabulates the classes and the built-in profiles.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

#include "feel/axis.hpp"
#include "feel/effect_type.hpp"
#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::runtime {

// The protocol the runtime speaks to the host: the USB HID Physical Interface Device class
// (PID 1.0, the DirectInput model of §6) plus feel's vendor-defined reports for what PID
// lacks (Dynamics, reflex repeat, IDF). The host side arrives with the host-link issue;
// this names the version it will be.
inline constexpr std::string_view kProtocolVersion = "HID PID 1.0 + feel vendor 2";
inline constexpr int32_t kProtocolVendorRevision = 2;

// One axis as the host sees it: what ±10000 of position and force mean physically.
struct AxisCapability {
    Axis axis = Axis::x;
    sim::AxisKind kind = sim::AxisKind::linear;
    double half_travel = 0;       // m (linear) or rad (rotary), > 0: position ±10000
    double max_force = 0;         // N (linear) or N·m (rotary), > 0: force ±10000
    int32_t sensor_counts = 0;    // 2..2^24 encoder steps across the full travel
    double resolution = 0;        // m or rad per sensor step: 2·half_travel / sensor_counts
};

// "m" or "rad"; "N" or "N·m".
[[nodiscard]] std::string_view travel_unit(sim::AxisKind kind) noexcept;
[[nodiscard]] std::string_view force_unit(sim::AxisKind kind) noexcept;

struct Capabilities {
    std::string_view device;           // the profile's name, e.g. "iforce1"
    std::string_view description;      // one line about the hardware
    sim::DeviceClass device_class = sim::DeviceClass::iforce2;
    std::string_view class_name;       // "I-FORCE 1.x", "I-FORCE 2.0"

    // Input (GetCapabilities, §7.4).
    int32_t axis_count = 0;            // 1..6, axes x, y, z, rx, ry, rz in order
    AxisCapability axes[kMaxAxes] = {};
    int32_t button_count = 0;          // 0..32, buttons 1..button_count
    int32_t hat_count = 0;             // 0..4, hats 1..hat_count
    bool dead_man_switch = false;      // senses the hand on the handle (§2.2)

    // Force output. Forces are normalized: ±kFullScale (10000) is each axis's max_force.
    int32_t max_force_normalized = kFullScale;

    // Effects (EnumEffects, §6.2) and the local memory (§2.2).
    uint64_t supported_types = 0;      // effect_type_bit(t) per playable EffectType
    int32_t effect_slots = 0;          // effects resident (and playing) at once
    int32_t pool_bytes = 0;            // parameter memory, bytes (pool_cost in engine.hpp)
    int32_t sample_memory = 0;         // force-profile sample storage, samples
    bool local_reflexes = false;       // the device runs trigger-button reflexes (§1.2.c)
    bool interim_reports = false;      // dynamics report their mass while they play (§5.2)

    // The local processor's loop (§2.2) and its reports.
    int32_t loop_rate_hz = 0;          // default control-loop rate, Hz
    int32_t max_loop_rate_hz = 0;      // the fastest the device's loop may be set to, Hz
    float interim_report_hz = 0;       // interim reports of dynamics, Hz (0 without them)

    std::string_view firmware_version; // e.g. "feel-sim 0.1.0"
    std::string_view protocol_version; // kProtocolVersion

    [[nodiscard]] bool supports(EffectType t) const noexcept {
        return (supported_types & effect_type_bit(t)) != 0;
    }
    // Whether it plays at least one type of the class.
    [[nodiscard]] bool supports(EffectClass c) const noexcept;
    [[nodiscard]] int32_t supported_type_count() const noexcept;
};

// The capabilities of a device built to this profile. Its budgets and effect types are the
// ones sim::engine_config_for(profile) gives the engine, so what the device reports is what
// the engine enforces. Throws std::invalid_argument (the check_device_profile message) for
// a profile that is not usable.
[[nodiscard]] Capabilities capabilities_for(const sim::DeviceProfile& profile);

// EnumEffects (§6.2): calls visit(type) for each supported type, in EffectType order (the
// order of §6.4), of the class `only` or of every class, until visit returns false.
// Returns how many types it visited.
template <class Visit>
int32_t enum_effects(const Capabilities& caps, Visit&& visit,
                     std::optional<EffectClass> only = std::nullopt) {
    int32_t visited = 0;
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        if (!caps.supports(t)) continue;
        if (only && effect_class(t) != *only) continue;
        ++visited;
        if (!visit(t)) break;
    }
    return visited;
}

// "Conditions", "Waves", "Dynamics" (the primer's class names, §6.2).
[[nodiscard]] std::string_view effect_class_label(EffectClass c) noexcept;

// The capabilities as text for people (feel caps): one "key: value" line per fact, the
// effect types grouped by class. docs/cli.md shows an example.
void print_capabilities(std::ostream& out, const Capabilities& caps);
[[nodiscard]] std::string format_capabilities(const Capabilities& caps);

}  // namespace feel::runtime
