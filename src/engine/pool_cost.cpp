// The parameter memory's cost table (§2.2): how many bytes each effect holds.
//
// A device's local memory stores the parameters the host downloads: an Effect Structure
// for every effect, an Envelope Struct when it has one, the Type Specific Structs, and the
// samples of a force profile (§6.3, §6.6). The sizes follow the I-FORCE protocol where it
// has a block (pool_cost in feel/engine.hpp); the blocks it lacks count their 16-bit
// fields. The result does not depend on the device or on the values inside the blocks,
// only on which blocks the effect holds, so a host can plan its downloads in advance.
#include "feel/engine.hpp"

#include <algorithm>

#include "engine_impl.hpp"

namespace feel {

namespace {

template <class Params>
int32_t type_specific_bytes(const Params& p) noexcept {
    if (is_periodic(p.type)) return pool_cost::kPeriodic;
    if (is_sweep(p.type)) return pool_cost::kAdvancedPeriodic;
    switch (p.type) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction: return pool_cost::kCondition * p.axis_count;
        case EffectType::angle_spring: return pool_cost::kCondition;  // one block, along its angle
        case EffectType::texture: return pool_cost::kTexture;
        case EffectType::axis_wall:
        case EffectType::angle_wall: return pool_cost::kWall;
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: return pool_cost::kBarrier;
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop: return pool_cost::kConstant;
        case EffectType::ramp: return pool_cost::kRamp;
        case EffectType::force_profile:
            return pool_cost::kCustom + pool_cost::kSample * std::max<int32_t>(p.custom.sample_count, 0);
        default: break;
    }
    // Dynamic Sensations: the device keeps what the §8.4 table maps them to, one control
    // law per axis of the effect.
    if (effect_class(p.type) == EffectClass::dynamic) return pool_cost::kDynamicAxis * p.axis_count;
    return 0;
}

// Of an EffectParams or a slot's SlotParams (the same field names).
template <class Params>
int32_t parameter_bytes(const Params& p) noexcept {
    return pool_cost::kEffect + (p.has_envelope ? pool_cost::kEnvelope : 0) + type_specific_bytes(p);
}

}  // namespace

int32_t effect_pool_bytes(const EffectParams& params) noexcept { return parameter_bytes(params); }

int32_t detail::slot_pool_bytes(const SlotParams& params) noexcept { return parameter_bytes(params); }

int64_t detail::pool_capacity_bytes(const EngineConfig& c) noexcept {
    if (c.pool_bytes != 0) return c.pool_bytes;
    // The largest effect without samples: a six-axis dynamic (or a profile's fixed blocks
    // with an envelope, if ever larger), so that any max_effects effects fit at once.
    constexpr int32_t kLargestFixed =
        pool_cost::kEffect + std::max(pool_cost::kDynamicAxis * kMaxAxes,
                                      pool_cost::kEnvelope + std::max(pool_cost::kCondition * kMaxAxes, pool_cost::kCustom));
    return static_cast<int64_t>(c.max_effects) * kLargestFixed +
           static_cast<int64_t>(pool_cost::kSample) * c.max_samples;
}

}  // namespace feel
