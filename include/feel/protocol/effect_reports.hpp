// feel::protocol — an effect's parameters as the PID reports that download it.
//
// A host downloads an effect as hid-pidff does: Create New Effect, then the blocks of its
// type, then Set Effect, which commits it (docs/protocol.md). These functions only build
// reports; they assume parameters that validate_effect() accepts (and a force profile's
// samples that fit), so every value fits its wire field. Sequence numbers are left 0: the
// sender numbers each report as it sends it (set_sequence).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "feel/effect.hpp"
#include "feel/protocol/reports.hpp"

namespace feel::protocol {

// Microseconds to a wire duration: kInfiniteUs is PID's "infinite".
[[nodiscard]] uint32_t wire_duration(int64_t us) noexcept;
// Iterations to Effect Operation's loop count and Set Effect's iterations:
// kInfiniteIterations -> kLoopInfinite, n -> n.
[[nodiscard]] uint16_t wire_iterations(int32_t iterations) noexcept;

// Sets the report's sequence number (every host-to-device report has one; others ignore it).
void set_sequence(AnyReport& report, uint32_t sequence) noexcept;

[[nodiscard]] CreateNewEffectReport create_new_effect_report(const EffectParams& params,
                                                                       std::span<const int16_t> samples);

// The Effect Structure (§6.3) of the effect.
[[nodiscard]] SetEffectReport set_effect_report(const EffectParams& params, uint16_t block);

// The parameter blocks to send before Set Effect, in order: the envelope when `envelope`
// and the effect has one, and the type's blocks when `type_specific` (one Set Condition per
// axis, Set Periodic, Set Constant Force, Set Ramp Force, Custom Force Data chunks then Set
// Custom Force, texture, wall, barrier, sweep, dynamic and one control law per axis).
[[nodiscard]] std::vector<AnyReport> parameter_block_reports(const EffectParams& params,
                                                                       std::span<const int16_t> samples,
                                                                       uint16_t block, bool envelope,
                                                                       bool type_specific);

}  // namespace feel::protocol
