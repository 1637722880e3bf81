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
// leaves: feel's types beyond PID's eleven and its custom force, a hat trigger or a button
// past the Trigger Button's range (a host runs the triggers a device cannot:
// device_runs_trigger), relative offsets, spherical and vector directions on more than two
// axes, a negative level on an unsigned field, a time, a level or a sample past a field's
// range.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
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

// A force profile's samples (EffectParams::custom says how many, on how many channels),
// and how the device wants them:
//  - a standard PID device: a sample is one value per axis of its Download Force Sample
//    report (the FF2: X and Y), so the host writes frame f's channel i into the slot of the
//    effect's axis i, 0 in the others; Sample Count counts frames; Custom Force Data Offset
//    counts the data's elements from the first; Create New Effect's Byte Count is the data's
//    size in bytes;
//  - feel's own device (feel_format): feel's samples as they are, interleaved by channel, with
//    feel's Channels and per-report sample count (its descriptor's vendor fields), Sample
//    Count the number of values.
struct ProfileSamples {
    std::span<const int16_t> values;
    bool feel_format = false;
};

// Whether the device runs `trigger` itself: a button trigger, and its Set Effect has a
// Trigger Button (PID names buttons only: a hat trigger is always the host's to run).
[[nodiscard]] bool device_runs_trigger(const PidLayout& layout, const Trigger& trigger) noexcept;

// Create New Effect for `type`, with PID's Byte Count (the custom force data's bytes, 0 for
// every other type). Empty with `error` when the device does not play it.
[[nodiscard]] std::optional<std::vector<uint8_t>> create_new_effect(const PidLayout& layout, EffectType type,
                                                                    std::string& error, int64_t byte_count = 0);
// The bytes a force profile's samples take in the device's Custom Force Data (Create New
// Effect's Byte Count). std::nullopt with `error` when the device cannot hold them.
[[nodiscard]] std::optional<int64_t> custom_force_bytes(const PidLayout& layout, const EffectParams& params,
                                                        const ProfileSamples& samples, std::string& error);

// The reports that set effect `block` to `params`, in sending order (Set Effect last); a
// force profile's Custom Force Data reports come first, then Set Custom Force.
// Empty with `error` naming the field and the reason when the device cannot hold them.
[[nodiscard]] std::vector<OutgoingReport> effect_reports(const PidLayout& layout, uint16_t block,
                                                         const EffectParams& params, std::string& error,
                                                         const ProfileSamples& samples = {});

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
