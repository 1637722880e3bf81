// What a host report means for an effect block: the checks a session can make alone, the
// shadow parameters a type block fills, the Set Effect fields, and the update mask of a
// commit. Pure functions of their arguments; the session (device_session.cpp) sequences
// them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "block_table.hpp"
#include "feel/effect.hpp"
#include "feel/protocol/reports.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/status.hpp"

namespace feel::peripheral::detail {

// Why the session refuses a report before the engine sees it. Like feel::Error, but its
// words may be composed (the block, the effect type): they travel in a CommandStatus.
struct Refusal {
    ErrorCode code = ErrorCode::invalid_parameter;
    std::string field;      // e.g. "set_condition.block"
    std::string rule;       // a sentence when there is no range
    bool has_range = false;
    int64_t value = 0;
    Range allowed{0, 0};

    static Refusal out_of_range(std::string field, int64_t value, Range allowed);
    static Refusal of(ErrorCode code, std::string field, std::string rule);
};

// The report's snake_case name, the prefix of the fields the session names ("set_effect").
[[nodiscard]] std::string_view report_key(protocol::ReportId id) noexcept;

// The block a report is about, 0 when it names none.
[[nodiscard]] uint16_t report_block(const protocol::AnyReport& report) noexcept;
// The report's sequence number, 0 for the reports without one (feature gets, input).
[[nodiscard]] uint32_t report_sequence(const protocol::AnyReport& report) noexcept;

// Whether a type block (Set Condition, Set Periodic, ...) fits an effect of this type.
// std::nullopt when it fits; otherwise invalid_parameter naming the report.
[[nodiscard]] std::optional<Refusal> check_type_block_fits(protocol::ReportId id, EffectType type,
                                                           uint16_t block);

// What a type block's values mean for an effect of this type, beyond the report's ranges.
// A Set Periodic with a negative magnitude (PID's Magnitude is signed: the wave upside down,
// evdev's negative periodic magnitude) is a wave half a period on for sine, square and
// triangle (apply_type_block maps it), and the other saw for saw_up and saw_down, which
// this refuses: an effect's type never changes (docs/protocol.md, "Standard hosts").
[[nodiscard]] std::optional<Refusal> check_type_block_values(const protocol::AnyReport& report, EffectType type);

// Writes a type block into the block's shadow and notes its arrival. The report must fit
// (check_type_block_fits). Custom Force Data carries samples, not parameters: not here.
void apply_type_block(const protocol::AnyReport& report, Block& block);

// Writes Set Effect's Effect Structure into `params` (the type blocks stay). A report
// without axes (axis_count 0: a standard PID host, which never writes feel's vendor
// fields) plays on the axes its Axes Enable names that the device has, or without Axes
// Enable on the device's first two axes, or its one: PID's direction is a 2D angle and
// hid-pidff sends two Set Condition blocks (docs/protocol.md, "Standard hosts").
void apply_set_effect(const protocol::SetEffectReport& report, EffectParams& params,
                      const runtime::Capabilities& device);

// PID's Axes Enable against the effect's axes. From feel's own host (axis_count >= 1) it is
// 0 or exactly the bits of axes[0..axis_count). From a standard host (axis_count 0) it
// names the effect's axes: those the device has play, in the device's order, and those it
// lacks are ignored (hid-pidff enables the first axes it finds in the list, whatever the
// device has), but at least one must be the device's. std::nullopt when it fits.
[[nodiscard]] std::optional<Refusal> check_axes_enable(const protocol::SetEffectReport& report,
                                                       const runtime::Capabilities& device);

// DirectInput's rule for conditions (spring, damper, inertia, friction): given one Set
// Condition per axis, the effect ignores its direction, which applies only to one block
// given for several axes. hid-pidff always sends Direction Enable with a direction and
// one block per axis; this drops that direction from `params` when every axis of the
// effect has its block (`conditions_arrived`: bit i for axis i). The other form, one Set
// Condition (axis 0) with a direction on 2 or more axes, keeps its direction: it is the
// condition with a direction (§3.1), its one block applied along the direction, as feel's
// own host sends it (check_blocks_complete accepts it).
void ignore_direction_of_per_axis_conditions(EffectType type, uint8_t conditions_arrived,
                                             EffectParams& params) noexcept;

// Set Condition blocks for axes the effect does not have (bit i of `conditions_arrived` for
// axis i >= the effect's axis count). hid-pidff sends two, for axes 0 and 1, whatever the
// device has: a one-axis wheel gets an axis-1 block it cannot use. A standard host says so
// by naming no axes in Set Effect (axis_count 0), and for it such blocks are accepted and
// ignored (docs/protocol.md, "Standard hosts"). feel's own host names the effect's axes and
// sends one block per axis; from it such a block is a mistake, refused at the commit naming
// `set_condition.axis_index` and the effect's axes as the allowed range.
[[nodiscard]] std::optional<Refusal> check_conditions_within_axes(const protocol::SetEffectReport& report,
                                                                  EffectType type, uint8_t conditions_arrived,
                                                                  const EffectParams& next);

// For a block's first commit: std::nullopt when every type block the effect needs has
// arrived, else a Refusal naming the first one missing.
[[nodiscard]] std::optional<Refusal> check_blocks_complete(const Block& block, const EffectParams& next,
                                                           uint16_t index);

// The effect_field::k* bits whose fields differ between two parameter sets.
[[nodiscard]] uint32_t changed_fields(const EffectParams& from, const EffectParams& to) noexcept;

// Effect Operation's loop count as a runtime start's iterations: 0 the effect's own count
// (runtime::kEffectIterations), 1..255 that many, kLoopInfinite kInfiniteIterations.
[[nodiscard]] int32_t iterations_of_loop_count(uint16_t loop_count) noexcept;

// PID Device Control as the runtime's DISFFC_* command.
[[nodiscard]] std::optional<runtime::DeviceControl> runtime_control(protocol::DeviceControlOp op) noexcept;

}  // namespace feel::peripheral::detail
