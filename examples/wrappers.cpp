// §8.5 "Sample Code for Function Wrappers", with feel's wrapper functions.
//
// §8.5 fills a DIEFFECT and a type-specific struct by hand in each wrapper, then calls
// EnumEffects, CreateEffect, Download and Start. With feel the wrapper is the one call that
// builds the effect (feel/iforce.hpp), and the host API does the rest:
//
//   auto impact = device.create_effect(feel::iforce::dynamic_impact(9000, 5000, 5000, 5000, 500));
//   impact->start(feel::kInfiniteIterations);
//
// This program plays each of §8.5's samples on the simulated I-FORCE 2.0 joystick, held
// at the center by a firm hand, and checks what each should do: DynamicImpact's blow from
// the east shoves the stick west; the Texture holds still at rest; a Wall the stick is
// inside pushes it out; so does a Barrier; the SineWave swings both ways and ends on time;
// the ImpulseSquareWave starts with its impulse and settles; the springs, dampers and the
// inertia play until stopped.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "example_support.hpp"
#include "feel/host/device.hpp"
#include "feel/iforce.hpp"

using example::expect;
namespace host = feel::host;
namespace fi = feel::iforce;

namespace {

// Per-axis extremes of the force the device reported over a time window.
struct ForceRange {
    float min[2] = {1e9f, 1e9f};
    float max[2] = {-1e9f, -1e9f};
    int reports = 0;
};

// Collects the reported force from `from` to `to` after now (device reports, ~real time).
ForceRange watch(host::Device& device, std::chrono::milliseconds from, std::chrono::milliseconds to) {
    const auto start = std::chrono::steady_clock::now();
    ForceRange r;
    while (std::chrono::steady_clock::now() < start + to) {
        host::Result<host::InputState> in = device.wait_input(std::chrono::milliseconds(200));
        if (!in) break;
        if (std::chrono::steady_clock::now() < start + from) continue;
        for (int a = 0; a < 2; ++a) {
            r.min[a] = std::min(r.min[a], in->force[a]);
            r.max[a] = std::max(r.max[a], in->force[a]);
        }
        ++r.reports;
    }
    return r;
}

// CreateEffect + Download, then Start as §8.5 does (INFINITE: "play until stopped").
host::Effect* play(host::Device& device, host::Result<host::Effect>& slot, const char* name,
                   const feel::EffectParams& params, int32_t iterations = feel::kInfiniteIterations) {
    slot = device.create_effect(params);
    if (!expect(slot.ok(), std::string(name) + ": created and downloaded" + example::because(slot.status()))) return nullptr;
    if (!expect(slot->start(iterations).ok(), std::string(name) + ": started")) return nullptr;
    return &slot.value();
}

bool playing(host::Effect& e) {
    host::Result<host::EffectStatusInfo> s = e.status();
    return s && s->state == feel::runtime::ReportedEffectState::playing;
}

}  // namespace

int main() {
    host::Result<host::Device> opened = host::Device::open("sim:iforce2");  // a firm hand holds the stick at 0
    if (!expect(opened.ok(), "open sim:iforce2" + example::because(opened.status()))) return example::exit_code();
    host::Device& device = opened.value();
    expect(example::wait_for_full_force(device), "the device has faded its forces in");
    host::Result<host::Effect> slot = host::Status::failure(host::ErrorKind::invalid_handle, "none yet");

    // DynamicImpact(ImpactDirection, ImpactIntensity, DynamicMass, Elasticity, CollisionAbsorption):
    // a blow from the east (9000). Its first pull on the handle comes from the east, like a
    // force from 9000: toward -x.
    if (host::Effect* e = play(device, slot, "DynamicImpact(9000, 5000, 5000, 5000, 500)",
                               fi::dynamic_impact(9000, 5000, 5000, 5000, 500))) {
        const ForceRange f = watch(device, std::chrono::milliseconds(0), std::chrono::milliseconds(300));
        std::printf("  force x from %.0f to %.0f, y from %.0f to %.0f\n", double(f.min[0]), double(f.max[0]),
                    double(f.min[1]), double(f.max[1]));
        expect(f.min[0] < -500, "  the blow from the east shoves the stick west (force x < -500)");
        expect(std::fabs(f.min[1]) < 0.2f * std::fabs(f.min[0]) && std::fabs(f.max[1]) < 0.2f * std::fabs(f.min[0]),
               "  and hardly along y");
        e->stop();
    }

    // Texture(Roughness, Spacing, Density, Angle): a texture is a resistance to motion
    // (§3.6); a stick held still feels nothing.
    if (host::Effect* e = play(device, slot, "Texture(5000, 2000, 7500, 0)", fi::texture(5000, 2000, 7500, 0))) {
        const ForceRange f = watch(device, std::chrono::milliseconds(50), std::chrono::milliseconds(250));
        expect(playing(*e), "  plays until stopped");
        expect(std::max({std::fabs(f.min[0]), f.max[0], std::fabs(f.min[1]), f.max[1]}) < 300,
               "  and resists nothing while the stick is still");
        e->stop();
    }

    // Wall(Hardness, Sense, Offset, Angle): a wall across y at -2000, solid on its + side
    // (positive sense): the stick at the center is inside it and is pushed out, toward -y.
    if (host::Effect* e = play(device, slot, "Wall(2000, positive, -2000, 0)",
                               fi::wall(2000, feel::WallSense::positive, -2000, 0))) {
        const ForceRange f = watch(device, std::chrono::milliseconds(50), std::chrono::milliseconds(250));
        std::printf("  force y from %.0f to %.0f\n", double(f.min[1]), double(f.max[1]));
        // It pushes until the hand gives way and the stick rests on the wall's surface.
        expect(f.min[1] < -500 && f.max[1] <= 50, "  the wall pushes the stick out of it, toward -y, and never pulls");
        e->stop();
    }

    // Barrier(PosHardness, NegHardness, Thickness, Offset, Angle): a slab across x
    // (angle 9000) from -200 to 800: the stick at 0 is inside it on the near side and is
    // pushed back out of the face it entered, toward -x.
    if (host::Effect* e = play(device, slot, "Barrier(6000, 6000, 1000, 300, 9000)",
                               fi::barrier(6000, 6000, 1000, 300, 9000))) {
        const ForceRange f = watch(device, std::chrono::milliseconds(50), std::chrono::milliseconds(250));
        std::printf("  force x from %.0f to %.0f\n", double(f.min[0]), double(f.max[0]));
        expect(f.min[0] < -500 && f.max[0] <= 50,
               "  the barrier pushes the stick back out of its near face, toward -x, and never the other way");
        e->stop();
    }

    // SineWave(Magnitude, Offset, Phase, Period, Duration, Angle, Trigger, TriggerRepeatInterval):
    // 20 Hz for half a second from the east. It swings both ways, then ends by itself.
    if (host::Effect* e = play(device, slot, "SineWave(3000, 0, 0, 50000, 500000, 9000)",
                               fi::periodic(feel::Waveform::sine, 3000, 0, 0, 50000, 500000, 9000, fi::kNoTrigger, 0),
                               1)) {
        const ForceRange f = watch(device, std::chrono::milliseconds(0), std::chrono::milliseconds(400));
        std::printf("  force x from %.0f to %.0f\n", double(f.min[0]), double(f.max[0]));
        expect(f.max[0] > 2000 && f.min[0] < -2000, "  the sine swings both ways along x (magnitude 3000)");
        expect(example::wait_until([&] { return !playing(*e); }, std::chrono::milliseconds(1000)),
               "  and ends by itself after its 0.5 s");
        host::Result<host::EffectStatusInfo> s = e->status();
        expect(s && s->last_end == feel::PlayEnd::finished, "  it finished (was not stopped)");
    }

    // ImpulseSquareWave(Magnitude, Offset, Phase, Period, Duration, Angle, ImpulseLevel,
    // SettleTime, FadeLevel, FadeTime): a 10 Hz square from ahead that starts with an
    // impulse of 8000 and settles to 2000 within 100 ms (§4.2.a).
    if (play(device, slot, "ImpulseSquareWave(2000, 0, 0, 100000, 600000, 0, 8000, 100000, 0, 200000)",
             fi::envelope_periodic(feel::Waveform::square, 2000, 0, 0, 100000, 600000, 0, 8000, 100000, 0, 200000,
                                   fi::kNoTrigger, 0),
             1)) {
        // The envelope falls from 8000 to 2000 over the 100 ms settle time: above 3000 for
        // the first 80 ms.
        const ForceRange early = watch(device, std::chrono::milliseconds(0), std::chrono::milliseconds(60));
        const ForceRange steady = watch(device, std::chrono::milliseconds(60), std::chrono::milliseconds(300));
        const float kick = std::max(std::fabs(early.min[1]), std::fabs(early.max[1]));
        const float settled = std::max(std::fabs(steady.min[1]), std::fabs(steady.max[1]));
        std::printf("  |force y| up to %.0f in the first 60 ms, up to %.0f after it settled\n", double(kick),
                    double(settled));
        expect(kick > 3000, "  the impulse kicks well above the wave's magnitude");
        expect(settled > 1500 && settled < 2300, "  then the square settles at its magnitude 2000");
    }

    // The conditions of §8.5: each plays until stopped.
    struct Sample {
        const char* name;
        std::function<feel::EffectParams()> build;
    };
    const Sample conditions[] = {
        {"XSpring(1000, 1000, 0, 10000, 10000, 0)", [] { return fi::x_spring(1000, 1000, 0, 10000, 10000, 0); }},
        {"YSpring(1000, 1000, 0, 10000, 10000, 0)", [] { return fi::y_spring(1000, 1000, 0, 10000, 10000, 0); }},
        {"Spring(1000, 1000, 0, 10000, 10000, 0, 2000, 2000, 0, 8000, 8000, 100)",
         [] { return fi::spring(1000, 1000, 0, 10000, 10000, 0, 2000, 2000, 0, 8000, 8000, 100); }},
        {"CenterSpring(3000, 10000, 0)", [] { return fi::center_spring(3000, 10000, 0); }},
        {"XDamper(2000, 2000, 0, 10000, 10000, 0)", [] { return fi::x_damper(2000, 2000, 0, 10000, 10000, 0); }},
        {"YDamper(2000, 2000, 0, 10000, 10000, 0)", [] { return fi::y_damper(2000, 2000, 0, 10000, 10000, 0); }},
        {"Damper(2000, 2000, 0, 10000, 10000, 0, 1000, 1000, 0, 10000, 10000, 0)",
         [] { return fi::damper(2000, 2000, 0, 10000, 10000, 0, 1000, 1000, 0, 10000, 10000, 0); }},
        {"XInertia(1000, 10000)", [] { return fi::x_inertia(1000, 10000); }},
    };
    for (const Sample& c : conditions) {
        if (host::Effect* e = play(device, slot, c.name, c.build())) {
            std::this_thread::sleep_for(std::chrono::milliseconds(30));
            expect(playing(*e), "  plays until stopped");
            expect(e->stop().ok() && !playing(*e), "  and stops");
        }
    }
    return example::exit_code();
}
