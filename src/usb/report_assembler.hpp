// Output reports from interrupt OUT packets.
//
// A report longer than the endpoint's packet size arrives as several packets of one
// transfer: full packets, then a short one (or none, when the report is a whole number of
// packets: the host sends no zero-length packet for a transfer it knows the length of).
// The device reads one packet at a time and puts the report back together: the first byte
// is the report id, protocol::report_size(id) says how long it is, and the report is done
// when that many bytes arrived or a short packet ended the transfer. An unknown id, or a
// transfer that ends early, is passed on as it came, for the device session to refuse with
// its error (report.id, report.length): the assembler judges nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace feel::usb::detail {

class ReportAssembler {
public:
    // `packet_bytes`: the endpoint's wMaxPacketSize (1..1024).
    explicit ReportAssembler(std::size_t packet_bytes);
    // Takes one packet; returns true when a report is complete (take it with report()).
    bool add(std::span<const uint8_t> packet);
    // The completed report; the assembler then starts afresh.
    [[nodiscard]] std::vector<uint8_t> take();
    // Forgets a partial report (the endpoint was disabled).
    void reset() noexcept;
    void set_packet_bytes(std::size_t packet_bytes) noexcept;

private:
    std::size_t packet_bytes_;
    std::vector<uint8_t> bytes_;
    bool complete_ = false;
};

}  // namespace feel::usb::detail
