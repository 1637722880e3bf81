// A DeviceSession on a RuntimePipeline ticked by hand, and a host that speaks to it in
// encoded frames: what the peripheral's tests drive. No thread: tick n runs when the test
// says, so every exchange is deterministic.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "feel/protocol/effect_reports.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/transport/transport.hpp"

namespace feel::peripheral::test {

using transport::Frame;
using transport::FrameKind;

inline const sim::DeviceProfile& profile(const char* name) { return *sim::find_device_profile(name); }

// The profile's runtime with forces at once and no host watchdog: the tests that are not
// about safety see the engine's forces unscaled and need no keep-alives.
inline runtime::RuntimeConfig quiet_config(const sim::DeviceProfile& p) {
    runtime::RuntimeConfig c = runtime::runtime_config_for(p);
    c.safety.fade_in_us = 0;
    c.safety.host_timeout_us = kInfiniteUs;
    return c;
}

inline Frame output(const protocol::AnyReport& r) { return Frame{FrameKind::output_report, protocol::encode(r)}; }
inline Frame set_feature(const protocol::AnyReport& r) { return Frame{FrameKind::set_feature, protocol::encode(r)}; }
inline Frame get_feature(protocol::ReportId id) { return Frame{FrameKind::get_feature, {static_cast<uint8_t>(id)}}; }

class SessionRig {
public:
    explicit SessionRig(const char* profile_name = "iforce2", const char* motion = "hold:0",
                        sim::Grip grip = sim::Grip::firm)
        : profile_(&profile(profile_name)), caps_(runtime::capabilities_for(*profile_)) {
        const runtime::RuntimeConfig config = quiet_config(*profile_);
        auto backend = std::make_unique<runtime::SimBackend>(
            *profile_, grip, sim::TargetMotion::parse(motion, 10, profile_->axis_count));
        sim_ = backend.get();
        pipeline_ = std::make_unique<runtime::RuntimePipeline>(config, std::move(backend));
        link_ = std::make_unique<runtime::HostLink>(pipeline_->commands(), pipeline_->reports());
        session_ = std::make_unique<DeviceSession>(caps_, pipeline_->config(), *link_);
        run(2);  // the session's first pool query, answered
    }

    DeviceSession& session() { return *session_; }
    runtime::RuntimePipeline& pipeline() { return *pipeline_; }
    runtime::SimBackend& sim() { return *sim_; }
    const runtime::Capabilities& caps() const { return caps_; }

    // One tick of the loop with the session pumped before and after.
    void run(int ticks = 1) {
        for (int i = 0; i < ticks; ++i) {
            pump();
            pipeline_->tick(next_tick_++);
            pump();
        }
    }

    void pump() {
        std::vector<Frame> out;
        session_->pump(out);
        for (Frame& f : out) take(std::move(f));
    }

    // Offers a frame (it must be taken).
    void offer(Frame f) { ASSERT_TRUE(session_->offer(std::move(f))) << "the session's inbox is full"; }

    // Sends an output report or sets a feature report and runs until its CommandStatus
    // comes (at most 50 ticks).
    protocol::CommandAnswer command(const protocol::AnyReport& r, bool feature = false) {
        const uint32_t sequence = std::visit([](const auto& x) -> uint32_t {
            if constexpr (requires { x.sequence; }) return x.sequence; else return 0;
        }, r);
        const std::size_t seen = statuses.size();
        offer(feature ? set_feature(r) : output(r));
        for (int i = 0; i < 50; ++i) {
            pump();
            for (std::size_t k = seen; k < statuses.size(); ++k) {
                if (statuses[k].sequence == sequence) return statuses[k];
            }
            run(1);
        }
        ADD_FAILURE() << "no CommandStatus for sequence " << sequence;
        return {};
    }

    // A command that must succeed.
    protocol::CommandAnswer ok(const protocol::AnyReport& r, bool feature = false) {
        const protocol::CommandAnswer s = command(r, feature);
        EXPECT_EQ(s.code, ErrorCode::ok) << "report " << static_cast<int>(s.command) << " seq " << s.sequence
                                         << ": " << s.field << " " << s.rule;
        return s;
    }

    // Gets a feature report and runs until the reply comes.
    template <class R>
    R get(protocol::ReportId id) {
        const std::size_t seen = feature_replies.size();
        offer(get_feature(id));
        for (int i = 0; i < 50; ++i) {
            pump();
            if (feature_replies.size() > seen) {
                const protocol::AnyReport& r = feature_replies[seen];
                if (const R* reply = std::get_if<R>(&r)) return *reply;
                ADD_FAILURE() << "the feature reply is another report";
                return R{};
            }
            run(1);
        }
        ADD_FAILURE() << "no feature reply";
        return R{};
    }

    // Creates an effect block of this type; returns the block (0 when refused).
    uint16_t create(EffectType type, uint16_t sample_count = 0) {
        protocol::CreateNewEffectReport r;
        r.sequence = next_sequence();
        r.type = type;
        r.sample_count = sample_count;
        const protocol::CommandAnswer s = command(r, true);
        const auto load = get<protocol::BlockLoadReport>(protocol::ReportId::block_load);
        if (s.code != ErrorCode::ok) {
            EXPECT_EQ(load.block, 0);
            return 0;
        }
        EXPECT_EQ(load.status, protocol::BlockLoadStatus::success);
        EXPECT_EQ(load.block, s.block);
        return load.block;
    }

    uint32_t next_sequence() { return sequence_++; }

    // Every frame the device sent, sorted by kind.
    // The CommandStatus answers, each joined with the Command Error Text before it.
    std::vector<protocol::CommandAnswer> statuses;
    std::vector<protocol::AnyReport> feature_replies;
    std::vector<std::vector<uint8_t>> descriptors;
    std::vector<protocol::JoystickInputReport> joystick;
    std::vector<protocol::DeviceStatusReport> device_status;
    std::vector<protocol::EffectStatesReport> effect_states;
    std::vector<protocol::PidStateReport> pid_states;
    std::vector<protocol::DynamicReportReport> dynamics;
    std::vector<Frame> other;

private:
    void take(Frame f) {
        if (f.kind == FrameKind::descriptor_reply) {
            descriptors.push_back(std::move(f.payload));
            return;
        }
        if (f.kind == FrameKind::input_report && !f.payload.empty() &&
            f.payload[0] == static_cast<uint8_t>(protocol::ReportId::joystick_input)) {
            // The device's own layout: the profile's axes, buttons and hats.
            protocol::JoystickLayout layout;
            layout.axis_count = static_cast<uint8_t>(profile_->axis_count);
            for (int a = 0; a < profile_->axis_count; ++a) layout.axes[a] = profile_->axes[a].axis;
            layout.button_count = static_cast<uint8_t>(profile_->button_count);
            layout.hat_count = static_cast<uint8_t>(profile_->hat_count);
            protocol::JoystickInputReport j;
            const Error e = protocol::decode(f.payload, layout, j);
            ASSERT_TRUE(e.ok()) << "the device sent a joystick input that does not decode: " << e.message();
            joystick.push_back(j);
            return;
        }
        protocol::AnyReport r;
        const Error e = protocol::decode(f.payload, r);
        ASSERT_TRUE(e.ok()) << "the device sent a report that does not decode: " << e.message();
        if (f.kind == FrameKind::feature_reply) {
            feature_replies.push_back(r);
            return;
        }
        ASSERT_EQ(f.kind, FrameKind::input_report);
        if (auto* t = std::get_if<protocol::CommandErrorTextReport>(&r)) error_text_.add(*t);
        else if (auto* s = std::get_if<protocol::CommandStatusReport>(&r)) statuses.push_back(error_text_.finish(*s));
        else if (auto* es = std::get_if<protocol::EffectStatesReport>(&r)) effect_states.push_back(*es);
        else if (auto* j = std::get_if<protocol::JoystickInputReport>(&r)) joystick.push_back(*j);
        else if (auto* d = std::get_if<protocol::DeviceStatusReport>(&r)) device_status.push_back(*d);
        else if (auto* p = std::get_if<protocol::PidStateReport>(&r)) pid_states.push_back(*p);
        else if (auto* y = std::get_if<protocol::DynamicReportReport>(&r)) dynamics.push_back(*y);
        else other.push_back(std::move(f));
    }

    const sim::DeviceProfile* profile_;
    runtime::Capabilities caps_;
    protocol::CommandAnswerJoiner error_text_;
    runtime::SimBackend* sim_ = nullptr;
    std::unique_ptr<runtime::RuntimePipeline> pipeline_;
    std::unique_ptr<runtime::HostLink> link_;
    std::unique_ptr<DeviceSession> session_;
    int64_t next_tick_ = 0;
    uint32_t sequence_ = 100;
};

// Reports a test builds often.
inline protocol::SetEffectReport set_effect(uint32_t sequence, uint16_t block, EffectType type, uint8_t axis_count = 1) {
    protocol::SetEffectReport r;
    r.sequence = sequence;
    r.block = block;
    r.type = type;
    r.axis_count = axis_count;
    return r;
}

inline protocol::SetConditionReport spring_axis(uint32_t sequence, uint16_t block, uint8_t axis, int16_t k) {
    protocol::SetConditionReport r;
    r.sequence = sequence;
    r.block = block;
    r.axis_index = axis;
    r.pos_coefficient = k;
    r.neg_coefficient = k;
    return r;
}

inline protocol::SetPeriodicReport periodic(uint32_t sequence, uint16_t block, int16_t magnitude, uint32_t period_us) {
    protocol::SetPeriodicReport r;
    r.sequence = sequence;
    r.block = block;
    r.magnitude = magnitude;
    r.period_us = period_us;
    return r;
}

inline protocol::EffectOperationReport operation(uint32_t sequence, uint16_t block, protocol::EffectOperation op,
                                                 uint16_t loop_count = protocol::kLoopEffectOwn) {
    protocol::EffectOperationReport r;
    r.sequence = sequence;
    r.block = block;
    r.operation = op;
    r.loop_count = loop_count;
    return r;
}

// Downloads an effect the way a host does (protocol/effect_reports.hpp): Create New Effect,
// Block Load, the envelope and every type block the type uses (a force profile's samples in
// data reports), Set Effect. Each report must succeed; returns the block.
inline uint16_t download(SessionRig& rig, const EffectParams& p, std::span<const int16_t> samples = {}) {
    const uint16_t block = rig.create(p.type, static_cast<uint16_t>(samples.size()));
    if (block == 0) return 0;
    for (protocol::AnyReport& r : protocol::parameter_block_reports(p, samples, block, true, true)) {
        protocol::set_sequence(r, rig.next_sequence());
        rig.ok(r);
    }
    protocol::SetEffectReport commit = protocol::set_effect_report(p, block);
    commit.sequence = rig.next_sequence();
    rig.ok(commit);
    return block;
}

}  // namespace feel::peripheral::test
