// §1.2.c "Reflexes, A Technique for Efficient Force Feedback Programming": the reflex table.
//
//   Button         Reflex sensation
//   Button #4      a 100 Hz sine at 20% magnitude, left-right: the afterburner's engine hum
//   Hat Switch #2  a 30 ms jolt at 75% magnitude: the Patriot missile launching
//   Trigger #1     a 10 Hz square wave at 70% magnitude: the forward machine guns
//
// The three sensations come from examples/primer.feel.json (afterburner_hum,
// patriot_missile, machine_guns), whose trigger_button fields make them reflexes when they
// are created. The program sets the table up on two simulated joysticks that differ only in
// their processor:
//
//   iforce2  I-FORCE 2.0 class: the device runs the reflexes itself, locally, at its 1 kHz
//            loop (the "knee jerk" of §1.2.c): no host traffic per press;
//   iforce1  I-FORCE 1.x class: no local reflexes, so the host emulates them ("the host can
//            emulate the feature in the driver"): it watches the buttons in the device's
//            input reports and starts the effect itself, one report and one round trip
//            later; each effect's status says "emulated".
//
// Then the player presses button 4, pushes hat switch #2 and holds the trigger for 1.2 s,
// and the program shows each effect's status: which fired, who fired it, how fast, and that
// the machine guns repeat every half second while the trigger is held.
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "example_support.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/host/device.hpp"

using example::expect;
namespace host = feel::host;
using feel::runtime::ReportedEffectState;
using Clock = std::chrono::steady_clock;

namespace {

const char* state_name(ReportedEffectState s) {
    switch (s) {
        case ReportedEffectState::stopped: return "stopped";
        case ReportedEffectState::playing: return "playing";
        case ReportedEffectState::delayed: return "delayed";
        case ReportedEffectState::emulated: return "playing (emulated by the host)";
    }
    return "?";
}

bool is_playing(host::Effect& e) {
    host::Result<host::EffectStatusInfo> s = e.status();
    return s && (s->state == ReportedEffectState::playing || s->state == ReportedEffectState::emulated);
}

void show(const char* name, host::Effect& e) {
    host::Result<host::EffectStatusInfo> s = e.status();
    if (!s) {
        std::printf("    %-16s status failed: %s\n", name, s.status().message.c_str());
        return;
    }
    const feel::Trigger t = e.parameters().trigger;
    std::printf("    %-16s %-6s %d  %-32s emulated=%s  completed plays=%d\n", name,
                t.kind == feel::TriggerKind::hat ? "hat" : "button", t.index, state_name(s->state),
                s->emulated ? "yes" : "no", s->completed_iterations);
}

const feel::format::Sensation* find(const feel::format::SensationFile& file, const std::string& name) {
    for (const auto& s : file.sensations) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

// Sets up the table on one device, presses the buttons, reports; returns nothing, counts
// failed expectations.
void run(const std::string& profile, const feel::format::SensationFile& file) {
    std::printf("\n== %s ==\n", profile.c_str());
    example::SimRig rig = example::SimRig::open(profile);
    if (!rig.device) return;
    host::Device& device = *rig.device;
    const host::DeviceCaps& caps = device.capabilities();
    std::printf("  %s, %s: %s\n", caps.device.c_str(), caps.class_name.c_str(),
                caps.local_reflexes ? "reflexes run on the device" : "no local reflexes: the host emulates them");

    host::Effect effects[3];
    const char* names[3] = {"afterburner_hum", "patriot_missile", "machine_guns"};
    for (int i = 0; i < 3; ++i) {
        const feel::format::Sensation* s = find(file, names[i]);
        if (!expect(s != nullptr && s->effects.size() == 1, std::string("primer.feel.json has ") + names[i])) return;
        const feel::format::EffectSpec& spec = s->effects[0];
        host::Result<host::Effect> e = device.create_effect(spec);
        if (!expect(e.ok(), std::string("  ") + names[i] + " armed as a reflex" + example::because(e.status()))) return;
        effects[i] = std::move(e).value();
        expect(effects[i].emulated() == !caps.local_reflexes,
               std::string("  ") + names[i] + (caps.local_reflexes ? " is a device reflex" : " is emulated by the host"));
    }
    host::Effect& afterburner = effects[0];
    host::Effect& patriot = effects[1];
    host::Effect& machine_guns = effects[2];
    std::printf("  the table, armed:\n");
    for (int i = 0; i < 3; ++i) show(names[i], effects[i]);
    const int64_t device_starts_before = rig.peripheral->stats().runtime.pipeline.reflex_starts;

    // Button 4: the afterburner.
    auto pressed = Clock::now();
    rig.set_buttons(1u << 3);
    const bool hum = example::wait_until([&] { return is_playing(afterburner); }, std::chrono::milliseconds(500));
    const double hum_ms = std::chrono::duration<double, std::milli>(Clock::now() - pressed).count();
    expect(hum, "  button 4 fires the afterburner hum (seen by the host " + std::to_string(int(hum_ms + 0.5)) +
                    " ms after the press)");
    rig.set_buttons(0);

    // Hat switch #2: the Patriot missile, a 30 ms jolt that ends by itself.
    pressed = Clock::now();
    rig.set_hats(1u << 1);
    const bool jolt = example::wait_until(
        [&] {
            host::Result<host::EffectStatusInfo> s = patriot.status();
            return s && s->iterations > 0 && s->last_end == feel::PlayEnd::finished;
        },
        std::chrono::milliseconds(500));
    const double jolt_ms = std::chrono::duration<double, std::milli>(Clock::now() - pressed).count();
    expect(jolt, "  hat 2 fires the Patriot missile's 30 ms jolt, which ends by itself (seen " +
                     std::to_string(int(jolt_ms + 0.5)) + " ms after the push)");
    rig.set_hats(0);

    // Trigger (button 1) held 1.2 s: the machine guns start and restart every 0.5 s.
    int plays = 0;
    bool was = false;
    int64_t last_elapsed = 0;
    pressed = Clock::now();
    rig.set_buttons(1u << 0);
    while (Clock::now() < pressed + std::chrono::milliseconds(1200)) {
        // A restart shows as the effect's elapsed time going back to the start.
        host::Result<host::EffectStatusInfo> s = machine_guns.status();
        const bool now = s && (s->state == ReportedEffectState::playing || s->state == ReportedEffectState::emulated);
        if (now && (!was || s->elapsed_us < last_elapsed)) ++plays;
        if (s) last_elapsed = s->elapsed_us;
        was = now;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    rig.set_buttons(0);
    expect(plays == 3,
           "  holding the trigger 1.2 s fires the machine guns at 0, 0.5 and 1.0 s (" + std::to_string(plays) +
               " plays)");

    const int64_t device_starts = rig.peripheral->stats().runtime.pipeline.reflex_starts - device_starts_before;
    if (caps.local_reflexes) {
        expect(device_starts >= 5, "  the device started them itself (" + std::to_string(device_starts) +
                                       " reflex starts on the device)");
    } else {
        expect(device_starts == 0, "  the device started none of them: the host did");
        host::Result<host::EffectStatusInfo> s = afterburner.status();
        expect(s && s->emulated, "  and the afterburner's status says emulated");
    }
    std::printf("  the table after the presses:\n");
    for (int i = 0; i < 3; ++i) show(names[i], effects[i]);
}

}  // namespace

// Usage: example_reflex_table [SENSATION_FILE]   (default: the source tree's examples/primer.feel.json)
int main(int argc, char** argv) {
    const std::string path = argc > 1 ? argv[1] : FEEL_SOURCE_DIR "/examples/primer.feel.json";
    feel::format::SensationFile file;
    try {
        file = feel::format::load_sensation_file(path);
    } catch (const std::exception& e) {
        expect(false, "load " + path + ": " + e.what());
        return example::exit_code();
    }
    run("iforce2", file);
    run("iforce1", file);
    return example::exit_code();
}
