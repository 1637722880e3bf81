// feel studio (studio_command.hpp).
#include "studio_command.hpp"

#include <chrono>
#include <ostream>
#include <stdexcept>
#include <thread>

#include "cli.hpp"
#include "studio_server.hpp"
#include "workspace.hpp"

namespace feel::cli {

int run_studio(const StudioArgs& args, std::ostream& out, std::ostream& err, std::atomic<bool>& stop) {
    if (args.port < 0 || args.port > 65535) {
        throw UsageError("--port " + std::to_string(args.port) + " is out of range (allowed 0..65535)");
    }
    if (args.hand != "loose" && args.hand != "firm" && args.hand != "stiff") {
        throw UsageError("--hand \"" + args.hand + "\" is not one of loose, firm, stiff");
    }
    studio::StudioOptions o;
    o.workspace = args.workspace;
    o.device = args.device;
    o.listen = args.listen;
    o.port = static_cast<uint16_t>(args.port);
    o.grip = args.hand;
    std::unique_ptr<studio::StudioServer> server;
    try {
        server = std::make_unique<studio::StudioServer>(o);
    } catch (const studio::WorkspaceError& e) {
        throw UsageError(std::string("--workspace: ") + e.what());
    }
    if (!server->loopback()) {
        err << "feel studio: warning: listening on " << args.listen
            << ", not on loopback: anyone who can reach this address can drive the device and read and write "
               "the workspace's sensation files\n";
    }
    server->start();
    out << "feel studio: open " << server->url() << " (workspace " << args.workspace << ", device " << args.device
        << ")" << std::endl;
    while (!stop.load()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    server->stop();
    out << "feel studio: stopped" << std::endl;
    return kExitOk;
}

}  // namespace feel::cli
