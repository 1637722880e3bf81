// The field tables: one line per field, in canonical (documented) order.
#include "effect_fields.hpp"

#include <type_traits>

namespace feel::format::detail {
namespace {

// Where a block lives inside EffectParams. `slot` is the axis for per-axis blocks.
template <auto Member>
struct Whole {
    static auto& in(EffectParams& p, int) noexcept { return p.*Member; }
    static const auto& in(const EffectParams& p, int) noexcept { return p.*Member; }
};

struct ConditionAt {
    static ConditionBlock& in(EffectParams& p, int slot) noexcept { return p.conditions[slot]; }
    static const ConditionBlock& in(const EffectParams& p, int slot) noexcept { return p.conditions[slot]; }
};

struct ControlLawAt {
    static ControlLawBlock& in(EffectParams& p, int slot) noexcept { return p.dynamic.control_law[slot]; }
    static const ControlLawBlock& in(const EffectParams& p, int slot) noexcept {
        return p.dynamic.control_law[slot];
    }
};

using InPeriodic = Whole<&EffectParams::periodic>;
using InConstant = Whole<&EffectParams::constant>;
using InRamp = Whole<&EffectParams::ramp>;
using InCustom = Whole<&EffectParams::custom>;
using InTexture = Whole<&EffectParams::texture>;
using InWall = Whole<&EffectParams::wall>;
using InBarrier = Whole<&EffectParams::barrier>;
using InDynamic = Whole<&EffectParams::dynamic>;
using InEnvelope = Whole<&EffectParams::envelope>;

template <class C, class T>
T member_type_of(T C::*);  // only for decltype

template <class At, auto Member>
constexpr FieldSpec field(std::string_view name, bool required,
                          std::span<const std::string_view> choices = {}, std::string_view alias = {}) {
    using T = decltype(member_type_of(Member));
    constexpr ValueKind kind = std::is_same_v<T, bool>      ? ValueKind::boolean
                               : std::is_enum_v<T>          ? ValueKind::choice
                               : std::is_same_v<T, int64_t> ? ValueKind::i64
                                                            : ValueKind::i32;
    static_assert(kind != ValueKind::i32 || std::is_same_v<T, int32_t>);
    return FieldSpec{
        name, kind, required, choices,
        [](const EffectParams& p, int slot) -> int64_t { return static_cast<int64_t>(At::in(p, slot).*Member); },
        [](EffectParams& p, int slot, int64_t v) {
            if constexpr (std::is_same_v<T, bool>) {
                At::in(p, slot).*Member = v != 0;
            } else {
                At::in(p, slot).*Member = static_cast<T>(v);
            }
        },
        alias};
}

constexpr bool kRequired = true;
constexpr bool kOptional = false;

constexpr std::string_view kSweepSenses[] = {"clockwise", "counterclockwise"};  // SweepSense
constexpr std::string_view kWallSenses[] = {"positive", "negative"};            // WallSense
constexpr std::string_view kOffsetModes[] = {"absolute", "relative"};           // OffsetMode

// --- waves ---

constexpr FieldSpec kPeriodic[] = {
    field<InPeriodic, &PeriodicBlock::magnitude>("magnitude", kRequired),
    field<InPeriodic, &PeriodicBlock::offset>("offset", kOptional),
    field<InPeriodic, &PeriodicBlock::period_us>("period_us", kRequired),
    field<InPeriodic, &PeriodicBlock::phase>("phase", kOptional),
};

constexpr FieldSpec kSweep[] = {
    field<InPeriodic, &PeriodicBlock::magnitude>("magnitude", kRequired),
    field<InPeriodic, &PeriodicBlock::offset>("offset", kOptional),
    field<InPeriodic, &PeriodicBlock::period_us>("period_us", kRequired),
    field<InPeriodic, &PeriodicBlock::phase>("phase", kOptional),
    field<InPeriodic, &PeriodicBlock::sweep_start_angle>("sweep_start_angle", kRequired),
    field<InPeriodic, &PeriodicBlock::sweep_end_angle>("sweep_end_angle", kRequired),
    field<InPeriodic, &PeriodicBlock::sweep_sense>("sweep_sense", kRequired, kSweepSenses),
};

constexpr FieldSpec kConstant[] = {
    field<InConstant, &ConstantBlock::magnitude>("magnitude", kRequired),
};

constexpr FieldSpec kRamp[] = {
    field<InRamp, &RampBlock::start>("start", kRequired),
    field<InRamp, &RampBlock::end>("end", kRequired),
};

// sample_count is not a field: it is the length of "samples".
constexpr FieldSpec kCustom[] = {
    field<InCustom, &CustomBlock::channels>("channels", kOptional),
    field<InCustom, &CustomBlock::sample_period_us>("sample_period_us", kRequired),
};

// --- conditions ---

constexpr FieldSpec kCondition[] = {
    field<ConditionAt, &ConditionBlock::pos_coefficient>("pos_coefficient", kRequired),
    field<ConditionAt, &ConditionBlock::neg_coefficient>("neg_coefficient", kRequired),
    field<ConditionAt, &ConditionBlock::offset>("offset", kOptional),
    field<ConditionAt, &ConditionBlock::pos_saturation>("pos_saturation", kOptional),
    field<ConditionAt, &ConditionBlock::neg_saturation>("neg_saturation", kOptional),
    field<ConditionAt, &ConditionBlock::deadband>("deadband", kOptional),
    field<ConditionAt, &ConditionBlock::offset_mode>("offset_mode", kOptional, kOffsetModes),
};

constexpr FieldSpec kTexture[] = {
    field<InTexture, &TextureBlock::pos_roughness>("pos_roughness", kRequired),
    field<InTexture, &TextureBlock::neg_roughness>("neg_roughness", kRequired),
    field<InTexture, &TextureBlock::spacing>("spacing", kRequired),
    field<InTexture, &TextureBlock::density>("density", kRequired),
};

// An axis_wall lies across its one axis: it has no angle field at all.
constexpr FieldSpec kAxisWall[] = {
    field<InWall, &WallBlock::hardness>("hardness", kRequired),
    field<InWall, &WallBlock::sense>("sense", kRequired, kWallSenses),
    field<InWall, &WallBlock::offset>("offset", kOptional),
    field<InWall, &WallBlock::offset_mode>("offset_mode", kOptional, kOffsetModes),
    field<InWall, &WallBlock::surface_friction>("surface_friction", kOptional),
    field<InWall, &WallBlock::surface_texture>("surface_texture", kOptional),
    field<InWall, &WallBlock::clipping>("clipping", kOptional),
};

constexpr FieldSpec kAngleWall[] = {
    field<InWall, &WallBlock::hardness>("hardness", kRequired),
    field<InWall, &WallBlock::sense>("sense", kRequired, kWallSenses),
    field<InWall, &WallBlock::offset>("offset", kOptional),
    field<InWall, &WallBlock::offset_mode>("offset_mode", kOptional, kOffsetModes),
    field<InWall, &WallBlock::angle>("angle", kRequired),
    field<InWall, &WallBlock::surface_friction>("surface_friction", kOptional),
    field<InWall, &WallBlock::surface_texture>("surface_texture", kOptional),
    field<InWall, &WallBlock::clipping>("clipping", kOptional),
};

constexpr FieldSpec kAxisBarrier[] = {
    field<InBarrier, &BarrierBlock::pos_hardness>("pos_hardness", kRequired),
    field<InBarrier, &BarrierBlock::neg_hardness>("neg_hardness", kRequired),
    field<InBarrier, &BarrierBlock::thickness>("thickness", kRequired),
    field<InBarrier, &BarrierBlock::offset>("offset", kOptional),
    field<InBarrier, &BarrierBlock::offset_mode>("offset_mode", kOptional, kOffsetModes),
    field<InBarrier, &BarrierBlock::surface_friction>("surface_friction", kOptional),
    field<InBarrier, &BarrierBlock::surface_texture>("surface_texture", kOptional),
};

constexpr FieldSpec kAngleBarrier[] = {
    field<InBarrier, &BarrierBlock::pos_hardness>("pos_hardness", kRequired),
    field<InBarrier, &BarrierBlock::neg_hardness>("neg_hardness", kRequired),
    field<InBarrier, &BarrierBlock::thickness>("thickness", kRequired),
    field<InBarrier, &BarrierBlock::offset>("offset", kOptional),
    field<InBarrier, &BarrierBlock::offset_mode>("offset_mode", kOptional, kOffsetModes),
    field<InBarrier, &BarrierBlock::angle>("angle", kRequired),
    field<InBarrier, &BarrierBlock::surface_friction>("surface_friction", kOptional),
    field<InBarrier, &BarrierBlock::surface_texture>("surface_texture", kOptional),
};

// --- dynamics: the §8.4 wrapper parameters, in the wrappers' argument order ---

constexpr FieldSpec kInterim = field<InDynamic, &DynamicBlock::interim_reporting>("interim_reporting", kOptional);

constexpr FieldSpec kRecoil[] = {
    field<InDynamic, &DynamicBlock::blast_direction>("blast_direction", kRequired),
    field<InDynamic, &DynamicBlock::blast_intensity>("blast_intensity", kRequired),
    field<InDynamic, &DynamicBlock::dynamic_mass>("dynamic_mass", kRequired),
    field<InDynamic, &DynamicBlock::blast_resonance>("blast_resonance", kRequired),
    field<InDynamic, &DynamicBlock::blast_decay>("blast_decay", kRequired),
    kInterim,
};

constexpr FieldSpec kImpact[] = {
    field<InDynamic, &DynamicBlock::impact_direction>("impact_direction", kRequired),
    field<InDynamic, &DynamicBlock::impact_intensity>("impact_intensity", kRequired),
    field<InDynamic, &DynamicBlock::dynamic_mass>("dynamic_mass", kRequired),
    field<InDynamic, &DynamicBlock::elasticity>("elasticity", kRequired),
    field<InDynamic, &DynamicBlock::collision_absorption>("collision_absorption", kRequired),
    kInterim,
};

constexpr FieldSpec kLiquid[] = {
    field<InDynamic, &DynamicBlock::density>("density", kRequired),
    field<InDynamic, &DynamicBlock::settle>("settle", kRequired),
    field<InDynamic, &DynamicBlock::viscosity>("viscosity", kRequired),
    kInterim,
};

constexpr FieldSpec kDynamicInertia[] = {
    field<InDynamic, &DynamicBlock::inertia>("inertia", kRequired),
    field<InDynamic, &DynamicBlock::play>("play", kRequired),
    kInterim,
};

constexpr FieldSpec kCenterDrift[] = {
    field<InDynamic, &DynamicBlock::stiffness>("stiffness", kRequired),
    field<InDynamic, &DynamicBlock::drift_resistance>("drift_resistance", kRequired),
    kInterim,
};

constexpr FieldSpec kSling[] = {
    field<InDynamic, &DynamicBlock::ball_mass>("ball_mass", kRequired),
    field<InDynamic, &DynamicBlock::string_length>("string_length", kRequired),
    field<InDynamic, &DynamicBlock::string_compliance>("string_compliance", kRequired),
    field<InDynamic, &DynamicBlock::ball_damping>("ball_damping", kRequired),
    kInterim,
};

constexpr FieldSpec kPaddle[] = {
    field<InDynamic, &DynamicBlock::ball_mass>("ball_mass", kRequired),
    field<InDynamic, &DynamicBlock::initial_velocity>("initial_velocity", kRequired),
    field<InDynamic, &DynamicBlock::initial_velocity_direction>("initial_velocity_direction", kRequired),
    field<InDynamic, &DynamicBlock::paddle_compliance>("paddle_compliance", kRequired),
    field<InDynamic, &DynamicBlock::paddle_damping>("paddle_damping", kRequired),
    field<InDynamic, &DynamicBlock::gravity>("gravity", kRequired),
    kInterim,
};

constexpr FieldSpec kControlLawBlock[] = {kInterim};

constexpr FieldSpec kControlLaw[] = {
    field<ControlLawAt, &ControlLawBlock::mass>("mass", kRequired),
    field<ControlLawAt, &ControlLawBlock::k_pos>("k_pos", kRequired),
    field<ControlLawAt, &ControlLawBlock::k_neg>("k_neg", kRequired),
    field<ControlLawAt, &ControlLawBlock::b>("b", kOptional),
    field<ControlLawAt, &ControlLawBlock::vel_init>("vel_init", kOptional),
    field<ControlLawAt, &ControlLawBlock::pos_init>("pos_init", kOptional),
    field<ControlLawAt, &ControlLawBlock::half_cycles>("half_cycles", kOptional),
    field<ControlLawAt, &ControlLawBlock::length>("length", kOptional),
    field<ControlLawAt, &ControlLawBlock::drag>("drag", kOptional),
    field<ControlLawAt, &ControlLawBlock::gravity>("gravity", kOptional),
};

constexpr FieldSpec kEnvelope[] = {
    // The primer's names (§6.4); DirectInput and evdev call them attack level and time.
    field<InEnvelope, &Envelope::impulse_level>("impulse_level", kRequired, {}, "attack_level"),
    field<InEnvelope, &Envelope::settle_time_us>("settle_time_us", kRequired, {}, "attack_time_us"),
    field<InEnvelope, &Envelope::fade_level>("fade_level", kOptional),
    field<InEnvelope, &Envelope::fade_time_us>("fade_time_us", kOptional),
};

constexpr std::string_view kBlockKeys[] = {"periodic", "constant", "ramp",    "custom", "conditions",
                                           "texture",  "wall",     "barrier", "dynamic"};

}  // namespace

BlockLayout block_layout(EffectType t) noexcept {
    if (is_periodic(t)) return {"periodic", BlockShape::object, kPeriodic};
    if (is_sweep(t)) return {"periodic", BlockShape::object, kSweep};
    switch (t) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction: return {"conditions", BlockShape::per_axis, kCondition};
        case EffectType::angle_spring: return {"conditions", BlockShape::one_block, kCondition};
        case EffectType::texture: return {"texture", BlockShape::object, kTexture};
        case EffectType::axis_wall: return {"wall", BlockShape::object, kAxisWall};
        case EffectType::angle_wall: return {"wall", BlockShape::object, kAngleWall};
        case EffectType::axis_barrier: return {"barrier", BlockShape::object, kAxisBarrier};
        case EffectType::angle_barrier: return {"barrier", BlockShape::object, kAngleBarrier};
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop: return {"constant", BlockShape::object, kConstant};
        case EffectType::ramp: return {"ramp", BlockShape::object, kRamp};
        case EffectType::force_profile: return {"custom", BlockShape::object, kCustom, BlockExtra::samples};
        case EffectType::dynamic_recoil: return {"dynamic", BlockShape::object, kRecoil};
        case EffectType::dynamic_impact: return {"dynamic", BlockShape::object, kImpact};
        case EffectType::dynamic_liquid: return {"dynamic", BlockShape::object, kLiquid};
        case EffectType::dynamic_inertia: return {"dynamic", BlockShape::object, kDynamicInertia};
        case EffectType::dynamic_center_drift: return {"dynamic", BlockShape::object, kCenterDrift};
        case EffectType::dynamic_sling: return {"dynamic", BlockShape::object, kSling};
        case EffectType::dynamic_paddle: return {"dynamic", BlockShape::object, kPaddle};
        case EffectType::dynamic_control_law:
            return {"dynamic", BlockShape::object, kControlLawBlock, BlockExtra::control_law};
        default: break;  // the periodic and sweep types returned above
    }
    return {"periodic", BlockShape::object, kPeriodic};
}

std::span<const FieldSpec> control_law_fields() noexcept { return kControlLaw; }
std::span<const FieldSpec> envelope_fields() noexcept { return kEnvelope; }
std::span<const std::string_view> all_block_keys() noexcept { return kBlockKeys; }

}  // namespace feel::format::detail
