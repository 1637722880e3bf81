// Dynamic Inertia on smooth motions (issue 16's review, §5.6 and §8.4): a kinematic hand
// moves the handle along sines and circles and the force it feels is compared with the
// force of a point mass, −M·a, where a is the second derivative of the motion itself
// (a sine of amplitude A at f Hz: a = −(2πf)²·A·sin(2πf·t)) and M is the documented §8.4
// mapping Inertia → Mass (M = Inertia/10000 · dynamic_mass_ref, docs/dynamics.md), never a
// value fitted from the rendered force.
//
// §5.6: "Dynamic_Inertia is a new command that enables accurate weight simulation", and
// "Inertia defines the felt weight of the joystick, wheel, or other gaming device"; "Play
// defines a gap of free motion between the stick and the mass", so with Play 0 the mass is
// coupled to the stick and is felt as its weight: the force of a mass M moved along the
// handle's path, −M·a. The coupling is §8.4's tether, which lets the mass lag a little: the comparison allows up to 30 ms of lag (the lag that fits
// best within 0..30 ms is searched), an error within 35% of the peak inertial force, and
// tick-to-tick jitter (the change of F from one tick to the next, less the change of −M·a)
// below 5% of it. These are the bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "feel/sim/device_profile.hpp"
#include "friction_loop.hpp"

namespace feel::test {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct InertiaFit {
    double peak = 0;        // the peak of M·|a|, force units
    double error = 0;       // the largest |F − (−M·a(t − lag))| at the best lag, force units
    double lag_s = 0;       // that lag
    double jitter = 0;      // the largest |ΔF − Δ(−M·a)| from one tick to the next, force units
};

// The acceleration of the kinematic motion on `axis` at time t: a sine on x of amplitude A
// and f Hz, or a circle of radius A (x = A·cos, y = A·sin).
using Acceleration = double (*)(double amplitude, double hz, double t, int axis);

double sine_acceleration(double amplitude, double hz, double t, int) {
    const double w = kTwoPi * hz;
    return -w * w * amplitude * std::sin(w * t);
}

double circle_acceleration(double amplitude, double hz, double t, int axis) {
    const double w = kTwoPi * hz;
    return -w * w * amplitude * (axis == 0 ? std::cos(w * t) : std::sin(w * t));
}

InertiaFit fit(const std::vector<LoopRow>& rows, double mass, double amplitude, double hz, Acceleration acc,
               int axes, double settle_s) {
    InertiaFit best;
    best.error = 1e300;
    const double w = kTwoPi * hz;
    const double peak = mass * w * w * amplitude;
    for (double lag = 0; lag <= 0.030 + 1e-9; lag += 0.0005) {
        double error = 0;
        for (const LoopRow& r : rows) {
            if (r.t_s < settle_s) continue;
            for (int a = 0; a < axes; ++a) {
                error = std::max(error, std::fabs(r.force[a] + mass * acc(amplitude, hz, r.t_s - lag, a)));
            }
        }
        if (error < best.error) {
            best.error = error;
            best.lag_s = lag;
        }
    }
    best.peak = peak;
    for (size_t i = 1; i < rows.size(); ++i) {
        if (rows[i - 1].t_s < settle_s) continue;
        for (int a = 0; a < axes; ++a) {
            const double expected = -mass * (acc(amplitude, hz, rows[i].t_s - best.lag_s, a) -
                                             acc(amplitude, hz, rows[i - 1].t_s - best.lag_s, a));
            best.jitter = std::max(best.jitter, std::fabs(rows[i].force[a] - rows[i - 1].force[a] - expected));
        }
    }
    return best;
}

void expect_feels_like_a_mass(const InertiaFit& f) {
    EXPECT_LE(f.error, 0.35 * f.peak) << "lag " << f.lag_s * 1e3 << " ms";
    EXPECT_LE(f.jitter, 0.05 * f.peak);
}

TEST(DynamicInertiaClosedLoop, OnSinesTheForceIsTheMassTimesTheAcceleration) {
    // The review's case, sine:x:2000:1 with inertia 10000, and the span the issue asks for:
    // sines of 0.5 to 5 Hz, inertia 3000 and 10000, at 500 Hz, 1 kHz and 10 kHz. The
    // amplitudes keep the peak acceleration within what a hand does (at most 5·10⁵ units/s²,
    // acceleration_ref's 5 times) and the force within the motor's range.
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const EngineConfig config = sim::engine_config_for(joystick);
    struct Sine {
        double amplitude, hz;
    };
    for (double rate : {500.0, 1000.0, 10000.0}) {
        for (int32_t inertia : {3000, 10000}) {
            for (const Sine s : {Sine{2000, 1}, Sine{4000, 0.5}, Sine{1000, 2}, Sine{500, 5}}) {
                SCOPED_TRACE(std::to_string(rate) + " Hz, inertia " + std::to_string(inertia) + ", sine " +
                             std::to_string(s.amplitude) + " at " + std::to_string(s.hz) + " Hz");
                const double mass = inertia / 10000.0 * config.dynamic_mass_ref;  // §8.4: Inertia → Mass
                const std::string motion =
                    "sine:x:" + std::to_string(static_cast<int>(s.amplitude)) + ":" + std::to_string(s.hz);
                const double duration = 1.0 / s.hz + 0.5;
                const auto rows = run_loop("joystick", sim::Grip::kinematic, motion,
                                           {dynamic_inertia_on({Axis::x}, inertia)}, duration, rate);
                expect_feels_like_a_mass(fit(rows, mass, s.amplitude, s.hz, sine_acceleration, 1, 0.5));
            }
        }
    }
}

TEST(DynamicInertiaClosedLoop, OnEveryProfileTheForceIsTheMassTimesTheAcceleration) {
    // The same on the wheel and the 3-axis device (their own mass scale, dynamic_mass_ref),
    // the review's sine at the three loop rates.
    for (const char* profile_name : {"wheel", "3axis"}) {
        const EngineConfig config = sim::engine_config_for(*sim::find_device_profile(profile_name));
        for (double rate : {500.0, 1000.0, 10000.0}) {
            for (int32_t inertia : {3000, 10000}) {
                SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz, inertia " +
                             std::to_string(inertia));
                const double mass = inertia / 10000.0 * config.dynamic_mass_ref;
                const auto rows = run_loop(profile_name, sim::Grip::kinematic, "sine:x:2000:1",
                                           {dynamic_inertia_on({Axis::x}, inertia)}, 1.5, rate);
                expect_feels_like_a_mass(fit(rows, mass, 2000, 1, sine_acceleration, 1, 0.5));
            }
        }
    }
}

TEST(DynamicInertiaClosedLoop, OnACircleEachAxisFeelsTheMassTimesItsAcceleration) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const EngineConfig config = sim::engine_config_for(joystick);
    for (double rate : {500.0, 1000.0, 10000.0}) {
        SCOPED_TRACE(std::to_string(rate) + " Hz");
        const double mass = config.dynamic_mass_ref;  // inertia 10000
        const auto rows = run_loop("joystick", sim::Grip::kinematic, "circle:2000:1",
                                   {dynamic_inertia_on({Axis::x, Axis::y}, 10000)}, 1.5, rate);
        expect_feels_like_a_mass(fit(rows, mass, 2000, 1, circle_acceleration, 2, 0.5));
    }
}

TEST(DynamicInertiaClosedLoop, TheMassIsProportionalToTheInertiaAndTheSameForEveryMotion) {
    // §8.4: Inertia → Mass. Fitting M from the force (least squares of F against −a) on
    // different sines must give the same M for every motion, and M ∝ Inertia.
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const EngineConfig config = sim::engine_config_for(joystick);
    for (int32_t inertia : {3000, 6000, 10000}) {
        for (double hz : {0.5, 1.0, 2.0, 5.0}) {
            SCOPED_TRACE("inertia " + std::to_string(inertia) + " at " + std::to_string(hz) + " Hz");
            const double amplitude = std::min(4000.0, 5e5 / (kTwoPi * hz * kTwoPi * hz));
            const std::string motion = "sine:x:" + std::to_string(amplitude) + ":" + std::to_string(hz);
            const auto rows = run_loop("joystick", sim::Grip::kinematic, motion,
                                       {dynamic_inertia_on({Axis::x}, inertia)}, 1.0 / hz + 0.5);
            double fa = 0, aa = 0;
            for (const LoopRow& r : rows) {
                if (r.t_s < 0.5) continue;
                const double a = sine_acceleration(amplitude, hz, r.t_s, 0);
                fa += -r.force[0] * a;
                aa += a * a;
            }
            const double fitted = fa / aa;
            EXPECT_NEAR(fitted, inertia / 10000.0 * config.dynamic_mass_ref, 0.1 * inertia / 10000.0 * config.dynamic_mass_ref);
        }
    }
}

}  // namespace
}  // namespace feel::test
