// feel::host — the PID transactions that put an effect on a device and change it.
//
// download_effect (hid-pidff's order, docs/protocol.md):
//   Create New Effect (feature set)      -> CommandStatus
//   Block Load (feature get)             -> the block, or Full / Error
//   the type's parameter blocks          -> one CommandStatus each
//   Set Effect                           -> CommandStatus: the engine's verdict (field, range)
//   Reflex assign (device with reflexes and an effect with a trigger)
// Any refusal after Block Load frees the block again, so a failed create leaves the
// device as it was. On a device without local reflexes an effect with a trigger goes down
// without it and the host's I/O thread plays the trigger (§1.2.c, device_core.hpp).
//
// Every function here expects the caller to hold core.call_mu.
#pragma once

#include <span>
#include <string>

#include "device_core.hpp"

namespace feel::host {

// Whether the host emulates this effect's trigger on this device.
[[nodiscard]] bool host_emulates_trigger(const DeviceCaps& caps, const EffectParams& params) noexcept;
// The parameters as the device gets them: without the trigger when the host emulates it.
[[nodiscard]] EffectParams device_params(const DeviceCaps& caps, const EffectParams& params) noexcept;

// Downloads the record's effect; on success the record holds its block.
Status download_effect(DeviceCore& core, EffectRecord& record, const std::string& what);

// Sends the blocks `field_mask` names and Set Effect for `merged` (the record's parameters
// with the changes applied), re-arms the trigger, restarts if asked. On success the
// record holds `merged` and `samples`.
Status update_effect(DeviceCore& core, EffectRecord& record, const EffectParams& merged,
                     std::span<const int16_t> samples, uint32_t field_mask, bool restart, const std::string& what);

// The record's parameters with the fields of `mask` taken from `changes` (DIEP_* semantics).
[[nodiscard]] EffectParams merge_parameters(const EffectParams& current, const EffectParams& changes,
                                            uint32_t mask) noexcept;

}  // namespace feel::host
