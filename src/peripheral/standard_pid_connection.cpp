// StandardPidConnection (standard_pid_connection.hpp).
#include "standard_pid_connection.hpp"

#include "feel/protocol/standard_pid.hpp"

namespace feel::peripheral {

using transport::Frame;
using transport::FrameKind;

StandardPidConnection::StandardPidConnection(std::unique_ptr<transport::Connection> inner,
                                             const protocol::JoystickLayout& layout)
    : inner_(std::move(inner)), descriptor_(protocol::standard_pid_descriptor(layout)) {}

bool StandardPidConnection::outgoing(const Frame& frame, Frame& out) const {
    out.kind = frame.kind;
    switch (frame.kind) {
        case FrameKind::input_report:
        case FrameKind::feature_reply: return protocol::feel_to_standard_pid(frame.payload, out.payload);
        case FrameKind::descriptor_reply: out.payload = descriptor_; return true;
        default: out.payload = frame.payload; return true;
    }
}

void StandardPidConnection::send(const Frame& frame) {
    Frame out;
    if (outgoing(frame, out)) inner_->send(out);
}

bool StandardPidConnection::send_or_drop(const Frame& frame) {
    Frame out;
    return !outgoing(frame, out) || inner_->send_or_drop(out);  // a vendor report is not "dropped": never sent
}

std::optional<Frame> StandardPidConnection::receive(std::chrono::milliseconds timeout) {
    std::optional<Frame> frame = inner_->receive(timeout);
    if (!frame) return frame;
    switch (frame->kind) {
        case FrameKind::output_report:
        case FrameKind::set_feature: {
            std::vector<uint8_t> feel;
            if (protocol::standard_pid_to_feel(frame->payload, feel)) return std::nullopt;
            frame->payload = std::move(feel);
            return frame;
        }
        case FrameKind::get_feature:
            if (frame->payload.empty() || !protocol::is_standard_pid_report(frame->payload[0])) return std::nullopt;
            return frame;
        case FrameKind::get_descriptor:
            inner_->send(Frame{FrameKind::descriptor_reply, descriptor_});
            return std::nullopt;
        default: return frame;
    }
}

}  // namespace feel::peripheral
