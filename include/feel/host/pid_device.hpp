// feel::host — the host API on any USB HID PID force-feedback device.
//
// Device (device.hpp) speaks feel's protocol: PID plus feel's vendor reports (sequence
// numbers, answers, Dynamics, walls, device info). A wheel or stick from anywhere speaks
// PID alone, in its own layout. PidDevice drives those: it reads the device's own report
// descriptor, maps it (protocol::pid::PidLayout: report IDs, fields, logical ranges, as
// Linux's hid-pidff does), and plays every effect type the descriptor lists natively, with
// the reports a standard PID host sends (pid_effect_reports.hpp). It sends feel's vendor
// reports never: on a feel device Device gives all of feel (capabilities().feel_device
// says when).
//
//   auto wheel = feel::host::PidDevice::open("usb:1209:ffb0");   // or "hidraw:/dev/hidraw3"
//   if (!wheel) { log(wheel.status().message); return; }
//   auto block = wheel->create_effect(feel::iforce::x_spring(...));
//   wheel->start(*block);
//
// What the device supports is in capabilities(): its effect types from the descriptor
// (which a host emulation layer may complete), and its pool from the PID Pool report.
//
// A standard PID device answers no command: the host knows an effect is loaded from PID
// Block Load (after Create New Effect) and that is all it can know. Everything else is
// checked before it is sent (validate_effect, then the device's field ranges), and a
// refused value is an error naming the field and what the device can hold.
//
// Host emulation (§1.2.c). A type the device does not play (walls, barriers, textures,
// sweeps, smart pops, Dynamics: feel's types PID has no usage for, and PID's own that the
// descriptor leaves out) is rendered by feel's engine on the host, on the positions the
// device's Input report carries, and streamed to the device as the level of a Constant
// Force effect per axis (src/host/emulation/pid_emulation.hpp). Its handle is
// kHostHandleBase or above, emulated(handle) is true and status(handle) says "emulated"
// while it plays. docs/real-devices.md, "Host emulation", has the limits. Reflexes the
// device cannot run (a hat trigger, no Trigger Button in Set Effect, a host-rendered
// effect's) are run by the host on the Input report's buttons and hats
// (emulation/trigger_watch.hpp; trigger_emulated(handle)).
//
// Threads. One thread at a time (calls are serialized inside). An I/O thread reads the
// device's input reports, hands feature replies to the waiting call, and runs host
// emulation's updates.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "feel/effect.hpp"
#include "feel/host/device.hpp"
#include "feel/host/result.hpp"
#include "feel/protocol/pid_effect_reports.hpp"
#include "feel/protocol/pid_layout.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/transport/hidraw.hpp"

namespace feel::host {

struct PidDeviceCore;  // private
namespace emulation {
class PidEmulation;
}

struct PidCaps {
    std::string address;
    bool feel_device = false;     // its descriptor is feel's protocol: Device::open gives all of feel
    uint64_t supported_types = 0; // effect_type_bit(t) of every type the device plays itself
    std::vector<protocol::pid::EffectTypeEntry> effect_types;  // as its descriptor lists them
    std::vector<Axis> axes;       // Set Effect's Axes Enable
    int32_t max_effects = 0;      // PID Pool's Simultaneous Effects Max, else the block index range
    int32_t pool_bytes = 0;       // PID Pool's RAM Pool Size, bytes; 0 when the device does not say
    bool device_managed_pool = true;
    bool has_pool_report = false;
    std::vector<Axis> input_axes;  // the axes the Input report carries positions of
    // The types the host renders here (host emulation): every type the device does not
    // play, when it can (positions in its Input report, a Constant Force to stream through,
    // an axis both report and force); else 0 and `emulation_problem` says why.
    uint64_t emulated_types = 0;
    std::string emulation_problem;
    // The feel profile whose mechanism the host's engine assumes (sim:PROFILE, or a HID name
    // "feel PROFILE"); empty: the engine's defaults.
    std::string profile;

    [[nodiscard]] bool supports(EffectType t) const noexcept { return (supported_types & effect_type_bit(t)) != 0; }
};

// Host emulation's figures (PidDevice::emulation_stats()).
struct PidEmulationStats {
    bool active = false;        // the link's Constant Force effects exist
    int64_t updates = 0;        // renders of the host's engine (one per Input report, or stall)
    int64_t levels_sent = 0;    // Set Constant Force reports sent
    std::vector<uint16_t> link_blocks;  // the device's Constant Force effect per force axis
};

// One render of host emulation, for an observer (PidDevice::observe_emulation): what the
// host rendered from. The sense time is the report's, reconstructed from the report
// sequence (src/host/emulation/sense_clock.hpp), on the host clock shifted by the link's
// least delay; the arrival is when the host read it.
struct PidEmulationUpdate {
    int64_t arrival_us = 0;  // HostClock
    int64_t sense_us = 0;    // HostClock frame
    float position[kMaxAxes] = {};  // the report's positions, normalized
    bool stalled = false;    // a render on the last positions: the device was silent
    // The Set Constant Force levels sent after this render ((block, level); the last
    // render of a drain carries them).
    std::vector<std::pair<uint16_t, int32_t>> sent;
};

class PidDevice {
public:
    // Handles of host-rendered effects start here (device blocks are below it).
    static constexpr uint16_t kHostHandleBase = 0x8000;
    // The clock host emulation stamps updates with, µs (default: the steady clock). Tests
    // give the simulated device's time.
    using HostClock = std::function<int64_t()>;
    // Called on the I/O thread after each render of host emulation (keep it short).
    using EmulationObserver = std::function<void(const PidEmulationUpdate&)>;

    // Opens "hidraw:/dev/hidrawN", "usb:VID:PID[:SERIAL]", or any of Device::open's
    // addresses (sim:, unix:, tcp: — a feel device driven as a standard PID one). Reads the
    // descriptor and maps it, then reads PID Pool. Errors: invalid_parameter (bad address),
    // disconnected (absent, no permission — the message has the udev rule — or gone),
    // not_supported (not a PID device, or one without the reports a host needs), timeout.
    [[nodiscard]] static Result<PidDevice> open(std::string_view address, const OpenOptions& options = {});
    [[nodiscard]] static Result<PidDevice> attach(std::unique_ptr<transport::Connection> connection, std::string name,
                                                  const OpenOptions& options = {});
    [[nodiscard]] static Result<PidDevice> attach(std::unique_ptr<transport::Connection> connection, std::string name,
                                                  const OpenOptions& options, HostClock clock);

    [[nodiscard]] const PidCaps& capabilities() const noexcept;
    [[nodiscard]] const protocol::pid::PidLayout& layout() const noexcept;
    [[nodiscard]] std::string address() const;

    // Create New Effect, PID Block Load, then the effect's reports. Returns the device's
    // effect block. A type the device does not play is rendered by the host (its handle is
    // kHostHandleBase or above; the first one creates the force link's Constant Force
    // effects); not_supported when the host cannot (capabilities().emulation_problem);
    // device_full when Block Load says full; invalid_parameter naming the field otherwise.
    //
    // A force profile (PID's custom force) comes with its samples: played by the device when
    // its descriptor has Set Custom Force, Custom Force Data and a sample format (Download
    // Force Sample), else rendered by the host. A trigger (a reflex) is run by the device
    // when Set Effect has a Trigger Button and the trigger is a button; otherwise the host
    // runs it on the Input report's buttons and hats (trigger_emulated()).
    [[nodiscard]] Result<uint16_t> create_effect(const EffectParams& params, std::span<const int16_t> samples = {});
    // Sends the effect's reports again with new parameters (the same type; a force profile's
    // samples again).
    Status set_effect(uint16_t block, const EffectParams& params, std::span<const int16_t> samples = {});
    // iterations: runtime::kEffectIterations (0) for the effect's own, 1.., or
    // kInfiniteIterations. solo: Op Effect Start Solo.
    Status start(uint16_t block, int32_t iterations = runtime::kEffectIterations, bool solo = false);
    Status stop(uint16_t block);
    Status free_effect(uint16_t block);
    Status set_gain(int32_t gain);                   // 0..10000
    Status command(runtime::DeviceControl control);  // PID Device Control
    [[nodiscard]] Result<protocol::pid::Pool> pool();
    // The blocks and host handles this host created and has not freed (not the force
    // link's own Constant Force effects).
    [[nodiscard]] std::vector<uint16_t> effects() const;
    // Whether `handle` is a host-rendered effect.
    [[nodiscard]] bool emulated(uint16_t handle) const noexcept { return handle >= kHostHandleBase; }
    // A host-rendered effect's status ("emulated" while it plays). A device block whose
    // trigger the host runs (trigger_emulated()) says "emulated" with its iterations: the
    // host starts it on each press; the device tells no more. A standard PID device tells a
    // host nothing per effect: not_supported for any other device block.
    [[nodiscard]] Result<EffectStatusInfo> status(uint16_t handle);
    [[nodiscard]] PidEmulationStats emulation_stats() const;
    // Sets (or, empty, removes) the observer of host emulation's renders.
    void observe_emulation(EmulationObserver observer);
    // Whether the host runs `handle`'s trigger (its state is "emulated"): a host-rendered
    // effect's, a hat trigger, or a button on a device whose Set Effect has no Trigger Button.
    [[nodiscard]] bool trigger_emulated(uint16_t handle) const;

    [[nodiscard]] bool connected() const noexcept;
    // Frees this host's effects, closes the connection. Harmless twice.
    void close();

private:
    explicit PidDevice(std::shared_ptr<PidDeviceCore> core) : core_(std::move(core)) {}
    struct HostEffect {
        std::shared_ptr<emulation::PidEmulation> em;
        EffectId id{};
    };
    [[nodiscard]] Result<HostEffect> host_effect(uint16_t handle, const std::string& what) const;
    [[nodiscard]] Status check_emulable(const EffectParams& params, const emulation::PidEmulation& em,
                                        const std::string& what);
    [[nodiscard]] Result<std::shared_ptr<emulation::PidEmulation>> ensure_link(const std::string& what);
    [[nodiscard]] Result<uint16_t> create_emulated(const EffectParams& params, std::span<const int16_t> samples,
                                                   const std::string& what);
    std::shared_ptr<PidDeviceCore> core_;
};

// A HID PID device present on this machine (the hidraw nodes whose report descriptor uses
// the PID page, 0x0F).
struct PidDeviceInfo {
    std::string address;      // "hidraw:/dev/hidraw3"
    std::string usb_address;  // "usb:1209:ffb0" (with ":SERIAL" when it has one); empty off USB
    std::string name;
    uint16_t vendor_id = 0, product_id = 0;
    bool feel_device = false;       // speaks feel's protocol (Device::open)
    uint64_t supported_types = 0;   // from its descriptor; 0 with `problem` when unusable
    std::string problem;            // why PidDevice cannot drive it (empty: it can)
};
[[nodiscard]] std::vector<PidDeviceInfo> enumerate_pid_devices(const transport::HidrawRoots& roots = {});

}  // namespace feel::host
