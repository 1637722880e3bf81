// The device session's state and its steps (private to src/peripheral).
//
// `DeviceSession::Impl` is one state machine in two files: device_session.cpp holds the
// runtime's side (internal commands, acks, state report rounds, the answers sent back) and
// the public calls; session_host_frames.cpp holds the host's side (each frame decoded,
// checked, and answered or turned into one runtime command). The design of the whole is at
// the top of device_session.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "block_table.hpp"
#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "report_translation.hpp"

namespace feel::peripheral {
namespace detail {

// What a pending entry sends to the host once complete.
enum class Answer : uint8_t {
    status,            // a CommandStatus
    status_if_refused, // a CommandStatus only for an error (Download Force Sample)
    block_load,        // feature reply: BlockLoad
    pid_pool,          // feature reply: PidPool (after its query_pool ack)
    device_info,       // feature reply: DeviceInfo
    descriptor,        // descriptor reply
    none,              // an internal command: nothing
};

// What the ack of an entry's command does to the session.
enum class OnAck : uint8_t {
    nothing,
    commit_create,  // the block's first commit
    commit_update,  // a later commit
    free_block,     // Block Free of a committed block
    reset,          // device reset: every block freed
    pool,           // query_pool: the pool
    stage,          // stage_samples: a refusal breaks the stage
    report_rate,    // set_report_rate: the new rate
};

struct Pending {
    Answer answer = Answer::status;
    OnAck on_ack = OnAck::nothing;
    bool waiting = false;        // its command's ack has not arrived
    bool fence = false;
    bool discard = false;        // the host that sent it is gone: apply the ack, send nothing
    bool effect_status = false;  // copy the ack's EffectStatus into the answer
    uint32_t runtime_sequence = 0;
    uint16_t block = 0;
    int32_t value = 0;           // report_rate: the rate asked for
    protocol::CommandAnswer status{};
    protocol::BlockLoadReport block_load{};
};

// An internal command waiting for room: the reset after a host left, a pool query.
struct Internal {
    runtime::Command command{};
    OnAck on_ack = OnAck::nothing;
    bool fence = false;
};

// The outcome of processing one frame.
enum class Step : uint8_t { done, blocked };

}  // namespace detail

struct DeviceSession::Impl {
    using Frame = transport::Frame;
    using FrameKind = transport::FrameKind;
    using ReportId = protocol::ReportId;
    using Refusal = detail::Refusal;
    using Answer = detail::Answer;
    using OnAck = detail::OnAck;
    using Pending = detail::Pending;
    using Internal = detail::Internal;
    using Step = detail::Step;

    Impl(const runtime::Capabilities& c, const runtime::RuntimeConfig& cfg, runtime::HostLink& l,
         LoopFiguresProvider f);

    // ---- configuration
    runtime::Capabilities caps;
    protocol::JoystickLayout layout;  // the device's inputs: its Joystick Input and descriptor
    std::vector<uint8_t> descriptor;
    runtime::RuntimeConfig config;
    runtime::HostLink* link;
    LoopFiguresProvider figures;

    // ---- state
    detail::BlockTable blocks;
    std::deque<Frame> inbox;
    std::deque<Pending> pending;
    std::size_t pending_capacity;
    std::deque<Internal> internal;  // at most five: release, reset, report rate, IDF, pool query
    int32_t waiting = 0;            // pending entries whose ack has not arrived
    bool fence_in_flight = false;
    uint32_t next_sequence = 1;
    PoolInfo pool{};
    bool pool_query_queued = false;
    int32_t report_rate_hz;
    protocol::BlockLoadReport last_block_load{0, protocol::BlockLoadStatus::error, 0};
    // The runtime's sample stage, as far as the session's commands made it.
    uint16_t stage_block = 0;
    int32_t staged = 0;
    // The state report round being gathered (its pages), and what the host was told.
    bool round_open = false;
    runtime::StateReport round{};
    std::vector<runtime::EffectStateEntry> round_entries;
    std::vector<uint8_t> playing_now;  // [block]: playing in the round being sent
    bool flags_sent = false;
    protocol::PidStateReport last_flags{};
    SessionCounters counters{};
    runtime::Report incoming{};  // the runtime report being read (1 KB: not on the stack)

    // ------------------------------------------------------------------------------------
    // Internal commands.

    void queue_internal(const runtime::Command& command, OnAck on_ack, bool fence);
    bool pending_full() const noexcept { return pending.size() >= pending_capacity; }

    // Sends `command` numbered with the session's counter; false (nothing sent) when the
    // queue is full.
    bool send(runtime::Command command, uint32_t& sequence);
    void send_internal();
    void push_waiting(Pending p);

    // ------------------------------------------------------------------------------------
    // Runtime reports.

    void drain_runtime(std::vector<Frame>& out);
    void on_ack(const runtime::CommandAck& ack);
    void apply_ack(Pending& p, const runtime::CommandAck& ack);

    // A refused commit: the block is as it was before the transaction began.
    static void roll_back(detail::Block& b);
    void on_state(const runtime::StateReport& s, std::vector<Frame>& out);
    void emit_round(std::vector<Frame>& out);
    static bool same_flags(const protocol::PidStateReport& a, const protocol::PidStateReport& b) noexcept;
    void on_dynamic(const DynamicReport& d, std::vector<Frame>& out);

    // ------------------------------------------------------------------------------------
    // Answers.

    void emit_answers(std::vector<Frame>& out);
    void emit_answer(Pending& p, std::vector<Frame>& out);
    protocol::PidPoolReport pid_pool_report() const;
    protocol::DeviceInfoReport device_info_report() const;

    // ------------------------------------------------------------------------------------
    // Host frames.

    void process_inbox();

    // An answer complete at once.
    void answer_now(Pending p) { pending.push_back(std::move(p)); }

    static Pending status_entry(uint32_t sequence, ReportId command, uint16_t block);
    void refuse(uint32_t sequence, ReportId command, uint16_t block, const Refusal& why);
    void refuse_frame(const Frame& f, const Refusal& why);
    static Refusal from_error(const Error& e);
    Step process(const Frame& f);
    Step process_get_feature(const Frame& f);
    Step process_report(const Frame& f, protocol::ReportKind expected);

    // ---- block lookups

    // The allocated block a report names, or a refusal.
    detail::Block* find_block(ReportId id, uint16_t index, uint32_t sequence);

    // The committed block a report names (its effect exists in the engine), or a refusal.
    detail::Block* find_committed(ReportId id, uint16_t index, uint32_t sequence);

    // A report that becomes one pipelined runtime command, answered by its ack.
    Step forward(const runtime::Command& command, uint32_t sequence, ReportId id, uint16_t block,
                 bool effect_status = false, OnAck on_ack = OnAck::nothing, int32_t value = 0);

    // ---- the reports

    Step handle(const protocol::CreateNewEffectReport& r);

    template <class R>
    Step type_block(const R& r);
    Step apply_level(const protocol::SetConstantForceReport& r, detail::Block& b);
    Step handle(const protocol::SetEnvelopeReport& r) { return type_block(r); }
    Step handle(const protocol::SetConditionReport& r) { return type_block(r); }
    Step handle(const protocol::SetPeriodicReport& r) { return type_block(r); }
    Step handle(const protocol::SetConstantForceReport& r) { return type_block(r); }
    Step handle(const protocol::SetRampForceReport& r) { return type_block(r); }
    Step handle(const protocol::SetCustomForceReport& r) { return type_block(r); }
    Step handle(const protocol::SetTextureReport& r) { return type_block(r); }
    Step handle(const protocol::SetWallReport& r) { return type_block(r); }
    Step handle(const protocol::SetBarrierReport& r) { return type_block(r); }
    Step handle(const protocol::SetSweepReport& r) { return type_block(r); }
    Step handle(const protocol::SetDynamicReport& r) { return type_block(r); }
    Step handle(const protocol::SetControlLawReport& r) { return type_block(r); }

    Step handle(const protocol::CustomForceDataReport& r);
    Step handle(const protocol::SetEffectReport& r);
    Step handle(const protocol::DownloadForceSampleReport& r);
    Step handle(const protocol::EffectOperationReport& r);
    Step handle(const protocol::BlockFreeReport& r);
    Step handle(const protocol::DeviceControlReport& r);
    Step handle(const protocol::DeviceGainReport& r);
    Step handle(const protocol::ReflexReport& r);
    Step handle(const protocol::IdfSettingsReport& r);
    Step handle(const protocol::ReportRateReport& r);
    Step handle(const protocol::KeepAliveReport& r);
    Step handle(const protocol::EffectStatusRequestReport& r);

    // Feature gets and input reports never arrive here (process_report refuses them by
    // kind first); these keep the visit total.
    Step handle(const protocol::BlockLoadReport&) { return Step::done; }
    Step handle(const protocol::PidPoolReport&) { return Step::done; }
    Step handle(const protocol::DeviceInfoReport&) { return Step::done; }
    Step handle(const protocol::JoystickInputReport&) { return Step::done; }
    Step handle(const protocol::PidStateReport&) { return Step::done; }
    Step handle(const protocol::CommandStatusReport&) { return Step::done; }
    Step handle(const protocol::DeviceStatusReport&) { return Step::done; }
    Step handle(const protocol::DynamicReportReport&) { return Step::done; }
    Step handle(const protocol::CommandErrorTextReport&) { return Step::done; }
    Step handle(const protocol::EffectStatesReport&) { return Step::done; }

    // ------------------------------------------------------------------------------------

    void host_gone();
};

}  // namespace feel::peripheral
