// What the host benchmarks share: percentiles, error checks, and one device of each
// transport (in-process, Unix socket, TCP loopback) to measure on.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/host/device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/transport/transport.hpp"

namespace feel::bench {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t0, Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(t - t0).count();
}

// Nearest-rank percentile of a sample, p in 0..100 (0 for an empty sample).
inline double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

inline void require(const host::Status& s, const char* what) {
    if (!s.ok()) throw std::runtime_error(std::string(what) + ": " + s.message);
}

// Calls measure(name, device) with a device of `profile` opened in process, over a Unix
// socket and over TCP on loopback (the last two served by a Peripheral in this process, so
// one steady clock times host and device). `tag` names the temporary socket file.
template <class Measure>
void for_each_transport(const char* profile, const char* tag, Measure&& measure) {
    {
        host::Result<host::Device> device = host::Device::open(std::string("sim:") + profile);
        require(device.status(), "open sim");
        measure("in-process", device.value());
        device->close();
    }
    peripheral::PeripheralOptions options;
    options.profile = profile;
    {
        const std::string path = (std::filesystem::temp_directory_path() /
                                  (std::string(tag) + "-" + std::to_string(::getpid()) + ".sock"))
                                     .string();
        peripheral::Peripheral device_side(options);
        device_side.serve(transport::listen(transport::Address::parse("unix:" + path)));
        host::Result<host::Device> device = host::Device::open("unix:" + path);
        require(device.status(), "open unix socket");
        measure("unix socket", device.value());
        device->close();
        device_side.stop();
    }
    {
        peripheral::Peripheral device_side(options);
        device_side.serve(transport::listen(transport::Address::parse_listen("tcp:127.0.0.1:0")));
        host::Result<host::Device> device = host::Device::open(device_side.address().to_string());
        require(device.status(), "open tcp");
        measure("tcp loopback", device.value());
        device->close();
        device_side.stop();
    }
}

}  // namespace feel::bench
