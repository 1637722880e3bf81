// libFuzzer target: a hostile host against the device session.
//
// The input is a script of steps, each [op: u8][length: u16 little-endian][payload]:
//   op 1..9    a frame of that transport::FrameKind carrying the payload (the host sends
//              anything, device-to-host kinds included)
//   op 0xFE    run payload[0] + 1 ticks of the loop (no payload: one tick)
//   op 0xFF    the host goes away (DeviceSession::host_gone)
//   other ops  a frame of kind (op % 8) + 1
// A length beyond the input takes what is left. Between steps the RuntimePipeline (the
// iforce2 simulated device, no threads) runs one tick with the session pumped before and
// after. At the end the loop runs until the session is idle.
//
// Invariants (a violation aborts):
//   - nothing throws or crashes; every frame the device sends decodes;
//   - every frame the host sent since it last went away got exactly one answer (a
//     CommandStatus, a feature reply or the descriptor), except Download Force Sample
//     reports, answered only when refused;
//   - whenever the session is idle, the blocks it holds committed are exactly the effects
//     resident in the engine, each one alive there, and every block it holds is one the
//     device has.
// The seeds in fuzz/corpus/device_session/ are valid transactions in this format
// (tests/peripheral/fuzz_corpus_test.cpp checks that they run clean).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>
#include <variant>
#include <vector>

#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"

namespace {

using namespace feel;
using transport::Frame;
using transport::FrameKind;

constexpr uint8_t kTicksOp = 0xFE;
constexpr uint8_t kHostGoneOp = 0xFF;
constexpr int kDrainTicks = 400;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "device session invariant broken: %s\n", what);
    std::abort();
}

class Harness {
public:
    Harness() : profile_(*sim::find_device_profile("iforce2")), caps_(runtime::capabilities_for(profile_)) {
        runtime::RuntimeConfig config = runtime::runtime_config_for(profile_);
        config.safety.fade_in_us = 0;
        config.safety.host_timeout_us = kInfiniteUs;  // the script's ticks are not the host's pace
        pipeline_ = std::make_unique<runtime::RuntimePipeline>(
            config, std::make_unique<runtime::SimBackend>(profile_, sim::Grip::firm,
                                                          sim::TargetMotion::hold_at({1000, -2000})));
        link_ = std::make_unique<runtime::HostLink>(pipeline_->commands(), pipeline_->reports());
        session_ = std::make_unique<peripheral::DeviceSession>(caps_, pipeline_->config(), *link_);
    }

    void send(Frame frame) {
        // A DownloadForceSample output report is answered only when refused.
        protocol::AnyReport r;
        const bool force_sample = frame.kind == FrameKind::output_report &&
                                  protocol::decode(frame.payload, r).ok() &&
                                  std::holds_alternative<protocol::DownloadForceSampleReport>(r);
        for (int i = 0; !session_->offer(frame); ++i) {
            if (i > kDrainTicks) fail("the inbox never makes room");
            tick();
        }
        (force_sample ? force_samples_ : frames_)++;
        tick();
    }

    void host_gone() {
        session_->host_gone();
        frames_ = force_samples_ = answers_ = force_answers_ = 0;
        tick();
    }

    void tick() {
        pump();
        pipeline_->tick(next_tick_++);
        pump();
        check_counts();
        if (session_->idle()) check_blocks();
    }

    void finish() {
        for (int i = 0; !session_->idle(); ++i) {
            if (i > kDrainTicks) fail("the session never becomes idle");
            tick();
        }
        check_blocks();
        if (answers_ != frames_) fail("a frame went unanswered (or was answered twice)");
        if (force_answers_ > force_samples_) fail("more force sample refusals than force samples");
    }

private:
    void pump() {
        out_.clear();
        session_->pump(out_);
        for (const Frame& f : out_) take(f);
    }

    void take(const Frame& f) {
        switch (f.kind) {
            case FrameKind::descriptor_reply: ++answers_; return;
            case FrameKind::feature_reply:
            case FrameKind::input_report: break;
            default: fail("the device sent a host-to-device frame kind");
        }
        if (f.kind == FrameKind::input_report && !f.payload.empty() &&
            f.payload[0] == static_cast<uint8_t>(protocol::ReportId::joystick_input)) {
            // The device's own joystick layout: the profile's axes, buttons and hats.
            protocol::JoystickInputReport joy;
            if (!protocol::decode(f.payload, peripheral::joystick_layout(caps_), joy).ok()) {
                fail("the device sent a joystick input that does not decode");
            }
            return;
        }
        protocol::AnyReport r;
        if (!protocol::decode(f.payload, r).ok()) fail("the device sent a report that does not decode");
        if (f.kind == FrameKind::feature_reply) {
            ++answers_;
            return;
        }
        if (const auto* t = std::get_if<protocol::CommandErrorTextReport>(&r)) error_text_.add(*t);
        if (const auto* status = std::get_if<protocol::CommandStatusReport>(&r)) {
            const protocol::CommandAnswer answer = error_text_.finish(*status);
            const protocol::CommandAnswer* s = &answer;
            // Refusals of a streamed sample come from the runtime and name its "stream." fields.
            const bool force_refusal = s->command == protocol::ReportId::download_force_sample &&
                                       answer.field_text().substr(0, 7) == "stream.";
            (force_refusal ? force_answers_ : answers_)++;
        }
    }

    void check_counts() const {
        if (answers_ > frames_) fail("more answers than frames");
        if (force_answers_ > force_samples_) fail("more force sample refusals than force samples");
    }

    void check_blocks() const {
        const runtime::RuntimePipeline& p = *pipeline_;
        if (session_->committed_blocks() != p.resident_effects()) {
            std::fprintf(stderr, "committed blocks %d, resident effects %d\n", session_->committed_blocks(),
                         p.resident_effects());
            fail("blocks committed != effects resident");
        }
        if (session_->allocated_blocks() > session_->block_capacity()) fail("more blocks than the device has");
        int committed = 0;
        for (int b = 1; b <= session_->block_capacity(); ++b) {
            const auto view = session_->block(static_cast<uint16_t>(b));
            if (!view || !view->committed) continue;
            ++committed;
            if (p.engine().state(view->effect) == EffectState::free) fail("a committed block names a freed effect");
            if (view->type != view->committed_params.type) fail("a block changed its type");
        }
        if (committed != session_->committed_blocks()) fail("the committed count disagrees with the blocks");
    }

    const sim::DeviceProfile& profile_;
    runtime::Capabilities caps_;
    std::unique_ptr<runtime::RuntimePipeline> pipeline_;
    std::unique_ptr<runtime::HostLink> link_;
    std::unique_ptr<peripheral::DeviceSession> session_;
    std::vector<Frame> out_;
    int64_t next_tick_ = 0;
    int64_t frames_ = 0, force_samples_ = 0, answers_ = 0, force_answers_ = 0;
    protocol::CommandAnswerJoiner error_text_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Harness h;
    size_t at = 0;
    while (at < size) {
        const uint8_t op = data[at++];
        size_t length = 0;
        if (at < size) length = data[at++];
        if (at < size) length |= static_cast<size_t>(data[at++]) << 8;
        if (length > size - at) length = size - at;
        const uint8_t* payload = data + at;
        at += length;
        if (op == kTicksOp) {
            const int ticks = length > 0 ? payload[0] + 1 : 1;
            for (int i = 0; i < ticks; ++i) h.tick();
        } else if (op == kHostGoneOp) {
            h.host_gone();
        } else {
            const uint8_t kind = op >= 1 && op <= transport::kFrameKindCount ? op : static_cast<uint8_t>(op % 8 + 1);
            h.send(Frame{static_cast<FrameKind>(kind), std::vector<uint8_t>(payload, payload + length)});
        }
    }
    h.finish();
    return 0;
}
