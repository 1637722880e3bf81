#include "wire_log.hpp"

#include <time.h>

#include <cstdio>
#include <ostream>
#include <variant>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/report_text.hpp"

namespace feel::bridge {
namespace {

double monotonic_s() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

}  // namespace

WireLog::WireLog(std::unique_ptr<transport::Connection> inner, std::ostream& out)
    : inner_(std::move(inner)), out_(out) {}

void WireLog::note(const transport::Frame& frame) {
    using transport::FrameKind;
    if (frame.kind != FrameKind::output_report && frame.kind != FrameKind::set_feature &&
        frame.kind != FrameKind::feature_reply && frame.kind != FrameKind::input_report) {
        return;
    }
    protocol::AnyReport report;
    if (protocol::decode(frame.payload, report)) return;  // state reports need the input layout: not logged
    std::string verb(transport::frame_kind_name(frame.kind));
    if (frame.kind == FrameKind::input_report) {
        const auto* status = std::get_if<protocol::CommandStatusReport>(&report);
        if (status == nullptr || status->code == ErrorCode::ok) return;
        verb = "refused";
    }
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%.6f ", monotonic_s());
    std::lock_guard lock(mutex_);
    out_ << stamp << verb << ' ' << protocol::describe_report(report) << '\n' << std::flush;
}

void WireLog::send(const transport::Frame& frame) {
    note(frame);
    inner_->send(frame);
}

bool WireLog::send_or_drop(const transport::Frame& frame) {
    const bool sent = inner_->send_or_drop(frame);
    if (sent) note(frame);
    return sent;
}

std::optional<transport::Frame> WireLog::receive(std::chrono::milliseconds timeout) {
    std::optional<transport::Frame> frame = inner_->receive(timeout);
    if (frame) note(*frame);
    return frame;
}

void WireLog::close() noexcept { inner_->close(); }

std::string WireLog::peer() const { return inner_->peer(); }

}  // namespace feel::bridge
