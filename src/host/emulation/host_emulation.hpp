// feel::host::emulation — HostEmulation: the host-rendered effects of one open device,
// wired to its DeviceCore.
//
// Design. An effect whose type the device does not play (emulation_config.hpp) is created
// in the host's HostRenderer instead of in a device block; its EffectRecord says
// `host_rendered` and holds the renderer's EffectId. The Effect's calls (download,
// unload, start, stop, status, set_parameters) come here instead of going to the device
// (the functions below; the caller holds DeviceCore::call_mu, as for a device effect).
//
// The loop is closed on the I/O thread: every Joystick Input report is one update. Its
// positions, buttons and hats, at the host's steady clock (a standard device's reports
// carry no time), go through the renderer, and the force comes back to the device as one
// sample on the force link (force_link.hpp), fire and forget. So the update rate is the
// device's report rate, which create raises to the most the device allows (the highest
// rate the link sustains), and the loop's lag is one report's trip up plus one sample's
// trip down. While no host-rendered effect plays nothing is sent, except one zero force
// when the last one stops (a streaming device holds the last sample).
//
// Triggers. The host engine runs no reflexes (they are the device runtime's), so a
// host-rendered effect with a trigger is started here on each press edge, and every
// trigger_repeat_interval_us while held, like DeviceCore's emulated reflexes.
//
// Locks: `mu` guards the renderer and the trigger states. The caller's thread holds
// DeviceCore::call_mu; under it, mu may be held while DeviceCore::mu is taken (to file the
// renderer's id in the record), never the reverse. The I/O thread takes mu alone and
// sends after releasing it.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "emulation/force_link.hpp"
#include "emulation/host_renderer.hpp"
#include "emulation/trigger_watch.hpp"
#include "feel/host/device.hpp"
#include "feel/protocol/reports.hpp"

namespace feel::host {
struct DeviceCore;
struct EffectRecord;
}  // namespace feel::host

namespace feel::host::emulation {

class HostEmulation {
public:
    HostEmulation(const DeviceCaps& caps, ForceLinkKind link);

    // The I/O thread, once per Joystick Input report: renders and, when a force is due,
    // returns it (normalized ±10000 per device axis) in `force`. The dynamics' interim and
    // final reports this render produced are appended to `reports`.
    bool update(std::chrono::steady_clock::time_point now, const protocol::JoystickInputReport& report,
                int32_t force[kMaxAxes], std::vector<DynamicReport>& reports);

    std::mutex mu;
    HostRenderer renderer;                          // guarded by mu
    TriggerWatch<EffectId> triggers;                // by record key; guarded by mu
    std::vector<EffectId> fired;                    // update()'s triggers that fired; guarded by mu
    const ForceLinkKind link;
    ForceLinkState link_state;                       // the I/O thread's alone
    const std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
    bool was_playing = false;                        // guarded by mu
    int32_t axis_count = 0;

    [[nodiscard]] int64_t now_us(std::chrono::steady_clock::time_point t) const noexcept;
};

// The core's HostEmulation, made at the first host-rendered effect (caller holds call_mu).
// Also raises the report rate to the device's most. Fails when the device cannot take a
// host's force (no axes, no way to send one).
Result<std::shared_ptr<HostEmulation>> emulation_of(DeviceCore& core, const std::string& what);

// Effect calls on a host-rendered record (the caller holds core.call_mu).
Status download(DeviceCore& core, EffectRecord& record, const std::string& what);
Status unload(DeviceCore& core, EffectRecord& record);
Status start(DeviceCore& core, EffectRecord& record, int32_t iterations, bool solo, const std::string& what);
Status stop(DeviceCore& core, EffectRecord& record, const std::string& what);
Result<EffectStatusInfo> status(DeviceCore& core, EffectRecord& record, const std::string& what);
Status update(DeviceCore& core, EffectRecord& record, const EffectParams& merged, std::span<const int16_t> samples,
              uint32_t field_mask, bool restart, const std::string& what);
// A device command succeeded: stop_all, reset, pause and continue apply to the host's
// effects too (reset frees them, like the device's blocks).
void on_device_command(DeviceCore& core, runtime::DeviceControl control);

// The I/O thread, per Joystick Input report (no lock held).
void on_joystick(DeviceCore& core, const protocol::JoystickInputReport& report);

}  // namespace feel::host::emulation
