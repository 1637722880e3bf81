// enumerate_devices: the in-process simulated devices, then the devices listening on Unix
// sockets in the socket directories (EnumDevices, §7.2).
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "device_info.hpp"
#include "feel/host/device.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/transport/transport.hpp"

namespace feel::host {
namespace {

// Asks the device at `path` for its DeviceInfo: connect, GET_REPORT(Feature), close. A
// device busy with another host, or one that does not answer in time, is skipped.
std::optional<DeviceInfo> probe(const std::filesystem::path& path, std::chrono::milliseconds timeout) {
    transport::Address address;
    address.kind = transport::Address::Kind::unix_socket;
    address.path = path.string();
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    try {
        std::unique_ptr<transport::Connection> connection = transport::connect(address, timeout);
        const auto id = static_cast<uint8_t>(protocol::ReportId::device_info);
        connection->send(transport::Frame{transport::FrameKind::get_feature, {id}});
        for (;;) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline -
                                                                                   std::chrono::steady_clock::now());
            if (left.count() <= 0) break;
            std::optional<transport::Frame> frame = connection->receive(left);
            if (!frame || frame->kind == transport::FrameKind::busy) break;
            if (frame->kind != transport::FrameKind::feature_reply || frame->payload.empty() ||
                frame->payload[0] != id) {
                continue;  // input reports the device sends meanwhile
            }
            protocol::AnyReport report;
            if (protocol::decode(frame->payload, report)) break;
            const auto* info = std::get_if<protocol::DeviceInfoReport>(&report);
            if (!info) break;
            connection->close();
            return device_info_from(*info, address.to_string());
        }
        connection->close();
    } catch (const std::exception&) {
        // Not a device, a stale socket, or it went away: not listed.
    }
    return std::nullopt;
}

}  // namespace

std::vector<DeviceInfo> enumerate_devices(const EnumerateOptions& options) {
    std::vector<DeviceInfo> out;
    if (options.in_process) {
        for (const sim::DeviceProfile& p : sim::device_profiles()) {
            DeviceInfo d;
            d.address = "sim:" + std::string(p.name);
            d.device = std::string(p.name);
            d.description = std::string(p.description);
            d.class_name = std::string(sim::device_class_name(p.device_class));
            d.in_process = true;
            out.push_back(std::move(d));
        }
    }
    std::vector<std::string> dirs = options.socket_dirs;
    if (dirs.empty()) dirs.push_back(transport::default_socket_dir());
    const auto timeout = std::max(options.timeout, std::chrono::milliseconds(1));
    for (const std::string& dir : dirs) {
        std::error_code ec;
        std::vector<std::filesystem::path> sockets;
        for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            const std::filesystem::path& p = it->path();
            std::error_code type_ec;
            if (p.extension() == ".sock" && it->is_socket(type_ec)) sockets.push_back(p);
        }
        std::sort(sockets.begin(), sockets.end());
        for (const auto& path : sockets) {
            if (std::optional<DeviceInfo> info = probe(path, timeout)) out.push_back(std::move(*info));
        }
    }
    return out;
}

}  // namespace feel::host
