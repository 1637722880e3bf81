// The bridge's record of what the feel device receives: a Connection that passes every
// frame through and writes one line per host report, feature reply and refusal.
//
// `feel bridge --log FILE` wraps its connection to the device in it, so the test in the VM
// (tests/linux) can compare what fftest and testhaptic asked the kernel for with what
// crossed the cable to the feel device. The lines have the form of feel's USB device log
// (docs/usb-device.md, "The device log"): the CLOCK_MONOTONIC time in seconds, the frame
// kind, then protocol::describe_report's fields; "refused ..." for a CommandStatus with an
// error. Input state reports are not logged (hundreds a second, nothing asked).
#pragma once

#include <iosfwd>
#include <memory>
#include <mutex>

#include "feel/transport/transport.hpp"

namespace feel::bridge {

class WireLog final : public transport::Connection {
public:
    // `out` must outlive the connection.
    WireLog(std::unique_ptr<transport::Connection> inner, std::ostream& out);
    void send(const transport::Frame& frame) override;
    bool send_or_drop(const transport::Frame& frame) override;
    std::optional<transport::Frame> receive(std::chrono::milliseconds timeout) override;
    void close() noexcept override;
    [[nodiscard]] std::string peer() const override;

private:
    void note(const transport::Frame& frame);
    std::unique_ptr<transport::Connection> inner_;
    std::ostream& out_;
    std::mutex mutex_;
};

}  // namespace feel::bridge
