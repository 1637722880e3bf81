// What the example programs share: expectations that print and count, a wait with a
// deadline, and a simulated device whose buttons the program can press.
//
// The examples run on feel's in-process simulated device, so they need no hardware. To
// press a button on it (the player pulling the trigger), SimRig builds the Peripheral
// itself and attaches the host to it, keeping the Peripheral to press its buttons and hats;
// a program on real hardware would open its address and the player would press them.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "feel/host/device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/transport/transport.hpp"

namespace example {

using namespace std::chrono_literals;

// Counts failed expectations; main() returns nonzero when there is one.
inline int failures = 0;

// Prints "ok   what" or "FAIL what" and remembers a failure.
inline bool expect(bool condition, const std::string& what) {
    std::printf("%s %s\n", condition ? "ok  " : "FAIL", what.c_str());
    if (!condition) ++failures;
    return condition;
}

// ": <message>" for a failed Status, "" for a good one: appended to an expectation's text.
inline std::string because(const feel::host::Status& status) {
    return status.ok() ? std::string() : ": " + status.message;
}

inline int exit_code() {
    std::printf(failures == 0 ? "all expectations met\n" : "%d expectation(s) failed\n", failures);
    return failures == 0 ? 0 : 1;
}

// Polls `done` every 2 ms until it holds or `limit` passes; returns whether it held.
inline bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds limit = 2000ms) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return done();
}

// The device fades its forces in when a host attaches (a safety measure); measurements
// of force wait until it is done.
inline bool wait_for_full_force(feel::host::Device& device) {
    return wait_until([&] { return device.input().fade_level >= 0.999f && device.input().handle_held; }, 3000ms);
}

// A simulated device served in process, with its buttons within reach.
struct SimRig {
    std::unique_ptr<feel::peripheral::Peripheral> peripheral;
    std::unique_ptr<feel::host::Device> device;  // closed before the peripheral goes

    static SimRig open(const std::string& profile, const std::string& hand = "firm",
                       const std::string& motion = "hold:0") {
        feel::peripheral::PeripheralOptions options;
        options.profile = profile;
        options.hand = hand;
        options.motion = motion;
        options.runtime.realtime_priority = false;  // an example needs no SCHED_FIFO
        options.runtime.lock_memory = false;
        SimRig rig;
        rig.peripheral = std::make_unique<feel::peripheral::Peripheral>(options);
        feel::transport::ConnectionPair pair = feel::transport::in_process_pair("sim:" + profile);
        rig.peripheral->attach(std::move(pair.device));
        feel::host::Result<feel::host::Device> opened =
            feel::host::Device::attach(std::move(pair.host), "sim:" + profile);
        if (!opened) {
            expect(false, "open sim:" + profile + ": " + opened.status().message);
            return rig;
        }
        rig.device = std::make_unique<feel::host::Device>(std::move(opened).value());
        return rig;
    }

    ~SimRig() {
        if (device) device->close();
    }
    SimRig() = default;
    SimRig(SimRig&&) noexcept = default;
    SimRig& operator=(SimRig&&) noexcept = default;

    // The simulated hand presses buttons (bit i = button i+1) and pushes hat switches
    // (bit h-1 = hat h); the device sees it at its next tick.
    bool set_buttons(uint32_t mask) { return peripheral->set_buttons(mask); }
    bool set_hats(uint32_t mask) { return peripheral->set_hats(mask); }
};

}  // namespace example
