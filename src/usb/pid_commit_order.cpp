// PidCommitOrder (pid_commit_order.hpp).
#include "pid_commit_order.hpp"

#include <optional>
#include <variant>

#include "feel/protocol/codec.hpp"

namespace feel::usb::detail {
namespace {

using protocol::ReportId;

// The effect block a report names, if it names one.
std::optional<uint16_t> block_of(const protocol::AnyReport& report) {
    return std::visit(
        [](const auto& r) -> std::optional<uint16_t> {
            if constexpr (requires { r.block; }) {
                return static_cast<uint16_t>(r.block);
            } else {
                return std::nullopt;
            }
        },
        report);
}

bool is_parameter_block(ReportId id) {
    switch (id) {
        case ReportId::set_envelope:
        case ReportId::set_condition:
        case ReportId::set_periodic:
        case ReportId::set_constant_force:
        case ReportId::set_ramp_force:
        case ReportId::set_custom_force:
        case ReportId::custom_force_data:
        case ReportId::set_texture:
        case ReportId::set_wall:
        case ReportId::set_barrier:
        case ReportId::set_sweep:
        case ReportId::set_dynamic:
        case ReportId::set_control_law: return true;
        default: return false;
    }
}

bool acts_on_effect(ReportId id) {
    return id == ReportId::effect_operation || id == ReportId::block_free ||
           id == ReportId::effect_status_request || id == ReportId::reflex;
}

}  // namespace

void PidCommitOrder::commit(uint16_t block, std::vector<transport::Frame>& out) {
    auto it = blocks_.find(block);
    if (it == blocks_.end() || !it->second.dirty) return;
    it->second.dirty = false;
    out.push_back(transport::Frame{transport::FrameKind::output_report, it->second.set_effect});
}

void PidCommitOrder::commit_all(std::vector<transport::Frame>& out) {
    for (auto& [block, state] : blocks_) commit(block, out);
}

std::vector<transport::Frame> PidCommitOrder::on_frame(transport::Frame frame, Clock::time_point now) {
    std::vector<transport::Frame> out;
    protocol::AnyReport report;
    const bool output = frame.kind == transport::FrameKind::output_report;
    if (!output || protocol::decode(frame.payload, report)) {
        out.push_back(std::move(frame));  // not an output report, or one the session refuses
        return out;
    }
    const ReportId id = protocol::report_id_of(report);
    const std::optional<uint16_t> block = block_of(report);
    if (id == ReportId::set_effect && block) {
        Block& b = blocks_[*block];
        b.set_effect = std::move(frame.payload);
        b.dirty = true;
        b.last = now;
        return out;  // held
    }
    if (is_parameter_block(id) && block) {
        out.push_back(std::move(frame));
        auto it = blocks_.find(*block);
        if (it != blocks_.end()) {
            it->second.dirty = true;
            it->second.last = now;
        }
        return out;
    }
    if (acts_on_effect(id) && block) {
        commit(*block, out);
        out.push_back(std::move(frame));
        if (id == ReportId::block_free) blocks_.erase(*block);
        return out;
    }
    if (id == ReportId::device_control) {
        commit_all(out);
        out.push_back(std::move(frame));
        const auto& control = std::get<protocol::DeviceControlReport>(report);
        if (control.control == protocol::DeviceControlOp::device_reset) blocks_.clear();
        return out;
    }
    out.push_back(std::move(frame));
    return out;
}

std::vector<transport::Frame> PidCommitOrder::on_time(Clock::time_point now) {
    std::vector<transport::Frame> out;
    for (auto& [block, state] : blocks_) {
        if (state.dirty && now - state.last >= kSettle) commit(block, out);
    }
    return out;
}

PidCommitOrder::Clock::time_point PidCommitOrder::next_deadline() const noexcept {
    Clock::time_point soonest = Clock::time_point::max();
    for (const auto& [block, state] : blocks_) {
        if (state.dirty && state.last + kSettle < soonest) soonest = state.last + kSettle;
    }
    return soonest;
}

void PidCommitOrder::reset() noexcept { blocks_.clear(); }

}  // namespace feel::usb::detail
