// feel devices: the simulated device profiles that --device accepts, with their class.
#include <cstdio>
#include <ostream>
#include <string>

#include "cli.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli {

void run_devices(std::ostream& out) {
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        std::string axes;
        for (int a = 0; a < p.axis_count; ++a) {
            if (!axes.empty()) axes += ',';
            axes += axis_name(p.axes[a].axis);
        }
        char head[128];
        std::snprintf(head, sizeof head, "%-10s %-8s %-12s ", std::string(p.name).c_str(),
                      axes.c_str(), std::string(sim::device_class_name(p.device_class)).c_str());
        out << head << p.description << '\n';
    }
}

}  // namespace feel::cli
