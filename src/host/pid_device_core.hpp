// The state a PidDevice shares with its I/O thread (private to src/host; the design is at
// the top of pid_device.cpp). pid_device_core.cpp holds the I/O thread's loop and the
// send/get primitives the calls use.
#pragma once

#include <atomic>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "emulation/pid_emulation.hpp"
#include "emulation/sense_clock.hpp"
#include "emulation/trigger_watch.hpp"
#include "feel/host/pid_device.hpp"
#include "feel/protocol/pid_effect_reports.hpp"
#include "feel/transport/transport.hpp"

namespace feel::host {

struct PidDeviceCore {
    using PidLayout = protocol::pid::PidLayout;
    using PidReport = protocol::pid::PidReport;
    using Frame = transport::Frame;
    using FrameKind = transport::FrameKind;

    PidDeviceCore(std::unique_ptr<transport::Connection> c, std::string name, OpenOptions o)
        : connection(std::move(c)), address(std::move(name)), options(std::move(o)) {}
    ~PidDeviceCore() { close(); }

    std::unique_ptr<transport::Connection> connection;
    const std::string address;
    const OpenOptions options;
    // Read from the descriptor by attach() while the I/O thread already runs (it has to, to
    // receive the descriptor), and never changed after: the I/O thread reads no Input
    // report until layout_known says it is set (ThreadSanitizer found the race).
    PidLayout layout;
    std::atomic<bool> layout_known{false};
    PidCaps caps;

    std::mutex call_mu;  // one caller at a time
    mutable std::mutex mu;
    std::condition_variable cv;
    // Guarded by mu.
    bool connected = true;
    std::string gone_reason;
    FrameKind wanted_kind = FrameKind::busy;  // busy: nothing awaited
    int wanted_id = -1;
    std::optional<std::vector<uint8_t>> reply;
    // The device's effects this host made: their parameters as the caller gave them (with a
    // trigger the host runs, which the device was not told), and a force profile's samples.
    struct DeviceEffect {
        EffectParams params;
        std::vector<int16_t> samples;
    };
    std::map<uint16_t, DeviceEffect> effects;
    // Triggers the device cannot run (no Trigger Button, a hat): the host starts the block on
    // the Input report's buttons and hats (emulation/trigger_watch.hpp).
    emulation::TriggerWatch<uint16_t> host_triggers;
    uint32_t buttons = 0, hats = 0;  // the last Input report's
    std::shared_ptr<emulation::PidEmulation> emulation;  // host emulation, once its link exists
    std::set<uint16_t> link_blocks;                      // the link's Constant Force effects
    uint16_t next_handle = PidDevice::kHostHandleBase;

    std::mutex send_mu;       // both threads send
    std::mutex emulation_mu;  // one link set-up at a time
    PidDevice::HostClock clock;

    std::thread io;
    std::atomic<bool> stopping{false};
    std::vector<uint16_t> fired;  // the I/O thread's: blocks whose host-run trigger fired
    // The I/O thread's: the Input reports of one drain (read back to back), their read
    // times and their sense times (emulation/sense_clock.hpp).
    std::vector<protocol::pid::JoystickReading> drain;
    std::vector<int64_t> drain_arrivals, drain_sense;
    emulation::SenseClock sense_clock;
    PidDevice::EmulationObserver emulation_observer;  // guarded by mu

    void start();

    std::shared_ptr<emulation::PidEmulation> emulation_now();

    // Files a reply, or keeps an Input report for the drain's render (render_drain). False
    // when the connection is lost to another host.
    bool handle(Frame& f);

    // The Input reports read back to back: each gets its sense time from the report sequence
    // (emulation/sense_clock.hpp), then, in order, runs the host's reflexes and, while host
    // emulation runs, a render of the host's engine at that time. Returns whether it rendered.
    bool render_drain(emulation::PidEmulation* em);

    // The observer's record of the drain's renders (the levels sent go with the last).
    // `stall_at`: a stall render's positions (the last reading, which it rendered on).
    void observe(const std::vector<std::pair<uint16_t, int32_t>>& sent, bool stalled, int64_t stall_us,
                 const protocol::pid::JoystickReading& stall_at = {});

    // The force's Set Constant Force reports, fire and forget; returns what went.
    std::vector<std::pair<uint16_t, int32_t>> send_due(emulation::PidEmulation& em);

    void run() noexcept;

    // Effect Operation Start for each block whose host-run trigger fired, with the effect's
    // own loop count, fire and forget (as the device's own reflex would start it).
    void start_fired();

    // The samples' format for this device: feel's on a feel device.
    protocol::pid::ProfileSamples samples_of(std::span<const int16_t> values) const;

    // What the device is told: the caller's parameters without a trigger the host runs.
    EffectParams for_device(const EffectParams& params) const;

    // Arms (or disarms) the host's run of a device block's trigger. Caller holds mu.
    void arm_host_trigger(uint16_t block, const EffectParams& params);

    void mark_gone(std::string why);

    Status gone(const std::string& what) const;

    Status send(FrameKind kind, std::vector<uint8_t> bytes, const std::string& what);

    // A get: sends `request`, waits for the reply of that kind (and report id).
    Result<std::vector<uint8_t>> get(FrameKind request, FrameKind reply_kind, int id, const std::string& what);

    Result<std::vector<uint8_t>> get_feature(PidReport r, const std::string& what);

    void close() noexcept;
};

}  // namespace feel::host
