// feel caps: what a simulated device tells the host about itself (GetCapabilities and
// EnumEffects, §6.2, §7.4).
#include <ostream>
#include <string>

#include "cli.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli {

void run_caps(const CapsArgs& args, std::ostream& out) {
    const sim::DeviceProfile* profile = sim::find_device_profile(args.device);
    if (profile == nullptr) {
        std::string names;
        for (const sim::DeviceProfile& p : sim::device_profiles()) {
            names += names.empty() ? "" : ", ";
            names += p.name;
        }
        throw UsageError("--device \"" + args.device + "\" is not a known device (available: " +
                         names + ")");
    }
    runtime::print_capabilities(out, runtime::capabilities_for(*profile));
}

}  // namespace feel::cli
