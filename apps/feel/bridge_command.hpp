// feel bridge: a feel device as a Linux force-feedback joystick through uinput
// (docs/real-devices.md, "feel bridge").
//
//   feel bridge [--device ADDR] [--name TEXT] [--log FILE] [--verbose]
//
// Prints the event node and what the device offers, serves games until SIGINT/SIGTERM, then
// removes the input device and prints its figures.
#pragma once

#include <atomic>
#include <iosfwd>
#include <string>

#include "cli.hpp"

namespace feel::cli {

struct BridgeArgs {
    std::string device = kDefaultDeviceAddress;  // every address `feel play` takes
    std::string name;                            // the input device's name (empty: the default)
    std::string log;                             // --log FILE: what the device receives
    std::string uinput = "/dev/uinput";          // --uinput PATH
    bool verbose = false;                        // --verbose: one line per request of the game
};

// Runs until `stop`. Throws UsageError (exit 2) for a malformed --device, std::runtime_error
// (exit 1) when the device or uinput cannot be used (saying what to do).
int run_bridge_command(const BridgeArgs& args, std::ostream& out, std::ostream& err, std::atomic<bool>& stop);

}  // namespace feel::cli
