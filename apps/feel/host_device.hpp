// What the host commands (caps, play, stream, monitor) share: opening --device through the
// host API, turning a host Status into the CLI's errors, and getting the device ready to be
// watched (fast state reports, the power-on fade-in done).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "feel/host/device.hpp"
#include "feel/host/result.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli {

// Opens the device at `address` (sim:PROFILE, unix:PATH, tcp:HOST:PORT, or a bare profile
// name). A malformed address or an unknown profile is a UsageError naming --device and the
// forms or profiles allowed (exit 2); a device that cannot be reached or does not answer
// is a std::runtime_error naming the address (exit 1).
[[nodiscard]] host::Device open_device(const std::string& address, const host::OpenOptions& options = {});

// An in-process simulated device whose hand the command can drive (buttons, hats), with
// the host's Device on it. The device is declared last so that it closes first.
struct HandledDevice {
    const sim::DeviceProfile* profile = nullptr;
    std::unique_ptr<peripheral::Peripheral> peripheral;
    host::Device device;
};
// Opens `address`, which must be sim:PROFILE or a bare PROFILE, for a command that presses
// its buttons (`flag` names the option that needs it, in the UsageError otherwise).
[[nodiscard]] HandledDevice open_handled_device(const std::string& address, const char* flag);

// Throws std::runtime_error "`what`: <the status's message>" when the status is an error.
void check(const host::Status& status, const std::string& what);

// Asks the device for state reports at the fastest rate it allows (1000 Hz, or its loop
// rate if slower), so that live figures and peaks see every tick it can report. Returns
// the rate in effect.
int32_t use_fastest_reports(host::Device& device);

// A device fades its forces in over half a second after power-on (safety.hpp), so a
// force measured before then is scaled down. Waits until the reported fade level is 1 or
// `limit` passes; returns whether the device is at full strength. It never gets there
// while nobody holds a handle with a dead-man switch.
bool wait_for_full_strength(host::Device& device, std::chrono::milliseconds limit);

// "x -2160.5  y +0.0": one signed force per axis, one decimal.
[[nodiscard]] std::string format_forces(const float* force, int32_t axis_count);
// "x" for axis 0, "y", "z", "rx", ...
[[nodiscard]] std::string axis_label(int32_t axis_index);

// Seconds as "0.300 s".
[[nodiscard]] std::string format_elapsed(double seconds);

}  // namespace feel::cli
