// The table of effect types: names, classes and envelope support (§6.4).
#include "feel/effect_type.hpp"

#include <array>

namespace feel {
namespace {

struct TypeInfo {
    std::string_view name;
    EffectClass cls;
    bool envelope;
};

// Indexed by EffectType; the order must follow the enum.
constexpr std::array<TypeInfo, kEffectTypeCount> kTypes = {{
    {"spring", EffectClass::condition, false},
    {"damper", EffectClass::condition, false},
    {"inertia", EffectClass::condition, false},
    {"friction", EffectClass::condition, false},
    {"angle_spring", EffectClass::condition, false},
    {"axis_barrier", EffectClass::condition, false},
    {"angle_barrier", EffectClass::condition, false},
    {"axis_wall", EffectClass::condition, false},
    {"angle_wall", EffectClass::condition, false},
    {"texture", EffectClass::condition, false},
    {"vector_force", EffectClass::wave, true},
    {"constant", EffectClass::wave, true},
    {"smart_pop", EffectClass::wave, false},
    {"sine", EffectClass::wave, true},
    {"square", EffectClass::wave, true},
    {"triangle", EffectClass::wave, true},
    {"saw_up", EffectClass::wave, true},
    {"saw_down", EffectClass::wave, true},
    {"sweep_sine", EffectClass::wave, true},
    {"sweep_square", EffectClass::wave, true},
    {"sweep_triangle", EffectClass::wave, true},
    {"sweep_saw_up", EffectClass::wave, true},
    {"sweep_saw_down", EffectClass::wave, true},
    {"force_profile", EffectClass::wave, true},
    {"ramp", EffectClass::wave, true},
    {"dynamic_recoil", EffectClass::dynamic, false},
    {"dynamic_impact", EffectClass::dynamic, false},
    {"dynamic_liquid", EffectClass::dynamic, false},
    {"dynamic_inertia", EffectClass::dynamic, false},
    {"dynamic_center_drift", EffectClass::dynamic, false},
    {"dynamic_control_law", EffectClass::dynamic, false},
    {"dynamic_sling", EffectClass::dynamic, false},
    {"dynamic_paddle", EffectClass::dynamic, false},
}};

constexpr const TypeInfo& info(EffectType t) noexcept { return kTypes[static_cast<size_t>(t)]; }

}  // namespace

std::string_view effect_type_name(EffectType t) noexcept { return info(t).name; }

std::optional<EffectType> effect_type_from_name(std::string_view name) noexcept {
    for (size_t i = 0; i < kTypes.size(); ++i) {
        if (kTypes[i].name == name) return static_cast<EffectType>(i);
    }
    return std::nullopt;
}

EffectClass effect_class(EffectType t) noexcept { return info(t).cls; }
bool supports_envelope(EffectType t) noexcept { return info(t).envelope; }

bool is_periodic(EffectType t) noexcept {
    return t >= EffectType::sine && t <= EffectType::saw_down;
}

bool is_sweep(EffectType t) noexcept {
    return t >= EffectType::sweep_sine && t <= EffectType::sweep_saw_down;
}

Waveform waveform_of(EffectType t) noexcept {
    const int first = is_sweep(t) ? static_cast<int>(EffectType::sweep_sine)
                                  : static_cast<int>(EffectType::sine);
    return static_cast<Waveform>(static_cast<int>(t) - first);
}

}  // namespace feel
