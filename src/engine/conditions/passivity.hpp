// Time-domain passivity for walls and barriers: an observer that keeps the energy ledger of
// the element's port and a controller that dissipates what the sampling has created.
//
// Why walls go unstable. A wall is a stiff spring F = −K·p evaluated once per tick and
// held until the next (zero-order hold). While the handle moves, the held force always
// lags the ideal one: going in it pushes back too little, coming out too much. Each tick
// the sampled spring therefore puts out K·Δp²/2 more energy than a real spring would; the
// device's own damping b removes b·v²·T. Colgate and Schenkel showed the sampled wall is
// passive only while K ≤ 2(b − B)/T (B: any virtual damping, T: the tick). Above that a
// handle resting against the wall rings in a limit cycle. docs/stability.md tabulates the
// bound of every device profile.
//
// The observer (Hannaford & Ryu, "Time-domain passivity control of haptic interfaces",
// 2002, with the reference energy of Ryu, Preusche, Hannaford & Hirzinger, "Time domain
// passivity control with reference energy following", 2005). The port is the handle's
// coordinate s along the element's direction u and the force F along u. Over the tick
// from n−1 to n the element received −F(n−1)·(s(n) − s(n−1)) from the handle; its ideal
// continuous-time counterpart (a real spring, saturated like the motor) would have changed
// its stored energy by U(s(n)) − U(s(n−1)). The difference is energy the sampled element
// made out of nothing:
//
//     E(n) = max(0, E(n−1) + [U(s(n)) − U(s(n−1))] + F(n−1)·(s(n) − s(n−1)))
//
// Using the ideal element's stored energy as the reference (instead of Hannaford & Ryu's
// plain "energy in ≥ 0") matters for a wall: a handle pressed into a spring holds a large
// stored energy, and the plain observer would let the ringing grow until that whole
// reservoir is spent before it acts. The reference ledger sees the K·Δp²/2 of every tick.
// The ledger keeps no credit (E ≥ 0): energy dissipated once never licenses a later burst.
// Positions are the sensor's, so the ledger is exact for the trajectory the sensor saw.
//
// The sensor's resolution. A handle dithering across one count boundary reads as a whole
// count of motion each time, so the ledger would book K·q²/2 (q: one count) per flicker
// for motion that hardly happened, and spend it later as a dead wall. Each tick therefore
// forgives one count's worth, ½·K·q·min(|Δs|, q): a one-count flicker books nothing, a
// move of n counts keeps (n² − 1)/n² of its K·Δs²/2. What this leaves unwatched is motion
// of about a count per tick or less: there the sampled wall may create up to ½·K·q² a
// tick unseen, which the mechanism's Coulomb friction must absorb (docs/stability.md
// gives each profile's margin). For moves of several counts the booking lies between the
// least the true motion could have created and its average; erring high only makes the
// controller dissipate a little more than needed, which is safe.
//
// The controller: a variable damper, Hannaford & Ryu's α = E/(v²·T), that spends the
// ledger over the next tick,
//
//     F_out = F − α·v,   α = min(E / (|v|·max(|v|·T, q)),  k·T)
//
//   * max(|v|·T, q): at speeds under one count per tick, over the next count the sensor
//     can resolve instead (a slow handle crosses a count in several ticks; spending E
//     every tick would overspend it);
//   * the ceiling k·T: a damper that removes k·v²·T² per tick, twice what the sampled
//     spring creates, and changes the force by at most k·|v|·T, one tick of motion. An
//     unbounded α (a force E/(|v|T) at a near-zero speed estimate) slams the force to
//     zero and back; the handle reverses inside the tick, the ledger charges the cut to
//     the element, and the controller itself chatters. Bounded, it is smooth;
//   * F_out keeps the sign of F (a wall pushes, it never pulls) and stays within ±10000.
//
// While the handle goes in the damper stiffens the wall a little, while it comes out it
// softens it: within what the sensor can resolve, the wall returns no more energy than a
// continuous spring would, and the device's own damping and friction make contact settle. What the damper cannot spend
// in one tick stays in the ledger.
//
// Single precision with an exact ledger (issue 14 §2). The port's readings, forces and
// the controller are float. The ledger is not: it sums, tick after tick, small differences
// of large energies (a wall pressed 10000 units deep at full force stores 10^8), and a float
// sum would lose each tick's few units in the rounding of the total. Two things keep it
// exact:
//   * each tick's ideal energy change U(s(n)) − U(s(n−1)) is computed as one difference
//     (saturated_spring_energy_change: ½k·(b − a)·(b + a) plus the saturated part's
//     L·Δ), never as two stored energies subtracted, so its rounding is float's relative
//     7 digits of the change, not of the energy stored;
//   * the ledger is a 64-bit integer in units of 2^-16 of an energy unit, so adding a
//     tick's booking to it is exact however large it grows. Scaling a float by a power of
//     two is exact, so a booking of 256 units or more (whose float ulp is at least 2^-15)
//     enters the ledger without any rounding; smaller ones are cut to 2^-16 of a unit, far
//     below the ½·k·q² the observer forgives each tick (670 units with the default wall
//     stiffness at hardness 10000, 67 at hardness 1000).
// On the Cortex-M4F that is a handful of FPU instructions and two integer conversions a
// tick instead of the soft-float double it used to be.
//
// Real-time safe: a few multiplications, no allocation, state only in ContactState.
#pragma once

#include <cmath>
#include <cstdint>

#include "conditions/contact_state.hpp"

namespace feel::detail {

// Ledger units per energy unit (force units · position units).
inline constexpr float kLedgerScale = 65536.0f;

// static_cast<int64_t>(x), truncating toward zero, for |x| < 2^63, in 32-bit conversions:
// a float's cast to int64 is libgcc's __aeabi_f2lz on the Cortex-M4F, which computes in
// soft-float double. Exact: a float of magnitude 2^31 or more has at most 24 significant
// bits, all at 2^8 or above, so the integer part of x·2^-32 has at most 24 and times 2^32
// is a float, and what is left of x (a multiple of 2^8 below 2^32 in magnitude, with the
// sign of x) is a float too, whose unsigned cast is one instruction.
[[nodiscard]] inline int64_t truncate_to_int64(float x) noexcept {
    if (x > -2147483648.0f && x < 2147483648.0f) return static_cast<int32_t>(x);
    const int32_t high = static_cast<int32_t>(x * 0x1p-32f);
    const float low = x - static_cast<float>(high) * 0x1p32f;  // the sign of x, |low| < 2^32
    const int64_t low_part = low >= 0 ? int64_t{static_cast<uint32_t>(low)} : -int64_t{static_cast<uint32_t>(-low)};
    return int64_t{high} * 4294967296 + low_part;
}

// One tick of a contact port.
struct PortTick {
    float coordinate = 0;           // s(n): the sensed position along u, position units
    float ideal_energy_change = 0;  // U(s(n)) − U(s(n−1)) of the ideal element (ignored on the first tick)
    float force = 0;                // the ideal element's force along u this tick, ±10000
    float stiffness = 0;            // the ideal element's k (|dF/ds| in contact), force units per position unit
    float velocity = 0;             // estimated ds/dt, position units/s
    float dt_s = 0;                 // the tick period T, s (0 on the engine's first tick)
    float resolution = 0;           // the sensor's step along u, position units, > 0
};

// Updates the ledger with this tick's reading and returns the force along u to command.
// With control off the observer still runs (the ledger shows what a naive element
// generates) and the force is returned unchanged.
float passive_port_force(ContactState& state, const PortTick& tick, bool control) noexcept;

// A tick of a port out of contact (docs/conditions.md, "Out of contact"): the depth
// into(s − surface) into the element was not positive at the last tick nor is it now at
// s = coordinate, and the force it held did no work (a zero force over a finite move, or
// any force over no move). passive_port_force would then book ±0 (the ideal element stored
// nothing at either end), leave the ledger alone and return the element's zero
// force, into · 0. If this tick is such a tick, records it as passive_port_force would
// (state.force is then the force to command) and returns true, so the element need not
// work out its stiffness, energy or rubbing; otherwise returns false and changes nothing.
// (Inline: every tick of every wall and barrier calls it, most of them out of contact.)
inline bool port_out_of_contact(ContactState& state, float coordinate, float into, float surface) noexcept {
    const float depth = into * (coordinate - surface);
    const float previous_depth = into * (state.coordinate - surface);
    // The work the held force did is passive_port_force's `work`, exactly: zero when the
    // force was zero over a finite move (or, after an update moved the surface, a force held
    // over no move at all); any other value, a NaN of an infinite move among them, is left
    // to passive_port_force.
    if (!(depth <= 0 && previous_depth <= 0 && state.force * (coordinate - state.coordinate) == 0)) return false;
    state.observing = true;
    state.coordinate = coordinate;
    state.force = into * 0.0f;
    return true;
}

// A contact element's tick in contact: the port's reading at coordinate s with the ideal
// element's energy change, force along u and stiffness k, the handle's velocity along u,
// the tick and the sensor's step, through passive_port_force (the commanded force is then
// state.force). Returns the ideal force's magnitude, the pressure on the surface.
inline float press_port(ContactState& state, float s, float ideal_energy_change, float ideal_force, float k,
                        float velocity, float dt_s, float resolution, bool control) noexcept {
    PortTick tick;
    tick.coordinate = s;
    tick.ideal_energy_change = ideal_energy_change;
    tick.force = ideal_force;
    tick.stiffness = std::fabs(k);
    tick.velocity = velocity;
    tick.dt_s = dt_s;
    tick.resolution = resolution;
    passive_port_force(state, tick, control);
    return std::fabs(ideal_force);
}

// The energy the ledger holds, in energy units (force units · position units), in float
// (2^-24 of it: the ledger's own resolution is 1/kLedgerScale).
[[nodiscard]] float generated_energy(const ContactState& state) noexcept;

// The energy stored in a spring of stiffness k (force units per position unit, any sign)
// compressed by depth (position units; none when depth <= 0), whose force saturates at the
// motor's full scale, 10000: the potential of F = −clamp(k·depth, ±10000).
float saturated_spring_energy(float k, float depth) noexcept;

// saturated_spring_energy(k, to) − saturated_spring_energy(k, from), computed as one
// difference so that its rounding is relative to the change, not to the energy stored.
float saturated_spring_energy_change(float k, float from, float to) noexcept;

// The force of that spring along its depth direction: −clamp(k·depth, ±10000), 0 when
// depth <= 0.
float saturated_spring_force(float k, float depth) noexcept;

}  // namespace feel::detail
