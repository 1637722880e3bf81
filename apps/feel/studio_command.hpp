// feel studio: the Studio's web server (src/studio), until SIGINT/SIGTERM.
//
//   feel studio [--workspace DIR] [--device ADDR] [--port N] [--listen ADDR] [--hand GRIP]
//
// Prints the URL to open, e.g. "feel studio: open http://127.0.0.1:8750/ (workspace
// /home/me/sensations, device sim:iforce2)". --listen on an address that is not loopback
// prints a warning: anyone who can reach it can drive the device.
#pragma once

#include <atomic>
#include <cstdint>
#include <iosfwd>
#include <string>

namespace feel::cli {

struct StudioArgs {
    std::string workspace = ".";
    std::string device = "sim:iforce2";
    int32_t port = 8750;           // 0..65535 (0: any free port)
    std::string listen = "127.0.0.1";
    std::string hand = "firm";     // loose, firm, stiff
};

int run_studio(const StudioArgs& args, std::ostream& out, std::ostream& err, std::atomic<bool>& stop);

}  // namespace feel::cli
