// The table of effect types: names, classes and envelope support (§6.4).
#include "feel/effect_type.hpp"

#include <array>
#include <cstdint>

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

// What the functions below read, built from kTypes at compile time (kTypes itself is not
// kept): a name's start and length and a byte of class and envelope, 6 bytes a type
// against kTypes' 12 (a string_view, 8, and 2 bytes padded to 4). On the Cortex-M4 build
// flash is counted (docs/firmware.md).
struct TypeTables {
    const char* name[kEffectTypeCount];
    uint8_t name_length[kEffectTypeCount];
    uint8_t traits[kEffectTypeCount];  // the class in bits 0..1, envelope support in bit 2
};

constexpr uint8_t kEnvelopeBit = 4;

constexpr TypeTables type_tables() noexcept {
    TypeTables t{};
    for (size_t i = 0; i < kTypes.size(); ++i) {
        t.name[i] = kTypes[i].name.data();
        t.name_length[i] = static_cast<uint8_t>(kTypes[i].name.size());
        t.traits[i] = static_cast<uint8_t>(static_cast<uint8_t>(kTypes[i].cls) | (kTypes[i].envelope ? kEnvelopeBit : 0));
    }
    return t;
}

constexpr TypeTables kTypeTables = type_tables();
static_assert(static_cast<int>(EffectClass::dynamic) < kEnvelopeBit, "the class fits below the envelope bit");

}  // namespace

std::string_view effect_type_name(EffectType t) noexcept {
    const auto i = static_cast<size_t>(t);
    return {kTypeTables.name[i], kTypeTables.name_length[i]};
}

std::optional<EffectType> effect_type_from_name(std::string_view name) noexcept {
    for (int i = 0; i < kEffectTypeCount; ++i) {
        if (effect_type_name(static_cast<EffectType>(i)) == name) return static_cast<EffectType>(i);
    }
    return std::nullopt;
}

EffectClass effect_class(EffectType t) noexcept {
    return static_cast<EffectClass>(kTypeTables.traits[static_cast<size_t>(t)] & (kEnvelopeBit - 1));
}

bool supports_envelope(EffectType t) noexcept {
    return (kTypeTables.traits[static_cast<size_t>(t)] & kEnvelopeBit) != 0;
}

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
