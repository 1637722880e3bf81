#include "bridge_command.hpp"

#include <fstream>
#include <ostream>
#include <stdexcept>

#include "feel/bridge/bridge.hpp"

namespace feel::cli {

int run_bridge_command(const BridgeArgs& args, std::ostream& out, std::ostream& err, std::atomic<bool>& stop) {
    if (args.name.size() > 79) {
        throw UsageError("--name is " + std::to_string(args.name.size()) + " bytes long (allowed 0..79)");
    }
    std::ofstream log_file;
    if (!args.log.empty()) {
        log_file.open(args.log, std::ios::out | std::ios::trunc);
        if (!log_file) throw std::runtime_error("cannot write the log " + args.log);
    }
    host::Result<host::Device> device = [&] {
        try {
            return bridge::open_device(args.device, args.log.empty() ? nullptr : &log_file);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--device: ") + e.what());
        }
    }();
    if (!device) {
        if (device.status().kind == host::ErrorKind::invalid_parameter) throw UsageError("--device: " + device.status().message);
        throw std::runtime_error("cannot open " + args.device + ": " + device.status().message);
    }
    bridge::BridgeOptions options;
    options.uinput_path = args.uinput;
    options.name = args.name;
    options.verbose = args.verbose;
    const bridge::BridgeStats stats = bridge::run_bridge(
        *device, options, [&](const std::string& line) { out << line << std::endl; },
        [&](const std::string& line) { err << line << std::endl; }, stop);
    out << "feel bridge: stopped; " << stats.uploads << " uploads (" << stats.uploads_refused << " refused), "
        << stats.erases << " erases, " << stats.plays << " plays and stops, " << stats.input_reports
        << " input reports\n";
    return kExitOk;
}

}  // namespace feel::cli
