// §7.5 "Generating DirectInput Force Feedback Device Effects — Example: Spring and
// Texture", with feel's host API in place of DirectInput:
//
//   DirectInput (§7)                          feel::host
//   EnumDevices                               enumerate_devices()
//   CreateDevice                              Device::open(address)
//   EnumEffects(GUID_Spring, DIEFT_CONDITION)  device.effects(EffectClass::condition)
//   CreateEffect + Download                   device.create_effect(params)
//   Start(INFINITE, 0)                        effect.start(kInfiniteIterations)
//
// A stiff spring on the X axis (coefficients 1000, saturations 10000, no offset, no
// deadband) and a washboard texture along the Y axis (roughness 5000, spacing 2000,
// density 7500, at 0 degrees = the Y axis), both playing until stopped. The simulated
// hand moves the stick around a circle so that both can be felt, and the program checks
// what the primer says they do: the spring pushes back toward the center in proportion to
// the displacement (§3.2), and the texture's bumps resist the motion along y, rising and
// falling as the stick crosses them (§3.6).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "example_support.hpp"
#include "feel/host/device.hpp"
#include "feel/iforce.hpp"

using example::expect;
namespace host = feel::host;

namespace {

bool lists(const std::vector<host::EffectSupport>& effects, feel::EffectType type) {
    return std::any_of(effects.begin(), effects.end(), [&](const host::EffectSupport& e) { return e.type == type; });
}

}  // namespace

int main() {
    // EnumDevices: the in-process simulated devices (and any device listening on a socket).
    host::EnumerateOptions enumerate;
    enumerate.timeout = std::chrono::milliseconds(100);
    const std::vector<host::DeviceInfo> devices = host::enumerate_devices(enumerate);
    std::printf("%zu devices:\n", devices.size());
    for (const host::DeviceInfo& d : devices) std::printf("  %-22s %s\n", d.address.c_str(), d.class_name.c_str());
    const bool found = std::any_of(devices.begin(), devices.end(),
                                   [](const host::DeviceInfo& d) { return d.address == "sim:iforce2"; });
    expect(found, "the I-FORCE 2.0 joystick sim:iforce2 is listed");

    // CreateDevice. The simulated hand (kinematic: the stick goes exactly where it moves)
    // circles with radius 5000 once every two seconds.
    host::OpenOptions options;
    options.sim_hand = "kinematic";
    options.sim_motion = "circle:5000:0.5";
    host::Result<host::Device> opened = host::Device::open("sim:iforce2", options);
    if (!expect(opened.ok(), "open sim:iforce2" + example::because(opened.status()))) return example::exit_code();
    host::Device& device = opened.value();
    const host::DeviceCaps& caps = device.capabilities();
    std::printf("opened %s: %s, %d axes, state reports at %d Hz\n", caps.device.c_str(), caps.class_name.c_str(),
                caps.axis_count, caps.report_rate_hz);

    // EnumEffects: is Spring supported? Is Texture?
    const std::vector<host::EffectSupport> conditions = device.effects(feel::EffectClass::condition);
    if (!expect(lists(conditions, feel::EffectType::spring), "EnumEffects lists Spring") ||
        !expect(lists(conditions, feel::EffectType::texture), "EnumEffects lists Texture")) {
        return example::exit_code();
    }

    // The Spring on X: lOffset 0, coefficients 1000, saturations 10000, deadband 0.
    host::Result<host::Effect> spring = device.create_effect(feel::iforce::x_spring(1000, 1000, 0, 10000, 10000, 0));
    if (!expect(spring.ok(), "CreateEffect + Download spring" + example::because(spring.status()))) return example::exit_code();
    // The washboard: cAxes 2, direction 0 (the Y axis), roughness 5000 both ways,
    // spacing 2000 (relatively sparse bumps), density 7500 (relatively wide bumps).
    host::Result<host::Effect> washboard = device.create_effect(feel::iforce::texture(5000, 2000, 7500, 0));
    if (!expect(washboard.ok(), "CreateEffect + Download texture" + example::because(washboard.status()))) {
        return example::exit_code();
    }
    expect(spring->start(feel::kInfiniteIterations).ok(), "Start(INFINITE) the spring");
    expect(washboard->start(feel::kInfiniteIterations).ok(), "Start(INFINITE) the washboard");
    expect(example::wait_for_full_force(device), "the device has faded its forces in");

    // Feel it for one turn of the circle (two seconds), from the device's state reports.
    int spring_samples = 0, spring_good = 0;
    int moving_samples = 0, resisting = 0, in_gap = 0;
    float strongest_bump = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < end) {
        host::Result<host::InputState> in = device.wait_input(std::chrono::milliseconds(200));
        if (!in) break;
        const float x = in->position[0], y_speed = in->velocity[1];
        const float fx = in->force[0], fy = in->force[1];
        // The spring: F = -1000/10000 · x on x (the texture lies along y: nothing on x).
        if (std::fabs(x) > 1000) {
            ++spring_samples;
            if (std::fabs(fx - (-0.1f * x)) <= 0.05f * std::fabs(0.1f * x) + 20) ++spring_good;
        }
        // The texture: while the stick moves along y it meets bumps that resist the motion
        // (force against the velocity), and gaps between them (density 7500: a quarter of
        // every spacing is bump-free).
        if (std::fabs(y_speed) > 3000) {
            ++moving_samples;
            if (fy * y_speed < 0 && std::fabs(fy) > 100) ++resisting;
            if (std::fabs(fy) < 50) ++in_gap;
            strongest_bump = std::max(strongest_bump, std::fabs(fy));
        }
    }
    std::printf("spring: %d of %d reports within 5%% of F = -0.1·x\n", spring_good, spring_samples);
    std::printf("texture: %d reports while moving along y: %d on a bump resisting the motion, %d in a gap; "
                "strongest bump %.0f\n",
                moving_samples, resisting, in_gap, static_cast<double>(strongest_bump));
    expect(spring_samples >= 50 && spring_good == spring_samples,
           "the spring pushes back in proportion to the displacement on x");
    expect(moving_samples >= 50 && resisting >= moving_samples / 4,
           "the texture's bumps resist the motion along y");
    expect(in_gap >= moving_samples / 20, "and there are gaps between the bumps");
    // The bump's resistance is the roughness at its top (§6.6.j), plus at most a few percent of
    // the friction model's microdamping while the stick turns around on it (docs/conditions.md).
    expect(strongest_bump > 2000 && strongest_bump <= 5250,
           "a bump's resistance reaches toward the roughness 5000 and not beyond");

    expect(spring->stop().ok() && washboard->stop().ok(), "stop both");
    return example::exit_code();
}
