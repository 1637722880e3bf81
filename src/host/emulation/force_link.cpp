// The host's force to the device (force_link.hpp).
#include "force_link.hpp"


namespace feel::host::emulation {

Result<ForceLinkKind> choose_force_link(const DeviceCaps& caps, const std::string& what) {
    // Every feel device streams (the vendor protocol's Download Force Sample, revision 1
    // on); its Device Info is what told the host its capabilities.
    if (caps.axis_count < 1) {
        return Status::failure(ErrorKind::not_supported,
                               what + ": the device \"" + caps.device +
                                   "\" reports no axes, so the host has no positions to render on");
    }
    return ForceLinkKind::stream_sample;
}

protocol::DownloadForceSampleReport force_sample(int32_t axis_count, const int32_t force[kMaxAxes]) noexcept {
    protocol::DownloadForceSampleReport r;
    r.axis_count = static_cast<uint8_t>(axis_count);
    for (int32_t i = 0; i < axis_count && i < kMaxAxes; ++i) r.force[i] = static_cast<int16_t>(force[i]);
    return r;
}

}  // namespace feel::host::emulation
