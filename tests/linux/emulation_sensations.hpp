// The sensations the VM's host emulation case plays on the plain PID gadget
// (pid_emulation_probe.cpp) and renders device-side (check_pid_emulation.cpp), and the
// gadget they play on (tests/linux/pid_host_case.sh starts it with these figures).
#pragma once

#include <string_view>

#include "emulation/emulated_loop.hpp"
#include "support/valid_effects.hpp"

namespace feel::test::vm {

inline constexpr const char* kProfile = "iforce2";
inline constexpr const char* kMotion = "sine:x:2000:0.5";  // the kinematic hand: x swings, y holds 0
inline constexpr int32_t kLoopHz = 250;                     // TCG keeps 250 Hz, not 1 kHz

inline constexpr std::string_view kSensations[] = {"wall", "texture", "recoil"};

// A wall of hardness 2000 and §7.5's texture on x, which the hand sweeps; a recoil on y,
// where the handle is held still (as in tests/host/pid_emulation_test.cpp: a tethered
// dynamic on a handle that moves between laggy updates is another matter, real-devices.md).
inline EffectParams sensation(std::string_view name) {
    if (name == "wall") return host::emulation::wall_on_x(2000);
    if (name == "texture") {
        EffectParams t = valid_effect(EffectType::texture);
        t.axes[0] = Axis::x;
        return t;
    }
    EffectParams r = valid_effect(EffectType::dynamic_recoil);
    set_axes(r, {Axis::y});
    r.dynamic.blast_direction = 0;  // on one axis the intensity's sign is the direction
    return r;
}

}  // namespace feel::test::vm
