// Which effects the host renders, and with what engine (emulation_config.hpp).
#include "emulation_config.hpp"

#include "feel/sim/device_profile.hpp"

namespace feel::host::emulation {

bool host_renders(const DeviceCaps& caps, EffectType type) noexcept {
    return !caps.supports(type) && caps.axis_count >= 1;
}

EngineConfig host_engine_config(const DeviceCaps& caps) noexcept {
    EngineConfig c;
    if (const sim::DeviceProfile* profile = sim::find_device_profile(caps.device)) {
        c = sim::engine_config_for(*profile);
    } else if (caps.axes[0].sensor_counts > 0) {
        c.sensor_step = static_cast<float>(2.0 * kFullScale / caps.axes[0].sensor_counts);
    }
    c.axis_count = caps.axis_count;
    c.max_effects = 64;
    c.max_samples = 1 << 16;
    c.pool_bytes = 0;
    c.supported_types = kAllEffectTypes;
    c.device_class = {};
    return c;
}

}  // namespace feel::host::emulation
