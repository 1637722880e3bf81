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
    float coordinate = 0.0f;
    // The force along u the element commanded at the last tick (held until this tick),
    // force units ±10000, before effect and device gain.
    float force = 0.0f;
    // The energy the sampled element has put out beyond what its ideal continuous-time
    // counterpart would have, in ledger units (1/kLedgerScale of a force unit · position
    // unit: passivity.hpp), >= 0 (the observer never keeps credit). An integer, so the
    // sum of many small bookings stays exact. The controller dissipates it.
    int64_t generated_energy = 0;
};

}  // namespace feel::detail
