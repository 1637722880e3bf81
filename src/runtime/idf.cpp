// Intelligent Disturbance Filtering: cancel the known effects' displacement from the report.
//
// Why a model, not a notch or a hold. The primer names the two disturbances: a periodic
// one (a vibration at a given frequency) and an impulse (a jolt). The textbook answers are
// a notch at the vibration's frequency and holding the reported position through a jolt.
// Both filter the position itself, so both delay or freeze the hand's own motion: a notch
// at 10 Hz narrow enough to leave aiming alone has a group delay of tens of ms, and a hold
// hides every deliberate move made during the jolt. A square or saw wave also puts energy
// at every harmonic, and a jolt's response outlasts the jolt. But the device knows exactly
// what force it played and when, so it can compute the displacement that force causes and
// subtract just that. The hand's motion is never filtered: no lag by construction, and one
// mechanism covers every waveform, sweeps, envelopes and jolts alike.
//
// The plant. Per axis, handle plus hand: m·x'' + b·x' + k·x = F_hand + F_effects + f(x'),
// where the grip is a spring-damper to where the hand wants the handle, the mechanism adds
// mass and viscous damping, and f is the mechanism's dry friction, −F_c·sign(x') with
// sticking at rest (docs/simulated-device.md). Write x = x_u + d, with x_u the handle as it
// would move with no effect playing (what the host should see) and d the displacement the
// effects cause. Subtracting the two equations:
//
//     m·d'' + b·d' + k·d = F_effects + f(x_u' + d') − f(x_u')
//
// The hand's force drops out: d depends only on the known forces, the plant, and, through
// friction, the undisturbed velocity x_u', which the filter estimates from its own output.
//
// Friction matters. It is small (3% of the motor on the joystick), but the grip's spring is
// soft: at the end of a jolt the handle sticks where friction catches it instead of ringing
// back, and the slow ringing a vibration's onset excites dies in a few cycles. A linear
// model predicts both wrongly by tens of position units, as much as a 50 Hz vibration's
// whole amplitude. So d advances, in substeps of at most 250 µs (friction starts and stops
// the handle within a tick), by the exact zero-order-hold step of the linear part (the motor
// holds each tick's force until the next tick):
//
//     α = b/2m, ω0² = k/m, q = ω0² − α²,  C = cos(√q·h), S = sin(√q·h)/√q   (cosh/sinh
//     Φ = e^(−αh)·[[C + αS, S], [−ω0²·S, C − αS]]                           when q < 0)
//     [d, d']' = Φ·([d, d'] − [F/k, 0]) + [F/k, 0]
//
// and then by the difference friction makes, set-valued as in the simulated device and a
// real gear train: friction changes a handle's velocity by at most h·F_c/m per substep and
// stops it dead if it is slower than that. d gets friction(x_u' + d') − friction(x_u'), so
// with no effect d stays exactly 0, a hand moving faster than the effects shake it sees the
// linear model, and a still hand sees stick-slip. x_u' counts as 0 within the noise of its
// estimate (half a sensor step per 2π·20 Hz⁻¹).
//
// Classes. With friction, d is not a sum of one response per class, so the filter runs four
// copies of the model (worlds), driven by all known forces, all but the periodic ones, all
// but the impulses, and only the `other` ones. The displacement the periodic class causes is
// then d_all − d_without_periodic, and so on: the position the host gets is the position
// the handle would have without the classes the player filters. Fades between settings
// blend the four bilinearly, exact at the corners.
//
// Identification. The prior plant comes from the profile and a typical (firm) grip, but a
// hand may be loose or braced, and a spring condition adds stiffness: above the plant's
// resonance the response to a vibration is set by the mass, below it by the stiffness, and
// a 2x error in either leaves half the jitter. So the filter fits the plant online to the
// very forces it cancels (output-error identification by a recursive Gauss-Newton step):
// with θ = ln(m, b, k), the prediction's sensitivities g = ∂d/∂θ obey the linear plant
// driven by −m·d'', −b·d', −k·d (differentiate the ODE), and each tick moves θ by
//
//     Δθ = (dt/adaptation_time_s) · (R + g·gᵀ + (1 + λ)·σ²·I)⁻¹ · (g·e − λ·σ²·(θ − θ_prior))
//
// where e is the prediction error, R the running mean of g·gᵀ (the curvature), σ the
// expected noise (adaptation_noise). Normalizing by the curvature makes every identifiable
// direction converge at the same rate whatever the excitation's size; adding this tick's
// g·gᵀ bounds the step (it never predicts more than e); σ² keeps the unidentifiable
// directions still (one vibration frequency shows only the plant's complex gain there, two
// numbers for three parameters) and λ pulls them slowly back to the prior. Both e and g
// first pass the same 4th-order high-pass at separation_hz, so the hand's slow deliberate
// motion, which the model does not predict, barely enters; what remains of it is
// uncorrelated with the effects' forces. Errors beyond three times what the noise, the
// recent errors and the parameters' plausible error explain are clipped (a deliberate flick
// must not teach the model), learning slows while the hand moves fast (friction then couples
// its motion to the response in ways the model only approximates), and each parameter stays
// within adaptation_range of the prior. With no effect playing, g is zero and nothing moves.
//
// Limits (docs/runtime.md): a disturbance that drives the handle into an end stop is not
// cancelled while it presses there, and the identification pauses near the stops. A free
// handle (no hand) is outside the model; the safety monitor cuts the forces then. Conditions
// (springs, dampers) are part of the plant: the identification absorbs them.
#include "feel/runtime/idf.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace feel::runtime {
namespace {

constexpr int kMass = 0, kDamping = 1, kStiffness = 2;
constexpr int kPeriodic = static_cast<int>(DisturbanceClass::periodic);
constexpr int kImpulse = static_cast<int>(DisturbanceClass::impulse);
constexpr int kOther = static_cast<int>(DisturbanceClass::other);
// The worlds: which known forces drive each copy of the model.
constexpr int kAll = 0, kWithoutPeriodic = 1, kWithoutImpulse = 2, kOtherOnly = 3;
// A gap between ticks longer than this means the loop stopped: the handle's motion over it
// is unknown, so the model starts over.
constexpr double kMaxGapS = 0.1;
// The undisturbed velocity is the derivative of the filter's output, low-passed twice at
// this corner, Hz: above deliberate motion, below a vibration's residue and the sensor's
// step noise.
constexpr double kVelocityCornerHz = 20;
// Below this many sensor steps per (2π·kVelocityCornerHz)⁻¹ the undisturbed velocity is
// within the noise of its estimate, and the handle counts as still (held by friction).
constexpr double kStillSteps = 0.5;
// Learning slows (by 1 + (v/this)²) while the undisturbed handle moves faster than this,
// position units/s: a deliberate move, not the tremor of a hand holding still.
constexpr double kDeliberateSpeed = 5000;
// λ: the pull of unidentifiable directions back to the prior, relative to σ².
constexpr double kPriorPull = 0.1;
// Friction substeps: at most this long, s, and at most this many per tick.
constexpr double kFrictionSubstepS = 250e-6;
constexpr int kMaxFrictionSubsteps = 64;
// A reading this close to the end of the travel may be an end stop, outside the model.
constexpr double kNearStop = 9990;
// The identification's running means (curvature, error power) average over this long, s:
// a few cycles of the slowest response worth identifying, the ringing after a jolt.
constexpr double kInformationTauS = 0.5;
// The variance of ln(parameter) the clipping allows for: a factor of two either way.
constexpr double kParameterVariance = 0.48;  // ln(2)²
// Innovations beyond this many standard deviations are clipped.
constexpr double kInnovationClip = 3;

struct Discrete {
    double p11 = 1, p12 = 0, p21 = 0, p22 = 1;  // Φ
    double g1 = 0, g2 = 0;                       // response to a held unit force
};

// The exact zero-order-hold discretization of m·x'' + b·x' + k·x = F over h seconds.
Discrete discretize(const IdfPlant& p, double h) noexcept {
    const double alpha = p.damping / (2 * p.mass);
    const double w0_sq = p.stiffness / p.mass;
    const double q = w0_sq - alpha * alpha;
    double ec = 0, es = 0;  // e^(−αh)·C and e^(−αh)·S
    if (std::fabs(q) * h * h < 1e-6) {
        const double qh2 = q * h * h;
        const double e = std::exp(-alpha * h);
        ec = e * (1 - qh2 / 2 + qh2 * qh2 / 24);
        es = e * h * (1 - qh2 / 6 + qh2 * qh2 / 120);
    } else if (q > 0) {
        const double w = std::sqrt(q);
        const double e = std::exp(-alpha * h);
        ec = e * std::cos(w * h);
        es = e * std::sin(w * h) / w;
    } else {
        // Overdamped: w < α, so both exponents are <= 0 and nothing overflows.
        const double w = std::sqrt(-q);
        const double slow = std::exp((w - alpha) * h), fast = std::exp(-(w + alpha) * h);
        ec = (slow + fast) / 2;
        es = (slow - fast) / (2 * w);
    }
    Discrete d;
    d.p11 = ec + alpha * es;
    d.p12 = es;
    d.p21 = -w0_sq * es;
    d.p22 = ec - alpha * es;
    d.g1 = (1 - d.p11) / p.stiffness;
    d.g2 = es / p.mass;
    return d;
}

void step_linear(const Discrete& d, double force, double& x, double& v) noexcept {
    const double x_next = d.p11 * x + d.p12 * v + d.g1 * force;
    const double v_next = d.p21 * x + d.p22 * v + d.g2 * force;
    x = x_next;
    v = v_next;
}

bool finite_in(double v, double lo, double hi) noexcept { return std::isfinite(v) && v >= lo && v <= hi; }

// "plant[3].mass" without allocating.
Error bad_plant_field(int axis, const char* name, const char* rule) noexcept {
    char field[32] = "plant[0].";
    field[6] = static_cast<char>('0' + axis);
    size_t n = 9;
    for (const char* c = name; *c != '\0' && n + 1 < sizeof field; ++c) field[n++] = *c;
    field[n] = '\0';
    return Error::invalid(field, rule);
}

}  // namespace

IdfConfig idf_config_for(const sim::DeviceProfile& profile, const sim::GripModel& grip) noexcept {
    IdfConfig c;
    c.axis_count = std::clamp(profile.axis_count, 1, kMaxAxes);
    for (int a = 0; a < c.axis_count; ++a) {
        const sim::AxisModel& ax = profile.axes[a];
        // Force unit = max_force/10000, position unit = half_travel/10000.
        const double scale = ax.half_travel / ax.max_force;
        c.plant[a].mass = (ax.mass + grip.added_mass) * scale;
        c.plant[a].damping = (ax.viscous + grip.damping) * scale;
        c.plant[a].stiffness = grip.stiffness * scale;
        c.plant[a].coulomb = ax.coulomb * kFullScale / ax.max_force;
    }
    // The profiles' axes share a sensor; one step is the noise the identification expects.
    c.sensor_step = 2.0 * kFullScale / profile.axes[0].sensor_counts;
    c.adaptation_noise = c.sensor_step;
    return c;
}

IdfConfig idf_config_for(const sim::DeviceProfile& profile) noexcept {
    return idf_config_for(profile, profile.firm);
}

Error check_idf_config(const IdfConfig& c) noexcept {
    if (!Range{1, kMaxAxes}.contains(c.axis_count)) return Error::out_of_range("axis_count", c.axis_count, {1, kMaxAxes});
    for (int a = 0; a < c.axis_count; ++a) {
        const IdfPlant& p = c.plant[a];
        if (!(p.mass > 0) || !std::isfinite(p.mass)) return bad_plant_field(a, "mass", "must be a finite number > 0");
        if (!(p.damping > 0) || !std::isfinite(p.damping))
            return bad_plant_field(a, "damping", "must be a finite number > 0");
        if (!(p.stiffness > 0) || !std::isfinite(p.stiffness))
            return bad_plant_field(a, "stiffness", "must be a finite number > 0");
        if (!(p.coulomb >= 0) || !std::isfinite(p.coulomb))
            return bad_plant_field(a, "coulomb", "must be a finite number >= 0");
    }
    if (!finite_in(c.adaptation_time_s, 0.01, 600))
        return Error::invalid("adaptation_time_s", "must be a number in 0.01..600 s");
    if (!(c.adaptation_noise > 0) || !std::isfinite(c.adaptation_noise))
        return Error::invalid("adaptation_noise", "must be a finite number > 0 (position units)");
    if (!finite_in(c.adaptation_range, 1, 1e6))
        return Error::invalid("adaptation_range", "must be a number in 1..1e6");
    if (!(c.sensor_step > 0) || !std::isfinite(c.sensor_step))
        return Error::invalid("sensor_step", "must be a finite number > 0 (position units)");
    if (!finite_in(c.separation_hz, 0.5, 100)) return Error::invalid("separation_hz", "must be a number in 0.5..100 Hz");
    if (!Range{0, 1'000'000}.contains(c.blend_us)) return Error::out_of_range("blend_us", c.blend_us, {0, 1'000'000});
    return {};
}

void scale_activity(EngineActivity& activity, float factor) noexcept {
    if (!std::isfinite(factor)) factor = 0.0f;
    for (int i = 0; i < activity.count && i < kMaxActivityEffects; ++i) {
        for (float& f : activity.effects[i].force) f *= factor;
    }
    for (auto& per_class : activity.class_force) {
        for (float& f : per_class) f *= factor;
    }
}

void fit_activity_to_output(EngineActivity& activity, const TickOutput& out) noexcept {
    if (!out.saturated) return;
    for (int a = 0; a < kMaxAxes; ++a) {
        double total = 0;
        for (const auto& per_class : activity.class_force) total += per_class[a];
        const double output = out.force[a];
        const bool clamped = std::fabs(output) >= kFullScale;
        // Only when the waves alone would have pushed past the limit the same way.
        if (!clamped || !(std::fabs(total) > std::fabs(output)) || total * output <= 0) continue;
        const float factor = static_cast<float>(output / total);
        for (auto& per_class : activity.class_force) per_class[a] *= factor;
        for (int i = 0; i < activity.count && i < kMaxActivityEffects; ++i) activity.effects[i].force[a] *= factor;
    }
}

IdfFilter::IdfFilter(const IdfConfig& config) noexcept
    : config_(config), error_(check_idf_config(config)), settings_(config.settings) {
    if (error_) return;
    axes_ = config.axis_count;
    for (int a = 0; a < axes_; ++a) {
        AxisState& s = axis_[a];
        s.plant = config.plant[a];
        s.log_prior[kMass] = std::log(s.plant.mass);
        s.log_prior[kDamping] = std::log(s.plant.damping);
        s.log_prior[kStiffness] = std::log(s.plant.stiffness);
        for (int i = 0; i < 3; ++i) s.log_param[i] = s.log_prior[i];
    }
    blend_[kPeriodic] = settings_.periodic ? 1.0 : 0.0;
    blend_[kImpulse] = settings_.impulse ? 1.0 : 0.0;
}

void IdfFilter::reset() noexcept { started_ = false; }

const IdfPlant& IdfFilter::plant(int axis) const noexcept {
    static constexpr IdfPlant kNone{};
    return axis >= 0 && axis < axes_ ? axis_[axis].plant : kNone;
}

double IdfFilter::predicted_displacement(DisturbanceClass kind, int axis) const noexcept {
    if (axis < 0 || axis >= axes_) return 0;
    const Oscillator* w = axis_[axis].world;
    switch (kind) {
        case DisturbanceClass::periodic: return w[kAll].x - w[kWithoutPeriodic].x;
        case DisturbanceClass::impulse: return w[kAll].x - w[kWithoutImpulse].x;
        case DisturbanceClass::other: return 0;
    }
    return 0;
}

double IdfFilter::correction(int axis) const noexcept { return axis >= 0 && axis < axes_ ? axis_[axis].correction : 0; }

double IdfFilter::blend(DisturbanceClass kind) const noexcept { return blend_[static_cast<int>(kind)]; }

double IdfFilter::run_high_pass(HighPass& hp, double x) const noexcept {
    for (auto& section : hp.s) {
        const double y = hp_b_[0] * x + section[0];
        section[0] = hp_b_[1] * x - hp_a_[0] * y + section[1];
        section[1] = hp_b_[2] * x - hp_a_[1] * y;
        x = y;
    }
    return x;
}

// At rest with a constant input x: the first section's output is 0, so the second is empty.
void IdfFilter::settle_high_pass(HighPass& hp, double x) const noexcept {
    hp.s[0][0] = (hp_b_[1] + hp_b_[2]) * x;
    hp.s[0][1] = hp_b_[2] * x;
    hp.s[1][0] = hp.s[1][1] = 0;
}

// The first tick: the handle's history is unknown, so the effects' displacement starts at
// zero and the handle at rest. The identified plant is kept.
void IdfFilter::start(int64_t t_us, const float sensed_position[kMaxAxes]) noexcept {
    started_ = true;
    previous_t_us_ = t_us;
    hp_dt_s_ = 0;  // the high-passes settle on the first tick that has a length
    for (int a = 0; a < axes_; ++a) {
        AxisState& s = axis_[a];
        for (Oscillator& o : s.world) o = {};
        for (Oscillator& o : s.sensitivity) o = {};
        for (double& f : s.force) f = 0;
        s.undisturbed = std::isfinite(sensed_position[a]) ? sensed_position[a] : 0.0;
        s.undisturbed_velocity[0] = s.undisturbed_velocity[1] = 0;
        s.correction = 0;
    }
}

// Advances every world and the sensitivities over one tick of dt_s, with the forces held
// since the last tick, then identifies.
void IdfFilter::advance(AxisState& s, double dt_s, double sensed) noexcept {
    const IdfPlant& p = s.plant;
    const double fp = s.force[kPeriodic], fi = s.force[kImpulse], fo = s.force[kOther];
    const double world_force[kWorlds] = {fp + fi + fo, fi + fo, fp + fo, fo};
    // The undisturbed handle's velocity, zero within the noise of its estimate.
    const double still_band = kStillSteps * config_.sensor_step * 2 * std::numbers::pi * kVelocityCornerHz;
    const double vu_estimate = s.undisturbed_velocity[1];
    const double vu = std::fabs(vu_estimate) <= still_band ? 0.0 : vu_estimate - std::copysign(still_band, vu_estimate);
    // Friction stops and starts the handle within a tick (a 50 Hz vibration reverses every
    // 10 ticks at 1 kHz); resolved once per tick it would rectify the vibration into a slow
    // drift. So the worlds advance in substeps of at most kFrictionSubstepS.
    const int substeps =
        p.coulomb > 0 ? std::clamp(static_cast<int>(std::ceil(dt_s / kFrictionSubstepS)), 1, kMaxFrictionSubsteps)
                      : 1;
    const double h = dt_s / substeps;
    const Discrete d = discretize(p, h);
    const double stop_speed = h * p.coulomb / p.mass;  // what friction removes in a substep
    // Set-valued Coulomb friction: the velocity change friction makes in a substep to a
    // handle moving at v before friction (it stops a handle slower than stop_speed).
    auto friction = [stop_speed](double v) noexcept {
        return std::fabs(v) <= stop_speed ? -v : -std::copysign(stop_speed, v);
    };
    // What friction does to the undisturbed handle, which the disturbed one does not feel
    // unless it moves the same way: d gets the difference. With no effect, d stays 0.
    const double undisturbed_friction = friction(vu);

    const double x0 = s.world[kAll].x, v0 = s.world[kAll].v;
    for (int w = 0; w < kWorlds; ++w) {
        Oscillator& o = s.world[w];
        for (int n = 0; n < substeps; ++n) {
            const double x_start = o.x, v_start = o.v;
            step_linear(d, world_force[w], o.x, o.v);
            if (stop_speed > 0) {
                const double total = vu + o.v;
                o.v += friction(total) - undisturbed_friction;
                if (std::fabs(total) <= stop_speed) {
                    // Stuck: the handle stopped within the substep, so it moved only as far
                    // as its velocity took it (a handle at rest stays exactly where it is).
                    o.x = x_start + (v_start + o.v) * h / 2;
                } else {
                    o.x += (friction(total) - undisturbed_friction) * h / 2;  // over the substep
                }
            }
        }
    }

    // The sensitivities to ln m, ln b, ln k: the linear plant driven by minus its own
    // inertial, damping and spring forces, each held at its mean over the tick.
    const double x1 = s.world[kAll].x, v1 = s.world[kAll].v;
    const double spring = p.stiffness * (x0 + x1) / 2;
    const double damper = p.damping * (v0 + v1) / 2;
    const double drive[3] = {-(world_force[kAll] - damper - spring), -damper, -spring};
    const Discrete tick = substeps == 1 ? d : discretize(p, dt_s);
    for (int i = 0; i < 3; ++i) step_linear(tick, drive[i], s.sensitivity[i].x, s.sensitivity[i].v);

    // The undisturbed handle: the sensed position without every effect's displacement.
    const double undisturbed = sensed - x1;
    const double velocity = (undisturbed - s.undisturbed) / dt_s;
    s.undisturbed = undisturbed;
    const double smoothing = -std::expm1(-2 * std::numbers::pi * kVelocityCornerHz * dt_s);
    s.undisturbed_velocity[0] += smoothing * (velocity - s.undisturbed_velocity[0]);
    s.undisturbed_velocity[1] += smoothing * (s.undisturbed_velocity[0] - s.undisturbed_velocity[1]);

    if (config_.adapt) adapt(s, dt_s, sensed);
}

// One recursive Gauss-Newton step of the log-parameters on the high-passed prediction error.
void IdfFilter::adapt(AxisState& s, double dt_s, double sensed) noexcept {
    const double error = run_high_pass(s.hp_error, sensed - s.world[kAll].x);
    double g[3];
    for (int i = 0; i < 3; ++i) g[i] = run_high_pass(s.hp_sensitivity[i], s.sensitivity[i].x);

    // Running means of the sensitivities' outer product (the Gauss-Newton curvature) and of
    // the squared error, over kInformationTauS.
    const double mix = -std::expm1(-dt_s / kInformationTauS);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) s.information[i][j] += mix * (g[i] * g[j] - s.information[i][j]);
    }
    // The error to expect: noise, what recent ticks showed, and what the parameters'
    // uncertainty (a factor of two either way) can explain through this tick's sensitivities.
    const double noise_sq = config_.adaptation_noise * config_.adaptation_noise;
    const double g_sq = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    const double limit = kInnovationClip * std::sqrt(s.error_power + noise_sq + kParameterVariance * g_sq);
    s.error_power += mix * (error * error - s.error_power);
    if (std::fabs(sensed) >= kNearStop) return;  // maybe in an end stop: not the model
    const double innovation = std::clamp(error, -limit, limit);

    // Solve (R + g·gᵀ + σ²·(1 + λ)·I)·Δ = g·e − λ·σ²·(θ − θ_prior) (the essay above).
    const double pull = kPriorPull;
    double A[3][3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) A[i][j] = s.information[i][j] + g[i] * g[j] + (i == j ? noise_sq * (1 + pull) : 0.0);
    }
    const double c00 = A[1][1] * A[2][2] - A[1][2] * A[2][1];
    const double c01 = A[1][2] * A[2][0] - A[1][0] * A[2][2];
    const double c02 = A[1][0] * A[2][1] - A[1][1] * A[2][0];
    const double det = A[0][0] * c00 + A[0][1] * c01 + A[0][2] * c02;
    if (!(det > 0) || !std::isfinite(det) || !std::isfinite(innovation)) return;
    const double inverse[3][3] = {
        {c00, A[0][2] * A[2][1] - A[0][1] * A[2][2], A[0][1] * A[1][2] - A[0][2] * A[1][1]},
        {c01, A[0][0] * A[2][2] - A[0][2] * A[2][0], A[0][2] * A[1][0] - A[0][0] * A[1][2]},
        {c02, A[0][1] * A[2][0] - A[0][0] * A[2][1], A[0][0] * A[1][1] - A[0][1] * A[1][0]},
    };
    // Learn while the hand holds still: when it moves, friction couples its motion to the
    // effects' response in ways the model only approximates.
    const double moving = s.undisturbed_velocity[1] / kDeliberateSpeed;
    const double rate = std::min(1.0, dt_s / config_.adaptation_time_s) / (1 + moving * moving);
    const double range = std::log(config_.adaptation_range);
    double rhs[3];
    for (int i = 0; i < 3; ++i) rhs[i] = g[i] * innovation - pull * noise_sq * (s.log_param[i] - s.log_prior[i]);
    for (int i = 0; i < 3; ++i) {
        const double step = (inverse[i][0] * rhs[0] + inverse[i][1] * rhs[1] + inverse[i][2] * rhs[2]) / det;
        s.log_param[i] = std::clamp(s.log_param[i] + rate * step, s.log_prior[i] - range, s.log_prior[i] + range);
    }
    s.plant.mass = std::exp(s.log_param[kMass]);
    s.plant.damping = std::exp(s.log_param[kDamping]);
    s.plant.stiffness = std::exp(s.log_param[kStiffness]);
}

void IdfFilter::filter(int64_t t_us, const float sensed_position[kMaxAxes], const EngineActivity& activity,
                       float reported[kMaxAxes]) noexcept {
    for (int a = 0; a < kMaxAxes; ++a) reported[a] = sensed_position[a];
    if (error_) return;

    const double dt_s = started_ ? static_cast<double>(t_us - previous_t_us_) * 1e-6 : 0.0;
    if (!started_ || dt_s > kMaxGapS || dt_s < 0) {
        start(t_us, sensed_position);
    } else if (dt_s > 0) {
        if (dt_s != hp_dt_s_) {
            // 2nd-order Butterworth high-pass by the bilinear transform, prewarped.
            const double k = std::tan(std::numbers::pi * config_.separation_hz * dt_s);
            const double norm = 1 / (1 + std::numbers::sqrt2 * k + k * k);
            hp_b_[0] = norm;
            hp_b_[1] = -2 * norm;
            hp_b_[2] = norm;
            hp_a_[0] = 2 * (k * k - 1) * norm;
            hp_a_[1] = (1 - std::numbers::sqrt2 * k + k * k) * norm;
            if (hp_dt_s_ == 0) {
                for (int a = 0; a < axes_; ++a) {
                    AxisState& s = axis_[a];
                    settle_high_pass(s.hp_error, s.undisturbed);
                    for (HighPass& hp : s.hp_sensitivity) settle_high_pass(hp, 0);
                }
            }
            hp_dt_s_ = dt_s;
        }
        for (int a = 0; a < axes_; ++a) {
            const double sensed = sensed_position[a];
            advance(axis_[a], dt_s, std::isfinite(sensed) ? sensed : axis_[a].undisturbed + axis_[a].world[kAll].x);
        }
        previous_t_us_ = t_us;

        // Fade each class's correction toward the player's choice.
        const double fade = config_.blend_us > 0 ? dt_s * 1e6 / static_cast<double>(config_.blend_us) : 1.0;
        const bool wanted[kDisturbanceClassCount] = {settings_.periodic, settings_.impulse, false};
        for (int c = 0; c < kDisturbanceClassCount; ++c) {
            blend_[c] = wanted[c] ? std::min(1.0, blend_[c] + fade) : std::max(0.0, blend_[c] - fade);
        }
    }

    const double wp = blend_[kPeriodic], wi = blend_[kImpulse];
    for (int a = 0; a < axes_; ++a) {
        AxisState& s = axis_[a];
        // The forces the motors hold from now until the next tick.
        for (int c = 0; c < kDisturbanceClassCount; ++c) {
            const float f = activity.class_force[c][a];
            s.force[c] = std::isfinite(f) ? f : 0.0;
        }
        const Oscillator* w = s.world;
        s.correction = wp * (1 - wi) * (w[kAll].x - w[kWithoutPeriodic].x) +
                       (1 - wp) * wi * (w[kAll].x - w[kWithoutImpulse].x) +
                       wp * wi * (w[kAll].x - w[kOtherOnly].x);
        if (!std::isfinite(sensed_position[a])) continue;
        const double r = sensed_position[a] - s.correction;
        reported[a] = static_cast<float>(std::clamp(r, -static_cast<double>(kFullScale), static_cast<double>(kFullScale)));
    }
}

}  // namespace feel::runtime
