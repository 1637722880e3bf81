// The passivity observer and controller of contact ports; see passivity.hpp for the method.
#include "conditions/passivity.hpp"

#include <algorithm>
#include <cmath>

#include "feel/units.hpp"
#include "float_select.hpp"
#include "int64_to_float.hpp"

namespace feel::detail {

namespace {

// The controller's damping is at most k·T (in ticks of the element's stiffness k): a
// damper that removes k·v²·T² per tick, twice the K·v²·T²/2 the sampled spring creates,
// so it can cancel the creation as it happens and repay older debt at the same rate. It
// changes the force by at most k·|v|·T, the force change of one tick of motion, so it
// never jolts the handle; and k·T²/m stays far below 2 (the discrete damper's own
// stability limit) for any wall the device can render without the wall itself aliasing.
constexpr float kDampingCeilingTicks = 1.0f;

constexpr float kLimit = static_cast<float>(kFullScale);

// A tick's booking is clamped to this many energy units before it becomes ledger units,
// and the ledger to kLedgerCeiling, so neither can overflow int64 (the largest a real
// port books is a full-scale force over the whole travel, about 10^9; booked, at most
// 10^12 · 65536 < 2^56, is within truncate_to_int64's range).
constexpr float kLargestBooking = 1e12f;
constexpr int64_t kLedgerCeiling = int64_t{1} << 62;

// A tick's booking within this fraction of its two terms' size (2^-20, eight ulps of
// float) is their rounding, not energy.
constexpr float kRoundingSlack = 1.0f / 1048576.0f;

}  // namespace

float saturated_spring_energy(float k, float depth) noexcept {
    if (!(depth > 0) || k == 0) return 0.0f;
    const float stiffness = std::fabs(k);
    const float saturation_depth = kLimit / stiffness;
    const float magnitude = depth <= saturation_depth ? 0.5f * stiffness * depth * depth
                                                      : kLimit * depth - 0.5f * kLimit * saturation_depth;
    return k > 0 ? magnitude : -magnitude;
}

float saturated_spring_energy_change(float k, float from, float to) noexcept {
    if (k == 0) return 0.0f;
    const float stiffness = std::fabs(k);
    const float saturation_depth = kLimit / stiffness;
    // The force grows linearly up to the saturation depth and is constant beyond: the
    // change is the linear part's ½k·(b² − a²) over the depths clamped to it, plus the
    // constant part's L·(the distance moved beyond it).
    const float a = std::clamp(from, 0.0f, saturation_depth);
    const float b = std::clamp(to, 0.0f, saturation_depth);
    const float linear = 0.5f * stiffness * (b - a) * (b + a);
    const float saturated = kLimit * (std::max(to, saturation_depth) - std::max(from, saturation_depth));
    const float magnitude = linear + saturated;
    return k > 0 ? magnitude : -magnitude;
}

float saturated_spring_force(float k, float depth) noexcept {
    if (!(depth > 0)) return 0.0f;
    return -std::clamp(k * depth, -kLimit, kLimit);
}

float generated_energy(const ContactState& state) noexcept {
    return float_of_int64(state.generated_energy) / kLedgerScale;
}

float passive_port_force(ContactState& state, const PortTick& tick, bool control) noexcept {
    if (state.observing) {
        // The element held state.force over the tick while the handle moved by ds, so the
        // handle did −force·ds of work on it; the ideal element's storage changed by
        // ideal_energy_change. The excess is what the sampling created.
        const float ds = tick.coordinate - state.coordinate;
        const float work = state.force * ds;
        float generated = tick.ideal_energy_change + work;
        // A handle a hair across a count boundary reads as a whole count of motion, so
        // one count's worth of what a tick books, ½·k·q² (less for a smaller move), may
        // be the sensor's and not the handle's: forgive it. A flicker between two counts
        // books nothing; a move of n counts keeps (n² − 1)/n² of its k·Δs²/2.
        const float doubt =
            0.5f * std::fabs(tick.stiffness) * std::min(std::fabs(ds), tick.resolution) * tick.resolution;
        // Only a positive booking is forgiven. What is left within float's rounding of the
        // two terms (a few ulps of each) is not energy anyone can tell from zero: a flicker
        // forgiven in exact arithmetic must not leave its rounding residue in the ledger,
        // tick after tick. (Worked out whatever the booking's sign and then selected, without
        // a jump: on a wall in contact the booking is positive or not about every other tick,
        // at random, and a jump on it was mispredicted about one call in three: issue 14,
        // twelfth pass, "The conditions' branches".)
        const float rounding = (std::fabs(tick.ideal_energy_change) + std::fabs(work)) * kRoundingSlack;
        const float forgiven = generated - doubt;
#if defined(__OPTIMIZE_SIZE__)
        // (The Cortex-M4F predicts no branch: the build for size jumps, which is shorter.)
        if (generated > 0) generated = forgiven <= rounding ? 0.0f : forgiven;
#else
        const float kept = select_float(forgiven <= rounding, 0.0f, forgiven);
        generated = select_float(generated > 0, kept, generated);
#endif
        if (std::isfinite(generated)) {
            // Exact from here on: an integer sum (passivity.hpp, "single precision").
            const float booked = std::clamp(generated, -kLargestBooking, kLargestBooking) * kLedgerScale;
            const int64_t total = state.generated_energy + truncate_to_int64(booked);
            state.generated_energy = std::clamp(total, int64_t{0}, kLedgerCeiling);
        } else {
            state.generated_energy = 0;
        }
    }

    float force = tick.force;
    if (control && state.generated_energy > 0 && tick.dt_s > 0 && force != 0 && tick.velocity != 0) {
        const float ledger = float_of_int64(state.generated_energy) * (1.0f / kLedgerScale);
        const float speed = std::fabs(tick.velocity);
        const float travel = std::max(speed * tick.dt_s, tick.resolution);
        const float wanted = ledger / (speed * travel);
        const float ceiling = kDampingCeilingTicks * std::fabs(tick.stiffness) * tick.dt_s;
        const float damping = std::min(wanted, ceiling);
        float damped = force - damping * tick.velocity;
        if (damped * force < 0) damped = 0;  // never reverse: a wall pushes, it does not pull
        force = std::clamp(damped, -kLimit, kLimit);
    }

    state.observing = true;
    state.coordinate = tick.coordinate;
    state.force = force;
    return force;
}

}  // namespace feel::detail
