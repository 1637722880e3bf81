// A host connection seen through the standard PID device's eyes (PeripheralOptions::
// standard_pid_only): the Peripheral's session speaks feel's reports, the host the standard
// form (protocol/standard_pid.hpp). Wraps the device's end of the connection:
//
//   receive   a standard output or feature report becomes feel's (vendor fields 0); a
//             report the standard device lacks, or one that does not translate, is dropped
//             (a standard device has no answer to give); GET_REPORT of a feature report it
//             lacks is dropped too; GET_DESCRIPTOR is answered here with the standard
//             descriptor.
//   send      Joystick Input, PID State and the PID feature replies go out in the standard
//             form; every vendor report (Command Status, Device Status, ...) stays here.
//
// Counts what it kept back, for the tests. Not thread-safe beyond what the wrapped
// connection is: the Peripheral's service thread is its only user.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/transport/transport.hpp"

namespace feel::peripheral {

class StandardPidConnection final : public transport::Connection {
public:
    StandardPidConnection(std::unique_ptr<transport::Connection> inner, const protocol::JoystickLayout& layout);

    void send(const transport::Frame& frame) override;
    bool send_or_drop(const transport::Frame& frame) override;
    std::optional<transport::Frame> receive(std::chrono::milliseconds timeout) override;
    void close() noexcept override { inner_->close(); }
    [[nodiscard]] std::string peer() const override { return inner_->peer(); }

private:
    // The frame as the host sees it; false: not sent (a vendor report).
    bool outgoing(const transport::Frame& frame, transport::Frame& out) const;

    std::unique_ptr<transport::Connection> inner_;
    std::vector<uint8_t> descriptor_;
};

}  // namespace feel::peripheral
