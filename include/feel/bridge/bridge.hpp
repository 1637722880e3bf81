// feel::bridge — a feel device as a Linux force-feedback joystick (`feel bridge`,
// docs/real-devices.md).
//
// The bridge makes a virtual input device through uinput whose axes and buttons are the
// feel device's and whose EV_FF capabilities are the effects it plays. Every Linux game
// that drives a force-feedback joystick through evdev (SDL's haptic, Wine and Proton's
// DirectInput, fftest) then drives the feel device: its effects are translated to feel
// effects with the same units and direction mapping as feel's USB device gets from the
// kernel's hid-pidff, and the device's positions and buttons come back as input events.
//
//   game --evdev ioctls--> kernel ff-core --uinput--> feel bridge --host API--> feel device
//        <--EV_ABS/EV_KEY--                <--------              <--input reports--
//
// Linux only (the translation and the effect table are portable and unit tested; the
// uinput backend is tested in the VM of tests/linux).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

#include "feel/host/device.hpp"

namespace feel::bridge {

struct BridgeOptions {
    std::string uinput_path = "/dev/uinput";
    std::string name;           // the input device's name; empty: "feel <profile> (bridge)"
    int32_t input_poll_ms = 4;  // how often the device's state is turned into events, 1..100
    bool verbose = false;       // `say` one line per request of the kernel (what the game asked)
};

struct BridgeStats {
    uint64_t uploads = 0;          // UI_FF_UPLOAD requests
    uint64_t uploads_refused = 0;  // of those answered with an error
    uint64_t erases = 0;
    uint64_t plays = 0;            // EV_FF plays and stops
    uint64_t input_reports = 0;    // SYN_REPORT batches of EV_ABS / EV_KEY sent
};

// Opens the device at `address` (every address `feel play` takes). With `wire_log`, every
// report the host sends it, each feature reply and each refusal is written there, one
// line each (the form of feel's USB device log, docs/usb-device.md).
[[nodiscard]] host::Result<host::Device> open_device(const std::string& address, std::ostream* wire_log);

// Creates the uinput device for `device` and serves it until `stop` (or the device goes).
// `say` gets the banner (the event node and the capabilities), `warn` one line per refused
// effect or failed call. Throws std::runtime_error when uinput cannot be used (saying what
// to do) or the device is gone.
BridgeStats run_bridge(host::Device& device, const BridgeOptions& options,
                       const std::function<void(const std::string&)>& say,
                       const std::function<void(const std::string&)>& warn, const std::atomic<bool>& stop);

}  // namespace feel::bridge
