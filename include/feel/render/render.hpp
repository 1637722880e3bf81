// feel::render — closed-loop rendering of a sensation on the simulated device.
//
// render() runs the engine and the simulated device together at a fixed rate, the way
// the device's local loop would: sense, tick the engine, drive the motors, step physics.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/sim/input_schedule.hpp"

namespace feel::render {

// The limits render() enforces on its options. The rate is a whole number of Hz so that
// tick n happens at exactly round(n·1e6/rate) µs; a rate that divides 1e6 (100, 125, 200,
// 250, 500, 1000, 2000, 5000, 10000, ...) gives evenly spaced ticks, any other rate gives
// ticks that alternate by at most 1 µs.
inline constexpr double kMinRateHz = 100;
inline constexpr double kMaxRateHz = 10000;
inline constexpr double kMaxDurationS = 600;
inline constexpr int64_t kMaxTicks = 2'000'000;  // bounds a trace's memory (208 B a row: ~420 MB)

// A button or hat switch held down from press_us to release_us (`feel render --press`).
struct Press {
    Trigger control{};       // kind button (1..32) or hat (1..4)
    int64_t press_us = 0;    // µs after the start, >= 0
    int64_t release_us = 0;  // µs after the start, > press_us
};

// Parses a --press list: comma-separated tokens CONTROL@PRESS:RELEASE, CONTROL a button
// number (1..32) or hatN:DIR (N 1..4, DIR up, down, left, right, up-left, up-right,
// down-left, down-right: a reflex triggers on any direction off center), PRESS and
// RELEASE seconds with 0 <= PRESS < RELEASE <= kMaxDurationS. Throws
// std::invalid_argument naming the bad token and the allowed forms.
[[nodiscard]] std::vector<Press> parse_presses(const std::string& spec);

// The presses as a simulated device's input script (each press and its release). Throws
// std::invalid_argument naming --press, the device and the allowed range for a button or
// hat the profile lacks.
[[nodiscard]] sim::InputSchedule input_schedule(const std::vector<Press>& presses, const sim::DeviceProfile& profile);

struct RenderOptions {
    const sim::DeviceProfile* profile = nullptr;  // required
    sim::Grip grip = sim::Grip::firm;
    std::string motion = "hold:0";                 // a TargetMotion spec
    double duration_s = 0;                         // 0: the sensation's length, or 2 s if endless
    double rate_hz = 1000;                         // whole Hz, kMinRateHz..kMaxRateHz
    // Buttons and hats pressed during the render. Effects with a trigger (§6.3) are not
    // started at t = 0: they are reflexes (§1.2.c) that start on each press of their
    // trigger and every trigger_repeat_interval_us while it is held, as on the device.
    std::vector<Press> presses;
};

struct TraceRow {
    int64_t t_us = 0;
    float position[kMaxAxes] = {};  // true handle position, normalized
    float velocity[kMaxAxes] = {};  // true handle velocity, normalized units/s
    float force[kMaxAxes] = {};     // force the engine commands, normalized, physical sign
    float reported[kMaxAxes] = {};  // position the device reports (clipped at clipping walls)
    float target[kMaxAxes] = {};    // where the hand wants the handle (the --motion), normalized
    // The first playing dynamic's simulated mass (TickOutput::mass_*): relative to the
    // handle, and absolute (handle + relative) for plots. Zero while no dynamic plays.
    bool has_mass = false;
    float mass_relative[kMaxAxes] = {};  // position units, mass minus handle
    float mass_velocity[kMaxAxes] = {};  // position units/s, mass minus handle
    float mass_absolute[kMaxAxes] = {};  // position units
    bool saturated = false;         // the engine clamped the summed force on some axis
};

// Where a wall or barrier of the sensation lies (docs/conditions.md, "Geometry"), for plots:
// its surface is the set of positions p with p·u = at, u the direction across it (the
// effect's axis, or (sin a, cos a) on x, y for compass angle a).
struct SurfaceMark {
    std::string effect;          // "NAME" or "NAME effect I" in a compound
    bool barrier = false;        // false: a wall
    int32_t axis = -1;           // an axis element's device axis (0 = x); -1: an angle element
    int32_t angle = 0;           // an angle element's compass angle, 1/100 degree, on x, y
    double at = 0;               // the wall's surface, or the barrier's center: p·u, position units
    double thickness = 0;        // a barrier's, position units: its faces are at ± thickness/2
    bool solid_above = true;     // a wall: the solid is p·u > at (positive sense), else below
    bool clipping = false;       // a wall: the reported position stops at its surface
    bool relative = false;       // offset_mode relative: placed from the handle where it began playing
};

struct Trace {
    int32_t axis_count = 0;  // the device's axes, x, y, z, rx, ry, rz in that order
    double rate_hz = 0;
    std::vector<TraceRow> rows;
    bool has_hand = false;                     // a hand holds the handle: TraceRow::target means something
    // Every wall and barrier the sensation has; a relative wall only once it began playing.
    std::vector<SurfaceMark> surfaces;
    bool has_dynamics = false;                 // the sensation has a dynamic: mass columns
    std::vector<DynamicReport> final_reports;  // dynamics that ended by themselves (§5.2)
    std::vector<int64_t> reflex_starts_us;     // when a reflex started its effect, µs (every effect)
    int64_t interim_reports = 0;               // interim reports the engine sent
};

// Throws std::invalid_argument for bad options and std::runtime_error naming the effect
// for a sensation the engine refuses (e.g. a type it cannot render yet).
[[nodiscard]] Trace render(const format::Sensation& sensation, const RenderOptions& options);

// The time from start until every effect of the sensation has finished, µs: the largest
// start_delay + duration·iterations over its effects. nullopt when some effect never ends
// (infinite duration or iterations).
[[nodiscard]] std::optional<int64_t> sensation_length_us(const format::Sensation& sensation) noexcept;

// The render length used when RenderOptions::duration_s is 0: the sensation's length plus
// a tail of 10% (at least 100 ms) so that the end of the sensation shows, or 2 s for a
// sensation that never ends. May exceed kMaxDurationS for very long sensations, in which
// case render() asks for an explicit duration.
[[nodiscard]] double default_duration_s(const format::Sensation& sensation) noexcept;

// "t_us,x,y,vx,vy,fx,fy" then one row per tick. Numbers are written in their shortest
// form that reads back to the same value.
void write_csv(const Trace& trace, std::ostream& out);

// Draws force and position against time; the format follows the extension (.svg, .png).
// The position panel also shows the hand's target, the reported position and the walls
// and barriers of axis elements (and of angle elements at an axis angle).
// Throws std::invalid_argument for another extension or an empty trace, and
// std::runtime_error when the file cannot be written.
void write_plot(const Trace& trace, const std::string& title, const std::string& path);

// Draws the x-y plane (`feel render --plot-xy`): the handle's path, the hand's target and
// the reported position, the walls and barriers as lines across the plane, and the force
// as sparse arrows, at one scale on both axes. Throws std::invalid_argument for another
// extension, an empty trace or a trace of fewer than 2 axes (naming --plot-xy), and
// std::runtime_error when the file cannot be written.
void write_xy_plot(const Trace& trace, const std::string& title, const std::string& path);

}  // namespace feel::render
