// Which effect types the device plays (EngineConfig::supported_types): the engine's side of
// EnumEffects (§6.2). A device of an older class lacks whole classes of effects (the
// I-FORCE 1.x core has no Dynamics, §5.1); the engine refuses them at create() instead of
// playing something the device it stands for could not.
#pragma once

#include "feel/effect_type.hpp"
#include "feel/engine.hpp"
#include "feel/status.hpp"

namespace feel::detail {

// ok when the config's device plays `type`; otherwise ErrorCode::not_supported with the
// field "type NAME on CLASS" (e.g. "type dynamic_recoil on I-FORCE 1.x") and a rule saying
// why. Never allocates.
[[nodiscard]] Error check_supported(const EngineConfig& config, EffectType type) noexcept;

// ok when supported_types names only the kEffectTypeCount effect types.
[[nodiscard]] Error check_supported_types(const EngineConfig& config) noexcept;

}  // namespace feel::detail
