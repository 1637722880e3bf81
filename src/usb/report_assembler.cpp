// ReportAssembler: interrupt OUT packets to whole output reports (report_assembler.hpp).
#include "report_assembler.hpp"

#include <utility>

#include "feel/protocol/codec.hpp"

namespace feel::usb::detail {

ReportAssembler::ReportAssembler(std::size_t packet_bytes) : packet_bytes_(packet_bytes) {}

void ReportAssembler::set_packet_bytes(std::size_t packet_bytes) noexcept { packet_bytes_ = packet_bytes; }

bool ReportAssembler::add(std::span<const uint8_t> packet) {
    if (complete_) reset();
    bytes_.insert(bytes_.end(), packet.begin(), packet.end());
    if (bytes_.empty()) return false;  // a zero-length packet before any byte: nothing
    const std::size_t wanted = protocol::report_size(bytes_[0]);
    const bool short_packet = packet.size() < packet_bytes_;
    // Done: the report's size reached, or the transfer ended (short packet), or an id the
    // protocol does not know (its size is unknown, so this packet is all of it).
    complete_ = wanted == 0 || bytes_.size() >= wanted || short_packet;
    return complete_;
}

std::vector<uint8_t> ReportAssembler::take() {
    complete_ = false;
    return std::exchange(bytes_, {});
}

void ReportAssembler::reset() noexcept {
    bytes_.clear();
    complete_ = false;
}

}  // namespace feel::usb::detail
