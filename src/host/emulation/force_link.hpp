// feel::host::emulation — how a host-rendered force reaches the device.
//
// A device that streams (a feel device: Download Force Sample, §2.4) gets one sample per
// update: one unanswered report, per axis, which the device's reconstruction filter
// plays without overshoot and holds. That is the only link implemented today. A device
// with only the standard PID reports has no streaming; there the force goes as one
// constant effect the host owns, its Set Constant Force (and, on more than one axis, Set
// Effect's direction) rewritten each update after one Effect Operation start: that link
// needs the descriptor-driven PID mapping of a device that is not a feel device (issue 13,
// section 1), and choose_force_link() refuses such a device until it lands.
#pragma once

#include <cstdint>
#include <string>

#include "feel/host/device.hpp"
#include "feel/protocol/reports.hpp"

namespace feel::host::emulation {

enum class ForceLinkKind : uint8_t {
    stream_sample,  // Download Force Sample, one per update
};

// The I/O thread's memory of what it sent.
struct ForceLinkState {
    int64_t samples_sent = 0;
};

// The link for `caps`, or why there is none.
[[nodiscard]] Result<ForceLinkKind> choose_force_link(const DeviceCaps& caps, const std::string& what);

// The report that carries `force` (normalized ±10000 per device axis, already clamped).
[[nodiscard]] protocol::DownloadForceSampleReport force_sample(int32_t axis_count, const int32_t force[kMaxAxes]) noexcept;

}  // namespace feel::host::emulation
