// The built-in device profiles.
//
// The numbers describe real consumer hardware of each class, seen from the user's hand.
// Where a device is a lever (a joystick) its axis is modelled as linear motion of the grip
// point: mass is the effective mass felt at the grip (stick, gimbal and the motor rotors
// reflected through the transmission), force is the force at the grip. Rotary devices (a
// wheel) are modelled in rad, N·m and kg·m² about their shaft. docs/simulated-device.md
// tabulates every number with its normalized <-> physical mapping and its reasoning.
//
// Grip models are hand-arm impedances from the haptics literature: a hand resting on a
// handle is a soft, lightly damped spring (~100 N/m), a firm grasp a few hundred N/m, a
// braced, co-contracted arm one to two kN/m; the damping ratio of the coupled system stays
// near 0.25, as measured for human limbs. The added mass is the part of the hand and arm
// that moves with the handle: fingers for a loose grip, hand and forearm for a stiff one.
#include <cmath>
#include <cstdio>
#include <string>

#include "feel/sim/device_profile.hpp"

namespace feel::sim {
namespace {

// The control loop's rates the runtime can run (runtime::kMinLoopRateHz..kMaxLoopRateHz in
// feel/runtime/realtime_loop.hpp; feel_sim does not depend on the runtime).
constexpr int32_t kMinLoopRateHz = 100;
constexpr int32_t kMaxLoopRateHz = 20000;

// A linear grip axis, used by the joystick and the 3-axis device.
constexpr GripModel kLinearLoose{.stiffness = 100, .damping = 2, .added_mass = 0.05};
constexpr GripModel kLinearFirm{.stiffness = 400, .damping = 6, .added_mass = 0.15};
constexpr GripModel kLinearStiff{.stiffness = 1500, .damping = 15, .added_mass = 0.3};

// Force-FX class joystick (§3.7: "less than 1 pound of force"), two gimballed axes.
// The grip point sits ~0.115 m above the pivot; ±25° of stick travel is ±50 mm there.
constexpr AxisModel joystick_axis(Axis axis) {
    return AxisModel{
        .axis = axis,
        .kind = AxisKind::linear,
        .half_travel = 0.05,           // m: ±50 mm at the grip
        .max_force = 4.45,             // N: 1 lbf at the grip
        .mass = 0.15,                  // kg: stick + gimbal + reflected motor rotors
        .viscous = 0.5,                // N·s/m: motor back-EMF and gear losses
        .coulomb = 0.15,               // N: gear-train friction, ~3% of the motor limit
        .end_stop_stiffness = 5e4,     // N/m: padded hard stop, 0.09 mm under 1 lbf
        .end_stop_damping = 45,        // N·s/m: damping ratio ~0.26 against the bare stick
        .sensor_counts = 4096,         // 12 bits over the travel: 24 µm at the grip
    };
}

// Force-feedback wheel of the geared 900° class (e.g. 2.5 N·m, 14-bit encoder).
constexpr AxisModel wheel_axis() {
    return AxisModel{
        .axis = Axis::x,
        .kind = AxisKind::rotary,
        .half_travel = 7.853981633974483,  // rad: ±450°, 2.5 turns lock to lock
        .max_force = 2.5,                  // N·m: at the rim's shaft
        .mass = 0.015,                     // kg·m²: 280 mm rim and hub + reflected rotor
        .viscous = 0.01,                   // N·m·s/rad: back-EMF and gear losses
        .coulomb = 0.05,                   // N·m: helical gear friction, 2% of the limit
        .end_stop_stiffness = 1000,        // N·m/rad: the lock, 0.14° under full torque
        .end_stop_damping = 2,             // N·m·s/rad: damping ratio ~0.26 at the lock
        .sensor_counts = 16384,            // 14 bits over 900°: 0.055° per step
    };
}

// Three-axis delta-type device (Novint Falcon class: 4 in cube, 2 lbf, ~400 dpi).
constexpr AxisModel three_axis_axis(Axis axis) {
    return AxisModel{
        .axis = axis,
        .kind = AxisKind::linear,
        .half_travel = 0.0508,         // m: ±2 in, a 4 in cube
        .max_force = 8.9,              // N: 2 lbf
        .mass = 0.15,                  // kg: grip + arms + reflected capstan rotors
        .viscous = 0.4,                // N·s/m
        .coulomb = 0.05,               // N: cable capstans run almost without friction
        .end_stop_stiffness = 5e4,     // N/m: 0.18 mm under 2 lbf
        .end_stop_damping = 45,        // N·s/m: damping ratio ~0.26 against the bare grip
        .sensor_counts = 1600,         // 400 dpi over 4 in: 63.5 µm per step
    };
}

// The local processors (§2.2, §5.1, §6.1). The I-FORCE 2.0 class is DeviceProfile's
// default: 32 effect slots (the Linux iforce driver's IFORCE_EFFECTS_MAX), 16 KiB of
// parameter memory and a sample store as large as the pool, every type of the master set
// (§6.4), local reflexes. An I-FORCE 1.x-class core "supported the basic notions of
// Conditions and Waves but did not enable Dynamic Sensations" (§5.1). How many effects and
// bytes such a device holds varies by product: the iforce driver asks the device (its 'N'
// and 'B' queries) and assumes 10 effects and 200 bytes until it answers. feel's 1.x class
// takes half the 2.0 slots and a quarter of its memory: 16 slots of the largest wave (an
// enveloped sweep, 44 bytes) take 704 bytes, and the rest holds about 1.7 s of a one-axis
// force profile at 1 kHz. It does not run reflexes: the host emulates them (§1.2.c). Its
// loop runs at the 1 kHz the primer asks for (§2.2, rule ii) and no faster: a processor
// of that generation has no headroom beyond it (§2.2, "Local Bandwidth Limitations").
// docs/runtime.md, "Capabilities and device classes", tabulates both.
constexpr uint64_t kConditionsAndWaves = (effect_type_bit(EffectType::ramp) << 1) - 1;
static_assert(static_cast<int>(EffectType::ramp) + 1 == static_cast<int>(EffectType::dynamic_recoil),
              "kConditionsAndWaves relies on EffectType listing conditions, then waves, then dynamics");
constexpr int32_t kIforce1Slots = 16;
constexpr int32_t kIforce1PoolBytes = 4 * 1024;
constexpr int32_t kIforce1LoopRateHz = 1000;

constexpr DeviceProfile kProfiles[] = {
    DeviceProfile{
        .name = "joystick",
        .description = "2-axis force-feedback joystick of the Force-FX class: 4.45 N (1 lbf) "
                       "at the grip, ±50 mm of travel, 12-bit sensors",
        .axis_count = 2,
        .axes = {joystick_axis(Axis::x), joystick_axis(Axis::y)},
        .button_count = 4,
        .dead_man_switch = true,  // an optical hand sensor in the grip
        .velocity_ref = 1e5,  // 0.5 m/s at the grip: full travel in 0.2 s reads 10000
        .loose = kLinearLoose,
        .firm = kLinearFirm,
        .stiff = kLinearStiff,
        .hat_count = 2,  // a four-way hat on top of the grip, a second under the thumb
    },
    DeviceProfile{
        .name = "wheel",
        .description = "1-axis force-feedback steering wheel: 2.5 N·m, ±450° of travel, "
                       "14-bit sensor",
        .axis_count = 1,
        .axes = {wheel_axis()},
        .button_count = 8,
        .dead_man_switch = false,  // wheels of this class have none
        .velocity_ref = 2e4,  // 900°/s: lock to lock in one second reads 10000
        .loose = GripModel{.stiffness = 3, .damping = 0.12, .added_mass = 0.01},
        .firm = GripModel{.stiffness = 12, .damping = 0.35, .added_mass = 0.03},
        .stiff = GripModel{.stiffness = 40, .damping = 0.8, .added_mass = 0.05},
    },
    DeviceProfile{
        .name = "3axis",
        .description = "3-axis (x, y, z) force-feedback device of the Falcon class: 8.9 N "
                       "(2 lbf), a 4 in cube of travel, 400 dpi sensors",
        .axis_count = 3,
        .axes = {three_axis_axis(Axis::x), three_axis_axis(Axis::y),
                 three_axis_axis(Axis::z)},
        .button_count = 4,
        .dead_man_switch = false,  // the Falcon class has none
        .velocity_ref = 1e5,  // 0.508 m/s: full travel in 0.2 s reads 10000
        .loose = kLinearLoose,
        .firm = kLinearFirm,
        .stiff = kLinearStiff,
    },
    // The two classes side by side on the same stick: iforce1 and iforce2 have the
    // joystick's mechanics, buttons and hats, and differ only in their processor, so that a
    // sensation can be compared on both.
    DeviceProfile{
        .name = "iforce1",
        .description = "2-axis joystick with an I-FORCE 1.x-class processor: the joystick's "
                       "mechanics; Conditions and Waves, no Dynamics; 16 effects, 4 KiB; "
                       "reflexes emulated by the host",
        .axis_count = 2,
        .axes = {joystick_axis(Axis::x), joystick_axis(Axis::y)},
        .button_count = 4,
        .dead_man_switch = true,
        .velocity_ref = 1e5,
        .loose = kLinearLoose,
        .firm = kLinearFirm,
        .stiff = kLinearStiff,
        .device_class = DeviceClass::iforce1,
        .hat_count = 2,
        .effect_slots = kIforce1Slots,
        .pool_bytes = kIforce1PoolBytes,
        .sample_memory = kIforce1PoolBytes / pool_cost::kSample,
        .supported_types = kConditionsAndWaves,
        .local_reflexes = false,
        .default_loop_rate_hz = kIforce1LoopRateHz,
        .max_loop_rate_hz = kIforce1LoopRateHz,
    },
    DeviceProfile{
        .name = "iforce2",
        .description = "2-axis joystick with an I-FORCE 2.0-class processor: the joystick's "
                       "mechanics; every effect type, Dynamics included; 32 effects, 16 KiB; "
                       "local reflexes",
        .axis_count = 2,
        .axes = {joystick_axis(Axis::x), joystick_axis(Axis::y)},
        .button_count = 4,
        .dead_man_switch = true,
        .velocity_ref = 1e5,
        .loose = kLinearLoose,
        .firm = kLinearFirm,
        .stiff = kLinearStiff,
        .device_class = DeviceClass::iforce2,
        .hat_count = 2,
    },
};

std::string profile_number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// "" when lo <= v (or lo < v when strict) and v is finite.
std::string check_at_least(const std::string& field, double v, double lo, bool strict,
                           const char* unit) {
    const bool ok = std::isfinite(v) && (strict ? v > lo : v >= lo);
    if (ok) return {};
    return field + " = " + profile_number(v) + " is out of range (allowed a finite value " +
           (strict ? "> " : ">= ") + profile_number(lo) + ", " + unit + ")";
}

std::string check_grip(const std::string& name, const GripModel& g) {
    for (std::string e : {check_at_least(name + ".stiffness", g.stiffness, 0, false,
                                         "N/m or N·m/rad"),
                          check_at_least(name + ".damping", g.damping, 0, false,
                                         "N·s/m or N·m·s/rad"),
                          check_at_least(name + ".added_mass", g.added_mass, 0, false,
                                         "kg or kg·m²")}) {
        if (!e.empty()) return e;
    }
    return {};
}

std::string check_axis(int i, const AxisModel& a) {
    const std::string p = "axes[" + std::to_string(i) + "]";
    if (a.axis != static_cast<Axis>(i)) {
        return p + ".axis = " + std::string(axis_name(a.axis)) + " is wrong (axis " +
               std::to_string(i) + " of a device must be " +
               std::string(axis_name(static_cast<Axis>(i))) + ")";
    }
    for (std::string e : {
             check_at_least(p + ".half_travel", a.half_travel, 0, true, "m or rad"),
             check_at_least(p + ".max_force", a.max_force, 0, true, "N or N·m"),
             check_at_least(p + ".mass", a.mass, 0, true, "kg or kg·m²"),
             check_at_least(p + ".viscous", a.viscous, 0, false, "N·s/m or N·m·s/rad"),
             check_at_least(p + ".coulomb", a.coulomb, 0, false, "N or N·m"),
             check_at_least(p + ".end_stop_stiffness", a.end_stop_stiffness, 0, true,
                            "N/m or N·m/rad"),
             check_at_least(p + ".end_stop_damping", a.end_stop_damping, 0, false,
                            "N·s/m or N·m·s/rad"),
         }) {
        if (!e.empty()) return e;
    }
    // Readings are floats: 2^24 steps keep every one of them exact.
    constexpr int32_t kMaxCounts = 1 << 24;
    if (a.sensor_counts < 2 || a.sensor_counts > kMaxCounts) {
        return p + ".sensor_counts = " + std::to_string(a.sensor_counts) +
               " is out of range (allowed 2.." + std::to_string(kMaxCounts) + ")";
    }
    return {};
}

// The local processor's fields: budgets, effect types, loop rates, firmware.
std::string check_processor(const DeviceProfile& p) {
    if (p.device_class != DeviceClass::iforce1 && p.device_class != DeviceClass::iforce2) {
        return "device_class = " + std::to_string(static_cast<int>(p.device_class)) +
               " is out of range (allowed iforce1, iforce2)";
    }
    struct IntField {
        const char* name;
        int64_t value, lo, hi;
    };
    const IntField fields[] = {
        {"hat_count", p.hat_count, 0, 4},
        {"effect_slots", p.effect_slots, 1, 65535},
        {"pool_bytes", p.pool_bytes, 1, int64_t{1} << 30},
        {"sample_memory", p.sample_memory, 0, int64_t{1} << 24},
        {"max_loop_rate_hz", p.max_loop_rate_hz, kMinLoopRateHz, kMaxLoopRateHz},
        {"default_loop_rate_hz", p.default_loop_rate_hz, kMinLoopRateHz, p.max_loop_rate_hz},
    };
    for (const IntField& f : fields) {
        if (f.value < f.lo || f.value > f.hi) {
            return std::string(f.name) + " = " + std::to_string(f.value) +
                   " is out of range (allowed " + std::to_string(f.lo) + ".." +
                   std::to_string(f.hi) + ")";
        }
    }
    if ((p.supported_types & ~kAllEffectTypes) != 0 || p.supported_types == 0) {
        char buf[24];
        std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(p.supported_types));
        return std::string("supported_types = ") + buf +
               " is out of range (allowed a non-empty set of the " +
               std::to_string(kEffectTypeCount) + " effect types, bits 0.." +
               std::to_string(kEffectTypeCount - 1) + ")";
    }
    if (p.firmware_version.empty()) return "firmware_version is empty (allowed a non-empty name)";
    // What the device-info report can carry whole (the host must not get a cut text).
    const struct {
        const char* field;
        std::string_view text;
        std::size_t min, max;
    } texts[] = {{"name", p.name, 1, kMaxProfileNameBytes},
                 {"description", p.description, 0, kMaxProfileDescriptionBytes},
                 {"firmware_version", p.firmware_version, 1, kMaxProfileNameBytes}};
    for (const auto& t : texts) {
        if (t.text.size() < t.min || t.text.size() > t.max) {
            return std::string(t.field) + " is " + std::to_string(t.text.size()) +
                   " bytes long (allowed " + std::to_string(t.min) + ".." + std::to_string(t.max) + " bytes)";
        }
    }
    return {};
}

}  // namespace

std::string_view device_class_name(DeviceClass c) noexcept {
    switch (c) {
        case DeviceClass::iforce1: return "I-FORCE 1.x";
        case DeviceClass::iforce2: return "I-FORCE 2.0";
    }
    return "unknown device class";
}

std::span<const DeviceProfile> device_profiles() noexcept { return kProfiles; }

const DeviceProfile* find_device_profile(std::string_view name) noexcept {
    for (const DeviceProfile& p : kProfiles) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

std::string check_device_profile(const DeviceProfile& profile) {
    if (profile.axis_count < 1 || profile.axis_count > kMaxAxes) {
        return "axis_count = " + std::to_string(profile.axis_count) +
               " is out of range (allowed 1.." + std::to_string(kMaxAxes) + ")";
    }
    for (int i = 0; i < profile.axis_count; ++i) {
        if (std::string e = check_axis(i, profile.axes[i]); !e.empty()) return e;
    }
    if (profile.button_count < 0 || profile.button_count > 32) {
        return "button_count = " + std::to_string(profile.button_count) +
               " is out of range (allowed 0..32)";
    }
    if (std::string e = check_at_least("velocity_ref", profile.velocity_ref, 0, true,
                                       "normalized units/s");
        !e.empty()) {
        return e;
    }
    if (std::string e = check_grip("loose", profile.loose); !e.empty()) return e;
    if (std::string e = check_grip("firm", profile.firm); !e.empty()) return e;
    if (std::string e = check_grip("stiff", profile.stiff); !e.empty()) return e;
    return check_processor(profile);
}

}  // namespace feel::sim
