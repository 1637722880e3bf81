// feel check --device: whether each sensation of a valid file plays on a given device.
//
// The device is the judge: every sensation is downloaded onto it as `feel play` would
// (SensationLibrary::load with its name), which checks everything the device limits — its
// effect types, axes, buttons and hats, effect slots, parameter and sample memory — with the
// same code and the same messages as playing it. Each sensation gets a freshly opened
// device, so one that does not fit does not hide the verdict on the next; then the whole
// file is loaded at once, as a game that loads its file at start-up would.
#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "check_device.hpp"
#include "feel/host/sensation_library.hpp"
#include "host_device.hpp"

namespace feel::cli {

bool check_on_device(const std::string& path, const format::SensationFile& file, const std::string& address,
                     std::ostream& out) {
    {
        const host::Device probe = open_device(address);
        const host::DeviceCaps& caps = probe.capabilities();
        out << "\non " << probe.address() << " (" << caps.device << ", " << caps.class_name << "): "
            << caps.effect_slots << " effect slots, " << caps.button_count << " buttons, " << caps.hat_count
            << " hats\n";
    }
    bool all_play = true;
    size_t width = 0;
    for (const format::Sensation& s : file.sensations) width = std::max(width, s.name.size());
    for (const format::Sensation& s : file.sensations) {
        const std::string only[] = {s.name};
        host::Result<host::SensationLibrary> loaded = host::SensationLibrary::load(path, open_device(address), only);
        std::string line = s.name;
        line.append(width - s.name.size() + 2, ' ');
        if (loaded) {
            line += "plays";
        } else {
            line += "does not play: " + loaded.status().message;
            all_play = false;
        }
        out << line << '\n';
    }
    if (file.sensations.size() > 1) {
        host::Result<host::SensationLibrary> whole = host::SensationLibrary::load(path, open_device(address));
        if (whole) {
            out << "the whole file fits on the device at once\n";
        } else {
            out << "the whole file does not fit at once (load sensations by name): " << whole.status().message
                << '\n';
        }
    }
    return all_play;
}

}  // namespace feel::cli
