// feel::host::emulation — which effects the host renders for a device, and the engine
// configuration it renders them with.
#pragma once

#include "feel/engine.hpp"
#include "feel/host/device.hpp"

namespace feel::host::emulation {

// Whether the host renders effects of this type on this device: the device does not play
// the type itself, and it reports positions on at least one axis for the host's engine
// to read. Every one of feel's types is then renderable: the engine plays them all.
[[nodiscard]] bool host_renders(const DeviceCaps& caps, EffectType type) noexcept;

// The engine the host runs for `caps`. A device whose name is one of feel's built-in
// profiles gets that profile's configuration (sim::engine_config_for: its mechanism's
// damping and sensor step, which the passivity controller reads, the stiffness of a
// hardness-10000 wall, the Dynamics' scales), so a host-rendered sensation means what the
// same sensation means on the device. Any other device gets the engine's defaults (the
// joystick's scales) on its own axis count and sensor resolution, with the passivity
// controller on. Either way the host's engine plays every type, holds 64 effects and
// 65536 samples, and its gain stays 10000 (the device's gain scales the streamed force).
[[nodiscard]] EngineConfig host_engine_config(const DeviceCaps& caps) noexcept;

}  // namespace feel::host::emulation
