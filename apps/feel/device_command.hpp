// feel device: the simulated device as its own process, a peripheral hosts connect to.
//
//   feel device --sim [--profile NAME] [--listen ADDR] [--hand GRIP] [--motion SPEC] [--rate HZ]
//               [--allow-remote] [--token-file FILE] [--group NAME]
//
// Builds the simulated device and its runtime (feel::peripheral::Peripheral), listens at
// ADDR (unix:PATH or tcp:HOST:PORT; default unix:<socket dir>/<profile>.sock, the
// directory verified private, else a fresh private one with a warning on `err`; socket
// files mode 0600, or 0660 with --group; tcp beyond loopback only with --allow-remote and
// a token, with a warning on `err`), prints
//   feel device: iforce2 (I-FORCE 2.0) listening on unix:/run/user/1000/feel/iforce2.sock, loop 1000 Hz
// and serves one host at a time until the stop flag is set (SIGINT/SIGTERM through the
// CLI's handlers), then prints its statistics, removes its socket and returns 0.
#pragma once

#include <atomic>
#include <iosfwd>
#include <string>

#include "feel/peripheral/peripheral.hpp"

namespace feel::cli {

struct DeviceArgs {
    // --sim: run the simulated device. Required: it is the only kind of device feel has
    // (a real-hardware backend would run without it).
    bool sim = false;
    std::string profile = "iforce2";  // --profile: a device profile (feel devices)
    std::string listen;               // --listen: unix:PATH or tcp:HOST:PORT; empty: the default socket
    std::string hand = "firm";        // --hand: none, loose, firm, stiff, kinematic
    std::string motion = "hold:0";    // --motion: the hand's target motion (as feel render)
    double rate_hz = 0;               // --rate: loop rate, whole Hz 100..the profile's max; 0: its default
    bool pid_effects_only = false;    // --pid-effects-only: HID PID 1.0's effect types only
    bool standard_pid_only = false;   // --standard-pid-only: a plain PID device, no vendor report
    bool allow_remote = false;        // --allow-remote: a tcp: address beyond loopback (needs a token)
    std::string token_file;           // --token-file: the shared secret's file; empty: $FEEL_DEVICE_TOKEN or none
    std::string group;                // --group: unix: the socket file's group (mode 0660); empty: mode 0600
};

// Runs the device until `stop` becomes true (polled every 20 ms). Returns kExitOk after a
// clean stop. Throws UsageError (exit 2) for a wrong option (no --sim, an unknown profile
// or hand, a bad address or rate), and std::runtime_error / transport::TransportError
// (exit 1) when it cannot listen.
int run_device(const DeviceArgs& args, std::ostream& out, std::ostream& err, std::atomic<bool>& stop);

// The Peripheral's options from the flags: throws UsageError naming a wrong profile, hand,
// motion or rate (what `feel device --usb` shares with the socket device).
[[nodiscard]] peripheral::PeripheralOptions peripheral_options(const DeviceArgs& args);

// The default listen address of a profile: unix:<transport::default_socket_dir()>/<profile>.sock.
[[nodiscard]] std::string default_device_address(const std::string& profile);

}  // namespace feel::cli
