// The passivity observer and controller of contact ports; see passivity.hpp for the method.
#include "conditions/passivity.hpp"

#include <algorithm>
#include <cmath>

#include "feel/units.hpp"

namespace feel::detail {

namespace {

// The controller's damping is at most k·T (in ticks of the element's stiffness k): a
// damper that removes k·v²·T² per tick, twice the K·v²·T²/2 the sampled spring creates,
// so it can cancel the creation as it happens and repay older debt at the same rate. It
// changes the force by at most k·|v|·T, the force change of one tick of motion, so it
// never jolts the handle; and k·T²/m stays far below 2 (the discrete damper's own
// stability limit) for any wall the device can render without the wall itself aliasing.
constexpr double kDampingCeilingTicks = 1.0;

}  // namespace

double saturated_spring_energy(double k, double depth) noexcept {
    if (!(depth > 0) || k == 0) return 0.0;
    const double limit = kFullScale;
    const double stiffness = std::fabs(k);
    const double saturation_depth = limit / stiffness;
    const double magnitude = depth <= saturation_depth
                                 ? 0.5 * stiffness * depth * depth
                                 : limit * depth - 0.5 * limit * saturation_depth;
    return k > 0 ? magnitude : -magnitude;
}

double saturated_spring_force(double k, double depth) noexcept {
    if (!(depth > 0)) return 0.0;
    const double limit = kFullScale;
    return -std::clamp(k * depth, -limit, limit);
}

double passive_port_force(ContactState& state, const PortTick& tick, bool control) noexcept {
    if (state.observing) {
        // The element held state.force over the tick while the handle moved by ds, so the
        // handle did −force·ds of work on it; the ideal element's storage changed by
        // ideal_energy_change. The excess is what the sampling created.
        const double ds = tick.coordinate - state.coordinate;
        double generated = tick.ideal_energy_change + state.force * ds;
        // A handle a hair across a count boundary reads as a whole count of motion, so
        // one count's worth of what a tick books, ½·k·q² (less for a smaller move), may
        // be the sensor's and not the handle's: forgive it. A flicker between two counts
        // books nothing; a move of n counts keeps (n² − 1)/n² of its k·Δs²/2.
        const double doubt =
            0.5 * std::fabs(tick.stiffness) * std::min(std::fabs(ds), tick.resolution) * tick.resolution;
        if (generated > 0) generated = std::max(0.0, generated - doubt);
        const double total = state.generated_energy + generated;
        state.generated_energy = std::isfinite(total) ? std::max(0.0, total) : 0.0;
    }

    double force = tick.force;
    if (control && state.generated_energy > 0 && tick.dt_s > 0 && force != 0 && tick.velocity != 0) {
        const double speed = std::fabs(tick.velocity);
        const double travel = std::max(speed * tick.dt_s, tick.resolution);
        const double wanted = state.generated_energy / (speed * travel);
        const double ceiling = kDampingCeilingTicks * std::fabs(tick.stiffness) * tick.dt_s;
        const double damping = std::min(wanted, ceiling);
        double damped = force - damping * tick.velocity;
        if (damped * force < 0) damped = 0;  // never reverse: a wall pushes, it does not pull
        force = std::clamp(damped, -static_cast<double>(kFullScale), static_cast<double>(kFullScale));
    }

    state.observing = true;
    state.coordinate = tick.coordinate;
    state.force = force;
    return force;
}

}  // namespace feel::detail
