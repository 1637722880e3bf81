// feel::studio — the device the Studio plays on, shared by every browser session.
//
// For a simulated address ("sim:PROFILE", or a bare profile name) the Studio builds the
// simulated device itself (a peripheral::Peripheral on an in-process transport) so that it
// can reach the simulated hand: the handle pad moves the hand's target, the hand menu
// changes its grip, the trigger palette presses its buttons. Any other address is opened
// through the host API exactly as `feel play --device` opens it; then the hand is a real
// person's and those calls answer false.
//
// A sampler thread records every state report the device sends (position and force per
// axis), through the host API's per-report subscription (Device::subscribe_input), into a
// bounded ring; each browser session reads what is new since its last frame.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "feel/host/device.hpp"

namespace feel::peripheral {
class Peripheral;
}

namespace feel::studio {

struct StudioDeviceOptions {
    std::string address = "sim:iforce2";  // everything `feel play --device` takes
    std::string grip = "firm";            // loose, firm, stiff (simulated devices)
    // State reports the plot and the pad get, 100..1000 Hz; 0: one per tick of the device's
    // loop (up to 1000 Hz), so that a pointer move's force change is reported at the tick
    // that makes it, not up to a report period later (docs/studio.md, "Latency").
    int32_t report_rate_hz = 0;
    // The three threads on a state report's way to the page's pad and plot (the simulated
    // device's service thread, the host's I/O thread, the sampler below) run under
    // SCHED_FIFO at this priority where the process may, below the device loop's 80; 0:
    // ordinary threads. Without it, each wake-up waits for a slice while the browser holds a
    // core (docs/studio.md, "Tenth pass"). 1..99 or 0.
    int32_t report_path_fifo_priority = 10;
};

// One state report: device time, force and position per axis (±10000).
struct DeviceSample {
    uint64_t seq = 0;
    int64_t t_us = 0;
    int32_t axis_count = 0;
    float force[kMaxAxes] = {};
    float position[kMaxAxes] = {};
    uint32_t buttons = 0;
    float fade_level = 1;    // the device's safety fade, 0..1 (below 1: forces faded)
    bool hands_off = false;  // the device judged the handle free: forces fade out
    int64_t host_us = 0;  // steady_clock µs when the sampler took it (the latency hops)
};

class StudioDevice {
public:
    // Throws std::runtime_error naming the address and the device's error.
    explicit StudioDevice(const StudioDeviceOptions& options);
    ~StudioDevice();
    StudioDevice(const StudioDevice&) = delete;
    StudioDevice& operator=(const StudioDevice&) = delete;

    [[nodiscard]] host::Device& device() noexcept { return *device_; }
    [[nodiscard]] bool simulated() const noexcept { return peripheral_ != nullptr; }
    // Capabilities for the browser: name, class, axes, buttons, hats, the types the device
    // enumerates (EnumEffects) by class.
    [[nodiscard]] nlohmann::json describe() const;
    [[nodiscard]] std::string grip() const;

    // The simulated hand (false on a device in another process, or for a bad value).
    bool set_hand_target(int32_t x, int32_t y);
    // The device time (µs) at which the simulated device's loop took the newest hand
    // target; -1 before the first, or for a device in another process.
    [[nodiscard]] int64_t hand_target_taken_us() const noexcept;
    bool set_grip(const std::string& grip);
    bool set_buttons(uint32_t pressed);
    bool set_hats(uint32_t pushed);

    // The samples newer than `after` (a seq), oldest first, at most the ring's size.
    [[nodiscard]] std::vector<DeviceSample> samples_after(uint64_t after) const;
    [[nodiscard]] uint64_t newest_seq() const;
    // The newest sample (seq 0 before the first report).
    [[nodiscard]] DeviceSample newest() const;
    // Reports the sampler's subscription lost because its queue was full (0 unless this
    // process was kept from running for longer than the queue lasts).
    [[nodiscard]] uint64_t dropped_reports() const;

    static constexpr size_t kRingSize = 4096;
    static constexpr size_t kSubscriptionRounds = 2048;

private:
    void sample_loop();

    std::shared_ptr<peripheral::Peripheral> peripheral_;  // simulated devices only
    std::optional<host::Device> device_;  // set by the constructor
    mutable std::mutex mu_;
    std::string grip_;
    std::vector<DeviceSample> ring_;  // kRingSize, indexed by seq % kRingSize
    uint64_t next_seq_ = 1;
    uint64_t dropped_ = 0;
    std::atomic<bool> stopping_{false};
    std::thread sampler_;
};

}  // namespace feel::studio
