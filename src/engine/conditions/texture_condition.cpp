// Texture (§3.6, §6.6.j): a grating of bumps that resist the motion across them.
//
//   s     = the handle's coordinate along the texture's line: its axis, or for a texture
//           on several axes the unit vector u of its direction (u = (sin a, cos a) for a
//           polar angle a; the §7.5 washboard on x, y at polar 0 runs along y)
//   w     = spacing · density / 10000, the bump width
//   z     = a Dahl bristle along s (friction_model.hpp): +1 moving toward +s, -1 toward -s,
//           a smooth turn-around between
//   F_s   = -R·bump(s)·z + microdamping,  R = pos_roughness while z >= 0, neg_roughness
//           while z < 0 (the bristle's microdamping scaled by the bump, friction_model.hpp)
//   F     = F_s along the line (on each axis a, F_s·u_a)
//
// The primer calls a texture "a spatially varying resistance" (§3.1) whose intensity can
// differ with the direction of travel (§3.6): here every bump is a patch of friction of
// strength R·bump(s). Dragged across the grating the handle meets a resistance that rises
// and falls once per spacing, felt as a rattle whose pitch follows the speed; at rest it
// holds still. Because the force always opposes the motion it only dissipates: a texture
// cannot make the handle unstable however fine its spacing, which a conservative washboard
// (a force pushing the handle into the gaps) of useful depth could, being a spring far
// stiffer than the device's passivity bound.
//
// The bump is a raised cosine, 1 on its top (s a multiple of spacing) and 0 beyond w/2:
//
//   bump                       spacing
//     1 |     _               <------->     _
//       |    / \                           / \            density 3000: w = 0.3 spacing
//       |   /   \                         /   \          (s = 0 is a bump's top)
//     0 +--'-----'-------------------------'-----'------- s
//       -w/2  0  w/2                  spacing
#include "conditions/condition_math.hpp"

namespace feel::detail {

void texture_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept {
    const EffectParams& p = *c.params;
    const TextureBlock& t = p.texture;
    double u[kMaxAxes] = {};
    if (p.axis_count == 1) {
        u[device_axis(c, 0)] = 1.0;
    } else {
        condition_line(c, u);
    }
    const double s = along(u, c.position);
    const double roughness = t.pos_roughness > t.neg_roughness ? t.pos_roughness : t.neg_roughness;
    const double presliding = presliding_distance(*c.config, c.dt_s, roughness);
    const double z = advance(c.state->friction.bristle[0], static_cast<float>(s), 0.0f, static_cast<float>(presliding));
    const double width = static_cast<double>(t.spacing) * t.density / kFullScale;
    const double bump = texture_bump(s, t.spacing, width);
    double f = -(z >= 0 ? t.pos_roughness : t.neg_roughness) * bump * z;
    if (presliding > 0 && c.dt_s > 0) f += bristle_damping(*c.config, roughness * bump / presliding, z, along(u, c.velocity));
    for (int a = 0; a < kMaxAxes; ++a) force[a] += f * u[a];
}

}  // namespace feel::detail
