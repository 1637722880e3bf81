// The piecewise exact integration of one control-law axis (tether_law.hpp).
#include "dynamics/tether_law.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "dynamics/tether_step.hpp"

namespace feel::detail {

namespace {

using Region = TetherRegion;

// The force on a mass that moves with the handle (in the handle's frame ṡ = 0 means
// ẋ = u), apart from the spring: gravity, the drag of moving at u, and the tether damper
// if it measures against a velocity other than u.
float free_force(const TetherLaw& law, const HandlePath& path) noexcept {
    return law.mass * law.gravity - law.drag * path.velocity - law.b * (path.velocity - path.damper_velocity);
}

// The same without the tether damper: in the free play the tether is slack.
float slack_force(const TetherLaw& law, const HandlePath& path) noexcept {
    return law.mass * law.gravity - law.drag * path.velocity;
}

Region classify(const TetherLaw& law, float s, float rate, float rest_force) noexcept {
    return tether_region(law.length, s, rate, rest_force);
}

// The linear segment of a region, in its local coordinate y: s − length above, s + length
// below, s in the slack. With the handle moving at u and the damper measuring against u_b,
// ẏ = ṡ and
//     M·ÿ = −k·y − b·(ẏ + u − u_b) − d·(ẏ + u) + M·g   ⇒   c = b + d,  f = M·g − d·u − b·(u − u_b).
SpringDamperF segment(const TetherLaw& law, Region r, const HandlePath& path) noexcept {
    switch (r) {
        case Region::above: return {law.mass, law.k_pos, law.b + law.drag, free_force(law, path)};
        case Region::below: return {law.mass, law.k_neg, law.b + law.drag, free_force(law, path)};
        case Region::slack: break;
    }
    return {law.mass, 0.0f, law.drag, slack_force(law, path)};
}

float local_origin(const TetherLaw& law, Region r) noexcept {
    switch (r) {
        case Region::above: return law.length;
        case Region::below: return -law.length;
        case Region::slack: break;
    }
    return 0.0f;
}

void count_half_cycle(const TetherLaw& law, TetherAxisState& state, float stretch, float hysteresis) noexcept {
    const int8_t side = stretch_side(law, stretch, hysteresis);
    if (side == 0 || side == state.side) return;
    if (state.side != 0) ++state.half_cycles;
    state.side = side;
}

}  // namespace

bool advance_tether_piece(const TetherLaw& law, TetherAxisState& state, float& s, float& rate,
                          const HandlePath& path, float h, float hysteresis, MassStateF first_end) noexcept {
    bool taut = false;
    const bool piecewise = law.length > 0 || law.k_pos != law.k_neg;
    const float rest_force = free_force(law, path);
    float remaining = h;
    int32_t switches = 0;
    while (remaining > 0) {
        const Region r = classify(law, s, rate, rest_force);
        taut = taut || r != Region::slack;
        const SpringDamperF seg = segment(law, r, path);
        const float origin = local_origin(law, r);
        const MassStateF start{s - origin, rate};
        // The piece to its end in this region (the caller's, for the whole piece), and
        // (below) the state where it leaves it.
        MassStateF end = switches == 0 ? first_end : tether_step(seg, start, remaining);
        float t = remaining;
        float snap_to = 0;
        bool crossed = false;
        if (piecewise && switches < kMaxRegionSwitches) {
            float tc = 0;
            MassStateF at = end;
            if (r == Region::slack) {
                // Either edge of the play, whichever comes first (the upper one is tried first).
                const MassStateF whole = end;
                for (const float edge : {law.length, -law.length}) {
                    if (tether_crossing(seg, start, whole, edge, remaining, tc, at) && tc < t) {
                        t = tc;
                        end = at;
                        snap_to = edge;
                        crossed = true;
                    }
                }
            } else if (tether_crossing(seg, start, end, 0.0f, remaining, tc, at) && tc < remaining) {
                t = tc;
                end = at;
                snap_to = origin;  // back onto the edge the region starts at
                crossed = true;
            }
        }
        s = crossed ? snap_to : end.position + origin;
        rate = end.velocity;
        remaining = crossed ? remaining - t : 0.0f;
        if (crossed) ++switches;
        // Only a law that ends after some half cycles counts them (advance_watched_tether's
        // pieces too): the others' count is never read, and keeping it untouched lets a kept
        // prediction stand for the whole state (control_law_dynamic.cpp).
        if (law.half_cycles > 0) count_half_cycle(law, state, s, hysteresis);
    }
    return taut;
}

float rest_stretch(const TetherLaw& law) noexcept {
    const float weight = law.mass * law.gravity;
    if (weight > 0) return law.length + weight / law.k_pos;
    if (weight < 0) return -law.length + weight / law.k_neg;
    return 0.0f;
}

float tether_reaction(const TetherLaw& law, float stretch, float stretch_rate) noexcept {
    // On an edge of the play (or at 0 without play) the tether is taut if the mass is
    // moving out: a kick from the handle meets the damper at once.
    const float edge = law.length;
    if (stretch > edge || (stretch == edge && stretch_rate > 0)) {
        return law.k_pos * (stretch - edge) + law.b * stretch_rate;
    }
    if (stretch < -edge || (stretch == -edge && stretch_rate < 0)) {
        return law.k_neg * (stretch + edge) + law.b * stretch_rate;
    }
    return 0.0f;
}

int8_t stretch_side(const TetherLaw& law, float stretch, float hysteresis) noexcept {
    const float e = stretch - rest_stretch(law);
    if (e > hysteresis) return 1;
    if (e < -hysteresis) return -1;
    return 0;
}

}  // namespace feel::detail
