// §8.2 Condition function wrappers: springs, dampers, inertias, frictions, textures, walls
// and barriers, built as §8.5's sample code fills its DICONDITION, DITEXTURE, DIWALL and
// DIBARRIER structures.
//
// Ranges: §8.2's tables. They equal the engine's (units.hpp) except for inertia (mass and
// saturation 1..10000) and friction (0..10000), where the primer is narrower and wins.
#include <string>

#include "feel/iforce.hpp"
#include "wrapper_args.hpp"

namespace feel::iforce {
namespace {

using detail::Args;
using detail::on_axes;

// One axis of a spring or damper as the §8.2 table ranges it. `prefix` names the axis's
// parameters in Spring/Damper ("x_"), empty for the one-axis wrappers.
ConditionBlock condition_block(const Args& args, const std::string& prefix, const char* coefficient,
                               int32_t pos_coefficient, int32_t neg_coefficient, int32_t offset,
                               int32_t pos_saturation, int32_t neg_saturation, int32_t deadband) {
    args.check(prefix + coefficient + "_pos", pos_coefficient, range::kSignedLevel);
    args.check(prefix + coefficient + "_neg", neg_coefficient, range::kSignedLevel);
    args.check(prefix + "offset", offset, range::kSignedLevel);
    args.check(prefix + "pos_saturation", pos_saturation, range::kLevel);
    args.check(prefix + "neg_saturation", neg_saturation, range::kLevel);
    args.check(prefix + "deadband", deadband, range::kLevel);
    ConditionBlock c;
    c.pos_coefficient = pos_coefficient;
    c.neg_coefficient = neg_coefficient;
    c.offset = offset;
    c.pos_saturation = pos_saturation;
    c.neg_saturation = neg_saturation;
    c.deadband = deadband;
    c.offset_mode = OffsetMode::absolute;
    return c;
}

// A symmetric block (CenterSpring, the inertias, Friction): the same coefficient and
// saturation both ways.
ConditionBlock symmetric_block(int32_t coefficient, int32_t saturation, int32_t deadband) {
    ConditionBlock c;
    c.pos_coefficient = coefficient;
    c.neg_coefficient = coefficient;
    c.offset = 0;
    c.pos_saturation = saturation;
    c.neg_saturation = saturation;
    c.deadband = deadband;
    return c;
}

EffectParams one_axis_condition(const char* wrapper, EffectType type, Axis axis, const char* coefficient,
                                int32_t pos_coefficient, int32_t neg_coefficient, int32_t offset,
                                int32_t pos_saturation, int32_t neg_saturation, int32_t deadband) {
    const Args args(wrapper);
    EffectParams p = on_axes(type, {axis});
    p.conditions[0] = condition_block(args, "", coefficient, pos_coefficient, neg_coefficient, offset,
                                      pos_saturation, neg_saturation, deadband);
    return args.finish(p);
}

EffectParams two_axis_condition(const char* wrapper, EffectType type, const char* coefficient,
                                const ConditionBlock& x, const ConditionBlock& y) {
    const Args args(wrapper);
    EffectParams p = on_axes(type, {Axis::x, Axis::y});
    p.conditions[0] = condition_block(args, "x_", coefficient, x.pos_coefficient, x.neg_coefficient,
                                      x.offset, x.pos_saturation, x.neg_saturation, x.deadband);
    p.conditions[1] = condition_block(args, "y_", coefficient, y.pos_coefficient, y.neg_coefficient,
                                      y.offset, y.pos_saturation, y.neg_saturation, y.deadband);
    return args.finish(p);
}

ConditionBlock raw_block(int32_t pos_coefficient, int32_t neg_coefficient, int32_t offset,
                         int32_t pos_saturation, int32_t neg_saturation, int32_t deadband) {
    ConditionBlock c;
    c.pos_coefficient = pos_coefficient;
    c.neg_coefficient = neg_coefficient;
    c.offset = offset;
    c.pos_saturation = pos_saturation;
    c.neg_saturation = neg_saturation;
    c.deadband = deadband;
    return c;
}

// CenterSpring and SpringatCurrentLocation: §8.5 fills both blocks alike.
EffectParams symmetric_spring(const char* wrapper, int32_t k, int32_t saturation, int32_t deadband,
                              OffsetMode mode) {
    const Args args(wrapper);
    args.check("k", k, range::kSignedLevel);
    args.check("saturation", saturation, range::kLevel);
    args.check("deadband", deadband, range::kLevel);
    EffectParams p = on_axes(EffectType::spring, {Axis::x, Axis::y});
    for (int i = 0; i < 2; ++i) {
        p.conditions[i] = symmetric_block(k, saturation, deadband);
        p.conditions[i].offset_mode = mode;
    }
    return args.finish(p);
}

EffectParams inertia_on(const char* wrapper, std::initializer_list<Axis> axes, int32_t mass,
                        int32_t saturation) {
    const Args args(wrapper);
    args.check("mass", mass, detail::kInertiaMass);
    args.check("saturation", saturation, detail::kInertiaSaturation);
    EffectParams p = on_axes(EffectType::inertia, axes);
    for (int i = 0; i < p.axis_count; ++i) p.conditions[i] = symmetric_block(mass, saturation, 0);
    return args.finish(p);
}

EffectParams friction_on(const char* wrapper, std::initializer_list<Axis> axes, const char* pos_name,
                         int32_t f_pos, const char* neg_name, int32_t f_neg) {
    const Args args(wrapper);
    args.check(pos_name, f_pos, range::kLevel);
    args.check(neg_name, f_neg, range::kLevel);
    EffectParams p = on_axes(EffectType::friction, axes);
    for (int i = 0; i < p.axis_count; ++i) {
        p.conditions[i] = raw_block(f_pos, f_neg, 0, kFullScale, kFullScale, 0);
    }
    return args.finish(p);
}

EffectParams texture_on(const char* wrapper, Axis axis, int32_t pos_roughness, int32_t neg_roughness,
                        int32_t spacing, int32_t density, bool symmetric) {
    const Args args(wrapper);
    if (symmetric) {
        args.check("roughness", pos_roughness, range::kPositiveLevel);
    } else {
        args.check("pos_roughness", pos_roughness, range::kPositiveLevel);
        args.check("neg_roughness", neg_roughness, range::kPositiveLevel);
    }
    args.check("spacing", spacing, range::kPositiveLevel);
    args.check("density", density, range::kPositiveLevel);
    EffectParams p = on_axes(EffectType::texture, {axis});
    p.texture = TextureBlock{pos_roughness, neg_roughness, spacing, density};
    return args.finish(p);
}

void check_sense(const Args& args, WallSense sense) {
    if (sense != WallSense::positive && sense != WallSense::negative) {
        args.fail("sense", "must be WallSense::positive or WallSense::negative");
    }
}

EffectParams axis_wall(const char* wrapper, Axis axis, int32_t hardness, WallSense sense, int32_t offset,
                       int32_t surface_friction, int32_t surface_texture, bool clipping) {
    const Args args(wrapper);
    args.check("hardness", hardness, range::kSignedLevel);
    check_sense(args, sense);
    args.check("offset", offset, range::kSignedLevel);
    args.check("surface_friction", surface_friction, range::kLevel);
    args.check("surface_texture", surface_texture, range::kLevel);
    EffectParams p = on_axes(EffectType::axis_wall, {axis});
    p.wall.hardness = hardness;
    p.wall.sense = sense;
    p.wall.offset = offset;
    p.wall.offset_mode = OffsetMode::absolute;
    p.wall.angle = 0;
    p.wall.surface_friction = surface_friction;
    p.wall.surface_texture = surface_texture;
    p.wall.clipping = clipping;
    return args.finish(p);
}

void check_barrier(const Args& args, int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                   int32_t offset) {
    args.check("pos_hardness", pos_hardness, range::kSignedLevel);
    args.check("neg_hardness", neg_hardness, range::kSignedLevel);
    args.check("thickness", thickness, range::kPositiveLevel);
    args.check("offset", offset, range::kSignedLevel);
}

EffectParams axis_barrier(const char* wrapper, Axis axis, int32_t pos_hardness, int32_t neg_hardness,
                          int32_t thickness, int32_t offset, int32_t surface_friction,
                          int32_t surface_texture) {
    const Args args(wrapper);
    check_barrier(args, pos_hardness, neg_hardness, thickness, offset);
    args.check("surface_friction", surface_friction, range::kLevel);
    args.check("surface_texture", surface_texture, range::kLevel);
    EffectParams p = on_axes(EffectType::axis_barrier, {axis});
    p.barrier = BarrierBlock{pos_hardness, neg_hardness, thickness, offset, 0, surface_friction,
                             surface_texture};
    return args.finish(p);
}

}  // namespace

// --- springs --------------------------------------------------------------------------------

EffectParams x_spring(int32_t k_pos, int32_t k_neg, int32_t offset, int32_t pos_saturation,
                      int32_t neg_saturation, int32_t deadband) {
    return one_axis_condition("x_spring", EffectType::spring, Axis::x, "k", k_pos, k_neg, offset,
                              pos_saturation, neg_saturation, deadband);
}

EffectParams y_spring(int32_t k_pos, int32_t k_neg, int32_t offset, int32_t pos_saturation,
                      int32_t neg_saturation, int32_t deadband) {
    return one_axis_condition("y_spring", EffectType::spring, Axis::y, "k", k_pos, k_neg, offset,
                              pos_saturation, neg_saturation, deadband);
}

EffectParams spring(int32_t x_k_pos, int32_t x_k_neg, int32_t x_offset, int32_t x_pos_saturation,
                    int32_t x_neg_saturation, int32_t x_deadband, int32_t y_k_pos, int32_t y_k_neg,
                    int32_t y_offset, int32_t y_pos_saturation, int32_t y_neg_saturation,
                    int32_t y_deadband) {
    return two_axis_condition(
        "spring", EffectType::spring, "k",
        raw_block(x_k_pos, x_k_neg, x_offset, x_pos_saturation, x_neg_saturation, x_deadband),
        raw_block(y_k_pos, y_k_neg, y_offset, y_pos_saturation, y_neg_saturation, y_deadband));
}

EffectParams angle_spring(int32_t k_pos, int32_t k_neg, int32_t offset, int32_t pos_saturation,
                          int32_t neg_saturation, int32_t deadband, int32_t angle) {
    const Args args("angle_spring");
    EffectParams p = on_axes(EffectType::angle_spring, {Axis::x, Axis::y});
    p.conditions[0] = condition_block(args, "", "k", k_pos, k_neg, offset, pos_saturation,
                                      neg_saturation, deadband);
    args.check("angle", angle, range::kAngle);
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = angle;
    return args.finish(p);
}

EffectParams center_spring(int32_t k, int32_t saturation, int32_t deadband) {
    return symmetric_spring("center_spring", k, saturation, deadband, OffsetMode::absolute);
}

EffectParams spring_at_current_location(int32_t k, int32_t saturation, int32_t deadband) {
    return symmetric_spring("spring_at_current_location", k, saturation, deadband, OffsetMode::relative);
}

// --- dampers --------------------------------------------------------------------------------

EffectParams x_damper(int32_t b_pos, int32_t b_neg, int32_t offset, int32_t pos_saturation,
                      int32_t neg_saturation, int32_t deadband) {
    return one_axis_condition("x_damper", EffectType::damper, Axis::x, "b", b_pos, b_neg, offset,
                              pos_saturation, neg_saturation, deadband);
}

EffectParams y_damper(int32_t b_pos, int32_t b_neg, int32_t offset, int32_t pos_saturation,
                      int32_t neg_saturation, int32_t deadband) {
    return one_axis_condition("y_damper", EffectType::damper, Axis::y, "b", b_pos, b_neg, offset,
                              pos_saturation, neg_saturation, deadband);
}

EffectParams damper(int32_t x_b_pos, int32_t x_b_neg, int32_t x_offset, int32_t x_pos_saturation,
                    int32_t x_neg_saturation, int32_t x_deadband, int32_t y_b_pos, int32_t y_b_neg,
                    int32_t y_offset, int32_t y_pos_saturation, int32_t y_neg_saturation,
                    int32_t y_deadband) {
    return two_axis_condition(
        "damper", EffectType::damper, "b",
        raw_block(x_b_pos, x_b_neg, x_offset, x_pos_saturation, x_neg_saturation, x_deadband),
        raw_block(y_b_pos, y_b_neg, y_offset, y_pos_saturation, y_neg_saturation, y_deadband));
}

// --- inertia and friction -------------------------------------------------------------------

EffectParams x_inertia(int32_t mass, int32_t saturation) {
    return inertia_on("x_inertia", {Axis::x}, mass, saturation);
}

EffectParams y_inertia(int32_t mass, int32_t saturation) {
    return inertia_on("y_inertia", {Axis::y}, mass, saturation);
}

EffectParams inertia(int32_t mass, int32_t saturation) {
    return inertia_on("inertia", {Axis::x, Axis::y}, mass, saturation);
}

EffectParams friction(int32_t f) {
    return friction_on("friction", {Axis::x, Axis::y}, "f", f, "f", f);
}

EffectParams x_friction(int32_t f_pos, int32_t f_neg) {
    return friction_on("x_friction", {Axis::x}, "f_pos", f_pos, "f_neg", f_neg);
}

EffectParams y_friction(int32_t f_pos, int32_t f_neg) {
    return friction_on("y_friction", {Axis::y}, "f_pos", f_pos, "f_neg", f_neg);
}

// --- textures -------------------------------------------------------------------------------

EffectParams texture(int32_t roughness, int32_t spacing, int32_t density, int32_t angle) {
    const Args args("texture");
    args.check("roughness", roughness, range::kPositiveLevel);
    args.check("spacing", spacing, range::kPositiveLevel);
    args.check("density", density, range::kPositiveLevel);
    args.check("angle", angle, range::kAngle);
    EffectParams p = on_axes(EffectType::texture, {Axis::x, Axis::y});
    p.texture = TextureBlock{roughness, roughness, spacing, density};
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = angle;
    return args.finish(p);
}

EffectParams x_texture(int32_t roughness, int32_t spacing, int32_t density) {
    return texture_on("x_texture", Axis::x, roughness, roughness, spacing, density, true);
}

EffectParams x_texture(int32_t pos_roughness, int32_t neg_roughness, int32_t spacing, int32_t density) {
    return texture_on("x_texture", Axis::x, pos_roughness, neg_roughness, spacing, density, false);
}

EffectParams y_texture(int32_t pos_roughness, int32_t neg_roughness, int32_t spacing, int32_t density) {
    return texture_on("y_texture", Axis::y, pos_roughness, neg_roughness, spacing, density, false);
}

// --- walls and barriers ---------------------------------------------------------------------

EffectParams wall(int32_t hardness, WallSense sense, int32_t offset, int32_t angle) {
    const Args args("wall");
    args.check("hardness", hardness, range::kSignedLevel);
    check_sense(args, sense);
    args.check("offset", offset, range::kSignedLevel);
    args.check("angle", angle, range::kAngle);
    EffectParams p = on_axes(EffectType::angle_wall, {Axis::x, Axis::y});
    p.wall.hardness = hardness;
    p.wall.sense = sense;
    p.wall.offset = offset;
    p.wall.angle = angle;
    return args.finish(p);
}

// A horizontal wall is a horizontal line y = offset: it stops motion along y.
EffectParams horizontal_wall(int32_t hardness, WallSense sense, int32_t offset, int32_t surface_friction,
                             int32_t surface_texture, bool clipping) {
    return axis_wall("horizontal_wall", Axis::y, hardness, sense, offset, surface_friction,
                     surface_texture, clipping);
}

EffectParams vertical_wall(int32_t hardness, WallSense sense, int32_t offset, int32_t surface_friction,
                           int32_t surface_texture, bool clipping) {
    return axis_wall("vertical_wall", Axis::x, hardness, sense, offset, surface_friction,
                     surface_texture, clipping);
}

EffectParams barrier(int32_t pos_hardness, int32_t neg_hardness, int32_t thickness, int32_t offset,
                     int32_t angle) {
    const Args args("barrier");
    check_barrier(args, pos_hardness, neg_hardness, thickness, offset);
    args.check("angle", angle, range::kAngle);
    EffectParams p = on_axes(EffectType::angle_barrier, {Axis::x, Axis::y});
    p.barrier = BarrierBlock{pos_hardness, neg_hardness, thickness, offset, angle, 0, 0};
    return args.finish(p);
}

EffectParams horizontal_barrier(int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                                int32_t offset, int32_t surface_friction, int32_t surface_texture) {
    return axis_barrier("horizontal_barrier", Axis::y, pos_hardness, neg_hardness, thickness, offset,
                        surface_friction, surface_texture);
}

EffectParams vertical_barrier(int32_t pos_hardness, int32_t neg_hardness, int32_t thickness,
                              int32_t offset, int32_t surface_friction, int32_t surface_texture) {
    return axis_barrier("vertical_barrier", Axis::x, pos_hardness, neg_hardness, thickness, offset,
                        surface_friction, surface_texture);
}

}  // namespace feel::iforce
