// Host emulation's measured limits (docs/real-devices.md, "Host emulation"): the stiffest
// wall that stays stable and the force error on a kinematic ramp, device-side versus
// host-emulated, at 1 kHz, 500 Hz and 125 Hz updates, on the joystick's mechanics
// (iforce2), in the closed-loop model of src/host/emulation/emulated_loop.hpp. A plain
// program that prints Markdown tables; simulated time, so the figures are exact repeats.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "emulation/emulated_loop.hpp"
#include "feel/sim/device_profile.hpp"

using namespace feel;
using namespace feel::host::emulation;

namespace {

// The handle meets the wall at 0.05 m/s at the grip (10000 units/s), pushed on by 30% of
// the motor's force: a brisk contact that the wall must stop and then hold.
constexpr double kContactSpeed = 10000.0;

// The stiffest hardness (of a ladder falling 5% a step from 10000) that settles, with the
// next two lower rungs settling too (a lone stable rung above unstable ones is luck).
int32_t stiffest_stable(const sim::DeviceProfile& profile, const EngineConfig& config, const LoopLink& link) {
    int32_t best = 0;
    int run = 0;
    for (double h = 10000; h >= 10; h *= 0.95) {
        const auto hardness = static_cast<int32_t>(std::lround(h));
        const bool ok = settled(run_pressed_wall(profile, config, hardness, link, 3000, kContactSpeed, 5.0), profile);
        if (ok) {
            if (run == 0) best = hardness;
            if (++run == 3) return best;
        } else {
            run = 0;
        }
    }
    return run > 0 ? best : 0;
}

struct RampError {
    double rms = 0, worst = 0;
};

RampError ramp_error(const sim::DeviceProfile& profile, const EngineConfig& config, const LoopLink& link,
                     int32_t hardness, double v) {
    const double k_h = config.wall_stiffness * static_cast<double>(hardness) / 10000.0;
    const WallRun run = run_ramp_into_wall(profile, config, hardness, link, -200.0, v, 0.4);
    RampError e;
    double sq = 0;
    int n = 0;
    for (size_t i = 0; i < run.position.size(); ++i) {
        if (run.position[i] < 100.0) continue;
        const double err = run.force[i] + k_h * run.position[i];
        sq += err * err;
        e.worst = std::max(e.worst, std::abs(err));
        ++n;
    }
    e.rms = n ? std::sqrt(sq / n) : 0;
    return e;
}

}  // namespace

int main() {
    const sim::DeviceProfile& profile = *sim::find_device_profile("iforce2");
    const EngineConfig base = sim::engine_config_for(profile);
    struct Rate {
        int32_t period_ms;
        const char* name;
    } rates[] = {{1, "1 kHz"}, {2, "500 Hz"}, {8, "125 Hz"}};
    struct Path {
        const char* name;
        bool host;
        int32_t up, down;
    } paths[] = {{"device-side", false, 0, 0}, {"host, 1+1 ms", true, 1, 1}, {"host, 4+4 ms", true, 4, 4}};

    std::printf("| update rate | rendering | delayed bound b/(T/2+L), hardness | stiffest stable, naive | "
                "stiffest stable, with controller | ramp error rms / max (h 2000, 2000 units/s) |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (const auto& rate : rates) {
        for (const auto& path : paths) {
            const LoopLink link{rate.period_ms, path.up, path.down, path.host};
            const double t = rate.period_ms * 1e-3, l = (path.up + path.down) * 1e-3;
            const double bound = base.device_damping / (t / 2 + l);
            EngineConfig naive = base;
            naive.passivity_control = false;
            const int32_t h_naive = stiffest_stable(profile, naive, link);
            const int32_t h_ctl = stiffest_stable(profile, base, link);
            const RampError e = ramp_error(profile, base, link, 2000, 2000.0);
            std::printf("| %s | %s | %.0f | %d | %d | %.0f / %.0f |\n", rate.name, path.name,
                        std::min(10000.0, bound / base.wall_stiffness * 10000.0), h_naive, h_ctl, e.rms, e.worst);
        }
    }
    return 0;
}
