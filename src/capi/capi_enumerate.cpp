// feel.h: EnumDevices (§7.3) — the devices a host could open, handed to a C callback one
// at a time, as DirectInput's EnumDevices does (each info carries its size, so a longer
// feel_device_info in a later version never changes the caller's array strides: there is
// no array).
#include <chrono>
#include <cstdio>

#include "capi_internal.hpp"

using namespace feel::capi;

extern "C" {

int feel_enumerate_devices(const feel_enumerate_options* options, feel_device_callback callback, void* user_data) {
    return guard("feel_enumerate_devices", [&] {
        if (!callback) return null_argument("feel_enumerate_devices", "callback");
        feel_enumerate_options in{};
        if (options && read_in("feel_enumerate_devices", "options", options, in) != FEEL_OK) {
            return feel_last_error();
        }
        feel::host::EnumerateOptions o;
        o.in_process = !in.skip_in_process;
        if (in.socket_dir) o.socket_dirs.emplace_back(in.socket_dir);
        if (in.timeout_ms != 0) {
            if (in.timeout_ms < 1 || in.timeout_ms > 60000) {
                return out_of_range("feel_enumerate_devices", "options->timeout_ms", in.timeout_ms, 1, 60000);
            }
            o.timeout = std::chrono::milliseconds(in.timeout_ms);
        }
        for (const feel::host::DeviceInfo& d : feel::host::enumerate_devices(o)) {
            feel_device_info info{};
            info.size = sizeof info;
            copy_string(info.address, d.address);
            copy_string(info.device, d.device);
            copy_string(info.description, d.description);
            copy_string(info.class_name, d.class_name);
            info.in_process = d.in_process;
            if (!callback(&info, user_data)) break;
        }
        return succeed();
    });
}

}  // extern "C"
