// feel::protocol::pid — an effect and the device commands as any PID device's reports.
//
// What a standard PID host sends (PID 1.0 §5, the order Windows' PID driver uses): Create
// New Effect (a feature report naming the type; the device answers with PID Block Load),
// then the effect's type-specific block(s) and envelope, then Set Effect, which names the
// block and its type and carries its timing, gain, axes and direction; Effect Operation
// starts and stops it, PID Block Free frees it. Every report is laid out by the device's
// own descriptor (pid_layout.hpp).
//
// What a standard PID device cannot hold is refused here with the reason, before any byte
// leaves: feel's types beyond PID's eleven, triggers (PID's Trigger Button is mapped by no
// host here; host emulation plays reflexes), relative offsets, spherical and vector
// directions on more than two axes, a negative level on an unsigned field, a time or a
// level past a field's range.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "feel/effect.hpp"
#include "feel/protocol/pid_layout.hpp"
#include "feel/runtime/runtime_messages.hpp"

namespace feel::protocol::pid {

struct OutgoingReport {
    PidReport report = PidReport::set_effect;
    std::vector<uint8_t> bytes;  // report ID first
};

// Create New Effect for `type` (and PID's Byte Count 0). Empty with `error` when the
// device does not play it.
[[nodiscard]] std::optional<std::vector<uint8_t>> create_new_effect(const PidLayout& layout, EffectType type,
                                                                    std::string& error);

// The reports that set effect `block` to `params`, in sending order (Set Effect last).
// Empty with `error` naming the field and the reason when the device cannot hold them.
[[nodiscard]] std::vector<OutgoingReport> effect_reports(const PidLayout& layout, uint16_t block,
                                                         const EffectParams& params, std::string& error);

enum class Operation : uint8_t { start, start_solo, stop };
// Effect Operation. loop_count: iterations 1..n, or kInfiniteIterations (the field's null
// when it has one, else its maximum, which PID's 8-bit Loop Count reads as "until stopped").
[[nodiscard]] std::optional<std::vector<uint8_t>> effect_operation(const PidLayout& layout, uint16_t block,
                                                                   Operation operation, int32_t loop_count,
                                                                   std::string& error);
// Set Constant Force alone: a constant effect's level (−10000..10000), the report a host
// that streams a force through a standard PID device rewrites each update.
[[nodiscard]] std::optional<std::vector<uint8_t>> set_constant_force(const PidLayout& layout, uint16_t block,
                                                                     int32_t magnitude, std::string& error);
[[nodiscard]] std::optional<std::vector<uint8_t>> block_free(const PidLayout& layout, uint16_t block,
                                                             std::string& error);
[[nodiscard]] std::optional<std::vector<uint8_t>> device_control(const PidLayout& layout,
                                                                 runtime::DeviceControl control, std::string& error);
// Device Gain, 0..10000.
[[nodiscard]] std::optional<std::vector<uint8_t>> device_gain(const PidLayout& layout, int32_t gain,
                                                              std::string& error);

// What PID Block Load says.
struct BlockLoad {
    uint16_t block = 0;
    enum class Status : uint8_t { success, full, error, unknown } status = Status::unknown;
    std::optional<int64_t> ram_pool_available;  // bytes, when the device says
};
[[nodiscard]] std::optional<BlockLoad> read_block_load(const PidLayout& layout, std::span<const uint8_t> bytes);

// What PID Pool says (each absent field: std::nullopt).
struct Pool {
    std::optional<int64_t> ram_pool_size;            // bytes
    std::optional<int64_t> simultaneous_effects_max;
    std::optional<bool> device_managed_pool;
    std::optional<bool> shared_parameter_blocks;
};
[[nodiscard]] Pool read_pool(const PidLayout& layout, std::span<const uint8_t> bytes);

}  // namespace feel::protocol::pid
