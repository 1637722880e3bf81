// §5.9 "Dynamic Paddle": an asteroid hits the space ship's force field, with interim
// reporting.
//
// "At the moment that the asteroid hits the space ship, you command the DDP engine of the
// force feedback device to produce a Dynamic_Paddle sensation ... With interim reporting,
// the position of the asteroid with respect to the joystick is reported to the host. This
// value lets you update the animation to show how deeply the force field is stretched
// during the collision. ... the final velocity of the asteroid is reported back to the host
// so the game can maintain coordination and have the asteroid fly off in the right
// direction."
//
// The asteroid (ball mass 10000) comes from ahead (compass 0, moving toward the user along
// -y) at 5000 into a soft force field (paddle compliance 500, a little damping, no
// gravity: space). The player's hand holds the stick firmly. The program subscribes to the
// effect's reports, prints the asteroid's depth in the field as the interim reports arrive
// (about 60 a second), and when the asteroid leaves prints the final report: its velocity,
// relative to the stick and in the game's fixed frame. It checks that the reports came at
// the device's interim rate, that the field was pressed in and let go, that exactly one final
// report came, with the asteroid flying back out the way it came in, and that the effect then
// ended by itself.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>

#include "example_support.hpp"
#include "feel/host/device.hpp"
#include "feel/iforce.hpp"
#include "feel/sim/device_profile.hpp"

using example::expect;
namespace host = feel::host;

int main() {
    host::Result<host::Device> opened = host::Device::open("sim:iforce2");
    if (!expect(opened.ok(), "open sim:iforce2" + example::because(opened.status()))) return example::exit_code();
    host::Device& device = opened.value();
    const host::DeviceCaps& caps = device.capabilities();
    if (!expect(caps.supports(feel::EffectType::dynamic_paddle) && caps.interim_reports,
                "the I-FORCE 2.0 joystick plays Dynamic Paddle with interim reports")) {
        return example::exit_code();
    }
    expect(example::wait_for_full_force(device), "the device has faded its forces in");

    // DynamicPaddle(BallMass, InitialVelocity (+ its direction), PaddleCompliance,
    // PaddleDamping, Gravity, InterimReporting).
    host::Result<host::Effect> asteroid =
        device.create_effect(feel::iforce::dynamic_paddle(10000, 5000, 0, 500, 300, 0, true));
    if (!expect(asteroid.ok(), "the asteroid's paddle sensation is downloaded" + example::because(asteroid.status()))) {
        return example::exit_code();
    }

    std::mutex mu;
    std::vector<host::DynamicEvent> interim;
    std::vector<host::DynamicEvent> finals;
    // Called on the device's I/O thread: keep it short, hand the data over.
    host::Subscription subscription = asteroid->subscribe([&](const host::DynamicEvent& e) {
        std::lock_guard lock(mu);
        (e.kind == feel::DynamicReport::Kind::final ? finals : interim).push_back(e);
    });

    std::printf("the asteroid hits the force field (interim reports at %.0f Hz):\n", caps.interim_report_hz);
    if (!expect(asteroid->start().ok(), "started")) return example::exit_code();
    const bool left = example::wait_until(
        [&] {
            std::lock_guard lock(mu);
            return !finals.empty();
        },
        std::chrono::milliseconds(3000));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // would a second final come?
    subscription.reset();

    std::lock_guard lock(mu);
    // Along the field's normal (the asteroid came from the north: +y faces it), the asteroid's
    // position relative to the stick is its depth in the field when negative.
    float deepest = 0;
    for (const host::DynamicEvent& e : interim) {
        const float depth = std::max(0.0f, -e.position[1]);
        deepest = std::max(deepest, depth);
        const int bar = static_cast<int>(depth / 100);
        std::printf("  t = %7.1f ms  asteroid at (%6.0f, %6.0f)  field pressed in %5.0f  %s\n",
                    double(e.t_us - interim.front().t_us) / 1000.0, double(e.position[0]), double(e.position[1]),
                    double(depth), std::string(static_cast<size_t>(std::min(bar, 60)), '#').c_str());
    }
    expect(interim.size() >= 5, std::to_string(interim.size()) + " interim reports arrived during the collision");
    if (interim.size() >= 2) {
        const double span_s = double(interim.back().t_us - interim.front().t_us) / 1e6;
        const double rate = double(interim.size() - 1) / span_s;
        expect(std::fabs(rate - caps.interim_report_hz) <= 0.15 * caps.interim_report_hz,
               "at " + std::to_string(int(rate + 0.5)) + " Hz (the device's interim rate is " +
                   std::to_string(int(caps.interim_report_hz + 0.5)) + " Hz)");
    }
    expect(deepest > 500, "the asteroid stretched the field " + std::to_string(int(deepest)) + " deep");
    expect(left, "the asteroid left the field");
    expect(finals.size() == 1, std::to_string(finals.size()) + " final report (exactly one)");
    if (!finals.empty()) {
        const host::DynamicEvent& f = finals.front();
        const float vx = f.velocity[0] + f.handle_velocity[0];
        const float vy = f.velocity[1] + f.handle_velocity[1];
        std::printf("final report: asteroid at (%.0f, %.0f) relative to the stick, velocity (%.0f, %.0f) relative, "
                    "(%.0f, %.0f) in the game's frame\n",
                    double(f.position[0]), double(f.position[1]), double(f.velocity[0]), double(f.velocity[1]),
                    double(vx), double(vy));
        expect(vy > 0 && std::fabs(vx) < 0.1f * vy,
               "it flies back out the way it came in (+y), for the game to send it on");
        // It came in at 5000 on the velocity scale: 5000/10000 of the device's velocity_ref
        // (the speed of a brisk hand on it, docs/dynamics.md). A damped field held by the hand
        // returns it slower (restitution below 1), never faster.
        const feel::sim::DeviceProfile* profile = feel::sim::find_device_profile(caps.device);
        const double came_in = profile ? 0.5 * profile->velocity_ref : 0.0;
        expect(vy < came_in, "slower than it came in (" + std::to_string(int(came_in)) +
                                 " units/s), as a damped field held still returns it");
    }
    host::Result<host::EffectStatusInfo> s = asteroid->status();
    expect(s && s->state == feel::runtime::ReportedEffectState::stopped && s->last_end == feel::PlayEnd::finished,
           "the sensation ended by itself when the asteroid left");
    return example::exit_code();
}
