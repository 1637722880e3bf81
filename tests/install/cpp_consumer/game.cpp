// A tiny C++ game against an installed feel: §7.5's x spring on the in-process simulated
// I-FORCE 2.0 stick, held by a kinematic hand at x = 4000. The force the device reports
// must follow the spring law F = -k/10000 * x (§3.2) at the position it reports.
#include <cmath>
#include <cstdio>

#include "feel/host/device.hpp"
#include "feel/iforce.hpp"
#include "feel/version.h"

int main() {
    std::printf("feel %s\n", FEEL_VERSION_STRING);
    feel::host::OpenOptions options;
    options.sim_hand = "kinematic";
    options.sim_motion = "hold:4000";
    auto device = feel::host::Device::open("sim:iforce2", options);
    if (!device) {
        std::fprintf(stderr, "open: %s\n", device.status().message.c_str());
        return 1;
    }
    auto spring = device->create_effect(feel::iforce::x_spring(5000, 5000, 0, 10000, 10000, 0));
    if (!spring || !spring->start(feel::kInfiniteIterations).ok()) {
        std::fprintf(stderr, "spring: %s\n", spring ? "start failed" : spring.status().message.c_str());
        return 1;
    }
    feel::host::InputState in{};
    for (int i = 0; i < 3000; ++i) {  // until the safety fade-in is complete
        auto s = device->wait_input(std::chrono::milliseconds(500));
        if (!s) {
            std::fprintf(stderr, "wait_input: %s\n", s.status().message.c_str());
            return 1;
        }
        in = s.value();
        if (in.fade_level >= 1.0f && i > 20) break;
    }
    const double expected = -0.5 * in.position[0];
    std::printf("x = %.0f, force = %.0f, spring law %.0f\n", in.position[0], in.force[0], expected);
    return in.position[0] > 3900 && std::fabs(in.force[0] - expected) < 30 ? 0 : 1;
}
