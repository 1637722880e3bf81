// feel::runtime — Intelligent Disturbance Filtering, IDF (§1.2.d).
//
// A vibration or a jolt the device plays moves the handle, and the host would see that
// motion in the reported position: the aim jitters while the jet-pack rumbles. With IDF on,
// the device removes from the reported position the displacement its own periodic and
// impulse effects cause, so the game gets the position the hand holds while the hand still
// feels every effect. The player chooses, per class, whether to filter (IdfSettings).
// Rendering always uses the unfiltered position; only what is reported is filtered.
//
// Method: model-based cancellation with online identification. The device knows the force
// it plays (Engine::activity), and the handle with the hand on it is, to a good
// approximation, a mass-spring-damper with the mechanism's dry friction on each axis:
//
//     mass·x'' + damping·x' + stiffness·x = F_hand(deliberate) + F_effects − friction
//
// Writing x = x_u + d, with x_u the handle as it would move without effects, the hand's
// unknown force drops out of the equation for d, the displacement the effects cause. The
// filter simulates d from the known forces (exact zero-order-hold steps, as the motor holds
// each tick's force; friction set-valued, sticking and slipping) and reports x minus the
// part of d due to the classes the player turned on. Deliberate motion passes untouched:
// nothing low-passes or holds the position, so it has no lag.
//
// The plant depends on the hand (a loose grip is soft and light, a braced arm stiff and
// heavy), and on the conditions playing (a spring adds stiffness). The prior comes from the
// device profile and a typical grip (idf_config_for); the filter then identifies mass,
// damping and stiffness online from the very forces it cancels (a recursive Gauss-Newton
// step on the prediction error above a separation frequency, where deliberate hand motion
// has little energy). See src/runtime/idf.cpp and docs/runtime.md ("IDF") for the reasoning,
// the measured figures and the limits.
//
// Real-time safety: filter(), set_settings(), reset(), scale_activity() and
// fit_activity_to_output() never allocate, lock, throw or read a clock (time is an
// argument). filter() costs about 0.5 µs per tick for two axes. Construction and
// idf_config_for() do not allocate either.
#pragma once

#include <cstdint>

#include "feel/axis.hpp"
#include "feel/engine.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/status.hpp"

namespace feel::runtime {

// The player's choice: which disturbance classes to filter out of the reported position.
struct IdfSettings {
    bool periodic = false;  // vibrations: periodic, sweep, looping force-profile effects
    bool impulse = false;   // jolts: short constant, vector, smart-pop, ramp, profile effects
};

// The handle and the hand holding it on one axis, as the filter models it:
//     mass·x'' + damping·x' + stiffness·x = force − coulomb·sign(x')
// in normalized units: force ±10000 of the motor's limit, position ±10000 of the travel.
// Mass, damping and stiffness are the hand's and the mechanism's together, and are
// identified online; coulomb is the mechanism's dry friction, a fact of the device.
struct IdfPlant {
    double mass = 0;       // > 0, finite: force units per (position unit/s²)
    double damping = 0;    // > 0, finite: force units per (position unit/s)
    double stiffness = 0;  // > 0, finite: force units per position unit
    double coulomb = 0;    // >= 0, finite: force units
};

struct IdfConfig {
    int32_t axis_count = 2;         // 1..kMaxAxes; the device's axes, x, y, z, rx, ry, rz
    IdfPlant plant[kMaxAxes] = {};  // the prior of axes 0..axis_count-1 (the rest unused)
    IdfSettings settings{};         // the player's choice at start; set_settings() changes it
    // Identify each axis's mass, damping and stiffness online from the known forces. Off,
    // the prior is used as is.
    bool adapt = true;
    // s, 0.01..600: the identification's time constant while the effects excite the
    // handle; shorter follows a new grip sooner, longer averages more noise away.
    double adaptation_time_s = 0.1;
    // Position units, > 0 and finite: the noise the identification expects on the
    // measured response (sensor steps, what the model leaves out). A predicted response
    // well below it teaches little. idf_config_for() uses one sensor step.
    double adaptation_noise = 20000.0 / 4096;
    // Position units, > 0 and finite: one step of the position sensor. Moving less than
    // about one step per 16 ms, the handle counts as still (its speed is within the noise
    // of the filter's estimate, and friction holds it).
    double sensor_step = 20000.0 / 4096;
    // >= 1 and finite: each identified parameter stays within [prior/range, prior·range].
    double adaptation_range = 8;
    // Hz, 0.5..100: the identification looks only above this corner (a 4th-order
    // high-pass), where the response to the effects lives and deliberate motion does not.
    // Voluntary motion stays below a few Hz; vibrations start near 10 Hz.
    double separation_hz = 4;
    // µs, 0..1e6: when a class is switched on or off its correction fades in or out over
    // this long, so the reported position never jumps.
    int64_t blend_us = 50'000;
};

// The prior for a device held with `grip` (physical units converted to normalized ones:
// mass, damping and stiffness times half_travel / max_force, the mechanism's coulomb
// friction times 10000 / max_force; the sensor step from sensor_counts).
[[nodiscard]] IdfConfig idf_config_for(const sim::DeviceProfile& profile,
                                       const sim::GripModel& grip) noexcept;
// The prior for a typical hand: the profile's firm grip.
[[nodiscard]] IdfConfig idf_config_for(const sim::DeviceProfile& profile) noexcept;

// Empty when the config is usable; otherwise names the first bad field and its range.
[[nodiscard]] Error check_idf_config(const IdfConfig& config) noexcept;

// Scales an activity by the share of the engine's force that reached the motors (the
// safety monitor's fade, 0..1), so that the filter models the force the handle felt.
void scale_activity(EngineActivity& activity, float factor) noexcept;

// Makes the activity's forces add up to what the engine put out on axes where it clamped the
// sum to the motor's limit (out.saturated): each wave's force on such an axis is scaled by
// out.force / (the waves' sum). Exact when the waves are all that plays on that axis; with
// conditions or dynamics also pushing there, their share is unknown to the activity and the
// waves take the whole clamp. Call it after Engine::activity, before scale_activity.
void fit_activity_to_output(EngineActivity& activity, const TickOutput& out) noexcept;

class IdfFilter {
public:
    // An invalid config (check_idf_config) makes a filter that reports the sensed position
    // unchanged; error() says why.
    explicit IdfFilter(const IdfConfig& config) noexcept;

    [[nodiscard]] const Error& error() const noexcept { return error_; }

    // The player's choice; takes effect at the next filter(), fading over blend_us.
    void set_settings(const IdfSettings& settings) noexcept { settings_ = settings; }
    [[nodiscard]] const IdfSettings& settings() const noexcept { return settings_; }

    // One tick, after Engine::tick and Engine::activity, every tick (the model integrates
    // the forces tick by tick). t_us: the tick's time, non-decreasing; sensed_position: what
    // the sensors read this tick (the position the engine rendered from); activity: what the
    // engine played this tick (the force the motors hold until the next tick), scaled by
    // scale_activity() if the safety monitor scaled the motors. Writes the position to
    // report, ±10000; axes beyond axis_count pass through.
    void filter(int64_t t_us, const float sensed_position[kMaxAxes], const EngineActivity& activity,
                float reported[kMaxAxes]) noexcept;

    // Forgets the handle's motion (after a reset of the device or a gap in the ticks); the
    // identified plant is kept.
    void reset() noexcept;

    // What the filter believes now. The identified plant of an axis; the displacement it
    // attributes to a class on an axis (position units; `other` is never separated: 0);
    // what it subtracts from the sensed position now; how much of each class's
    // displacement it subtracts now, 0..1 (the fade).
    [[nodiscard]] const IdfPlant& plant(int axis) const noexcept;
    [[nodiscard]] double predicted_displacement(DisturbanceClass kind, int axis) const noexcept;
    [[nodiscard]] double correction(int axis) const noexcept;
    [[nodiscard]] double blend(DisturbanceClass kind) const noexcept;

private:
    // The model runs four copies of the handle, each driven by a different subset of the
    // known forces (idf.cpp explains why).
    static constexpr int kWorlds = 4;
    struct Oscillator {
        double x = 0;  // position units, displacement from the undisturbed handle
        double v = 0;  // position units/s
    };
    // A 4th-order high-pass: two 2nd-order sections in transposed direct form II.
    struct HighPass {
        double s[2][2] = {};
    };
    struct AxisState {
        Oscillator world[kWorlds];
        double force[kDisturbanceClassCount] = {};  // each class's force, held until the next tick
        double undisturbed = 0;                     // sensed minus every effect's displacement
        double undisturbed_velocity[2] = {};        // its derivative, low-passed twice, position units/s
        Oscillator sensitivity[3];                  // d(response)/d ln(mass, damping, stiffness)
        HighPass hp_error, hp_sensitivity[3];       // the identification's high-passes
        double information[3][3] = {};              // running mean of the high-passed sensitivities' outer product
        double error_power = 0;                     // running mean of the high-passed error², position units²
        double log_param[3] = {};                   // ln(mass, damping, stiffness) identified
        double log_prior[3] = {};
        IdfPlant plant{};                           // exp(log_param), coulomb from the config
        double correction = 0;                      // subtracted at the last tick
    };

    void start(int64_t t_us, const float sensed_position[kMaxAxes]) noexcept;
    void advance(AxisState& s, double dt_s, double sensed) noexcept;
    void adapt(AxisState& s, double dt_s, double sensed) noexcept;
    double run_high_pass(HighPass& hp, double x) const noexcept;
    void settle_high_pass(HighPass& hp, double x) const noexcept;

    IdfConfig config_;
    Error error_{};
    IdfSettings settings_{};
    int axes_ = 0;
    AxisState axis_[kMaxAxes];
    double blend_[kDisturbanceClassCount] = {};
    bool started_ = false;
    int64_t previous_t_us_ = 0;
    // The high-pass coefficients for the last tick length (recomputed when it changes).
    double hp_dt_s_ = 0;
    double hp_b_[3] = {}, hp_a_[2] = {};
};

}  // namespace feel::runtime
