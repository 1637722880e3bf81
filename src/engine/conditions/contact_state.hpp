// Per-effect state of walls and barriers, kept in the effect's slot between ticks.
//
// The engine zeroes it when the effect is created and every time it starts, so a
// default-constructed ContactState means "no tick seen yet".
#pragma once

#include <cstdint>

namespace feel::detail {

struct ContactState {
    // Barriers (§3.8): the side of the barrier's center the handle is on, -1 (the negative
    // side) or +1; 0 until the first tick sets it from the handle's position. Pushing past
    // half the thickness flips it: the handle has popped through.
    int8_t side = 0;
    // Barriers: the crossing in progress while the handle is inside the slab, +1 if it
    // entered from the negative side (moving in +u, so pos_hardness governs the whole
    // crossing), -1 if from the positive side (neg_hardness); 0 while outside.
    int8_t crossing = 0;

    // The passivity ledger of the element's port (passivity.hpp). `observing` is false
    // until the first tick has recorded a coordinate and a force.
    bool observing = false;
    // The handle's coordinate along the element's direction u at the last tick, position
    // units (±10000 of travel, any finite value).
    double coordinate = 0.0;
    // The force along u the element commanded at the last tick (held until this tick),
    // force units ±10000, before effect and device gain.
    double force = 0.0;
    // The energy the sampled element has put out beyond what its ideal continuous-time
    // counterpart would have, force units · position units, >= 0 (the observer never
    // keeps credit). The controller dissipates it.
    double generated_energy = 0.0;
};

}  // namespace feel::detail
