// feel::protocol — feel's device as a plain USB HID PID device, with no vendor report.
//
// feel's descriptor (codec.hpp) is PID 1.0 plus feel's vendor page: vendor reports (Command
// Status, Device Info, Device Status, walls, textures, Dynamics...) and vendor fields inside
// PID's reports (the command sequence, sub-millisecond times, iterations, the axis list).
// A standard PID host ignores what it does not know, but the device still declares and
// sends it. The standard form is what a wheel or stick from elsewhere has: only PID's
// reports, each with only PID's fields, and the joystick's Input report:
//
//   Output   Set Effect, Set Envelope, Set Condition, Set Periodic, Set Constant Force,
//            Set Ramp Force, Effect Operation, PID Block Free, PID Device Control,
//            Device Gain
//   Feature  Create New Effect, PID Block Load, PID Pool
//   Input    Joystick Input (the device's axes, buttons, hats), PID State
//
// Effect Type lists PID's eleven types (constant, ramp, the five waves, spring, damper,
// inertia, friction), which the device plays, then ET Custom Force Data, which it refuses
// (hid-pidff reads one entry past each type it uses, so friction must not end the list).
// Custom forces and force streaming (Set Custom Force, Custom Force Data, Download Force
// Sample) are left out: feel's forms of them need vendor fields.
//
// Each standard report keeps feel's report ID and the PID fields of feel's report, in the
// same order, with the same sizes and logical ranges. So the device runs on unchanged: a
// standard report from the host becomes feel's report with every vendor field 0 (what a
// standard host such as hid-pidff leaves in them on feel's own descriptor, which the
// device session already reads as "not given"), and of what the device sends only the
// standard reports go out, without their vendor fields. Portable, no I/O.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "feel/effect_type.hpp"
#include "feel/protocol/codec.hpp"

namespace feel::protocol {

// The standard device's report descriptor for these joystick inputs (check_layout must
// pass; throws std::invalid_argument otherwise).
[[nodiscard]] std::vector<uint8_t> standard_pid_descriptor(const JoystickLayout& layout);

// The effect types the standard device plays (the first eleven of Effect Type's list).
[[nodiscard]] std::span<const EffectType> standard_pid_effect_types() noexcept;
// effect_type_bit() of each.
[[nodiscard]] uint64_t standard_pid_effect_type_bits() noexcept;

// Whether the standard device has a report with this id (Joystick Input included).
[[nodiscard]] bool is_standard_pid_report(uint8_t id) noexcept;

// Host -> device: a standard report (id byte first) as feel's report, vendor fields 0.
// Errors (nothing written): an id the standard device lacks ("report.id"), a wrong length
// ("report.length"), an Effect Type index outside PID's list ("set_effect.type",
// "create_new_effect.type", with the range). Joystick Input is copied as it is.
[[nodiscard]] Error standard_pid_to_feel(std::span<const uint8_t> bytes, std::vector<uint8_t>& feel);

// Device -> host: feel's report (id byte first) in the standard form. False when it has
// none (a vendor report, or a standard report whose Effect Type PID cannot name): the
// standard device does not send it. Joystick Input is copied as it is.
[[nodiscard]] bool feel_to_standard_pid(std::span<const uint8_t> bytes, std::vector<uint8_t>& standard);

}  // namespace feel::protocol
