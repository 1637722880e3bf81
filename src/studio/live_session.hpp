// feel::studio — one browser's live session: its sensation on the device, its buttons,
// the hand under its pointer, and the state frames it is sent.
//
// Messages (docs/studio.md, "Protocol") are checked against the protocol's one schema
// before they are read; a message that breaks it, or that the device refuses, gets an
// `error` reply and changes nothing. The sensation arrives whole on every edit
// (set_sensation). It is read by the format's own reader, as `feel check` reads a file, so
// an error names the same field with the same sentence; an invalid sensation never
// reaches the device. A valid one reaches it as partial updates (Effect::set_parameters
// with the mask of the fields that changed, no restart): a playing effect goes on playing
// with its new parameters. Only a change of type or of axes needs a new effect, which is
// restarted if it was playing.
//
// The session owns the effects it made: when the browser goes away the session is
// destroyed, and with it the effects (RAII unload: they stop) and its pressed buttons.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "feel/format/sensation_file.hpp"
#include "feel/host/device.hpp"
#include "studio_device.hpp"

namespace feel::studio {

class ProtocolSchema;
class Workspace;

// A dynamic's interim and final reports (§5.2), as the device's I/O thread delivers them,
// kept until the next state frame takes them (the dynamics schematic animates from them).
// Bounded: a browser that takes none keeps the newest kMax.
struct DynamicInbox {
    static constexpr size_t kMax = 256;
    std::mutex mu;
    std::vector<nlohmann::json> reports;
    void push(size_t effect, const host::DynamicEvent& e);
    std::vector<nlohmann::json> take();
};

class LiveSession {
public:
    LiveSession(std::shared_ptr<StudioDevice> device, const ProtocolSchema& schema);
    ~LiveSession();
    LiveSession(const LiveSession&) = delete;
    LiveSession& operator=(const LiveSession&) = delete;

    using Clock = std::chrono::steady_clock;
    // Handles one message (a WebSocket text frame) that the socket read at `received`;
    // returns the replies. Never throws.
    std::vector<nlohmann::json> handle(std::string_view text, Clock::time_point received = Clock::now());
    // Where `import_file` saves what it imports (docs/import.md); without one it is refused.
    void set_workspace(Workspace* workspace) noexcept { workspace_ = workspace; }
    // The next state frame: the device's reports since the last frame. `pointer_answered`
    // says whether it is the first to show the newest pointer message's force change.
    // `news` says whether it shows the page anything new: a report whose force, position
    // (in whole units, as the page draws them) or buttons differ from the last frame's, an
    // effect whose state, start count or arming changed, a dynamic's reports, a pointer's
    // hops. A frame without news carries only its newest report (the others were the same
    // but for their time), and the server need not send it (studio_server.cpp).
    nlohmann::json state_frame(bool* pointer_answered = nullptr, bool* news = nullptr);
    // The frame that answered pointer message `seq` was written to the socket `write_us`
    // after it was queued, behind `ahead` frames: the next frame says so.
    void note_pointer_written(int64_t seq, size_t ahead, double write_us);
    // Whether the newest pointer message's force change has not been shown yet.
    [[nodiscard]] bool pointer_awaited() const noexcept { return !pointer_.answered; }
    // Whether the device's newest report, not yet in a frame, shows that change (the next
    // frame would answer the pointer message).
    [[nodiscard]] bool pointer_answer_ready() const;

    [[nodiscard]] int64_t pointer_seq() const noexcept { return pointer_seq_; }

    // For tests: the effects the session holds on the device, by index.
    [[nodiscard]] size_t effect_count() const noexcept { return slots_.size(); }
    [[nodiscard]] const host::Effect* effect(size_t i) const noexcept;

private:
    // Whether report `s` came from a tick after the device took the newest pointer's target
    // (`taken_us`: the newest take, device time), so that it can answer that pointer.
    [[nodiscard]] bool after_take(const DeviceSample& s, int64_t taken_us) const;
    struct Slot {
        format::EffectSpec spec;  // as the browser last sent it (valid)
        std::optional<host::Effect> effect;
        bool armed = true;        // "play on trigger": downloaded with its trigger
        bool playing = false;     // started by this session and not stopped
        int32_t starts = 0;       // how often this session started it
        host::Subscription reports;  // its dynamic reports (declared after effect: goes first)
    };

    nlohmann::json set_sensation(const nlohmann::json& m);
    std::optional<std::string> apply(size_t index, const format::EffectSpec& spec, bool& restarted);
    nlohmann::json effect_states();
    [[nodiscard]] EffectParams device_params(const Slot& slot) const;

    std::shared_ptr<StudioDevice> device_;
    const ProtocolSchema& schema_;
    std::vector<Slot> slots_;
    Workspace* workspace_ = nullptr;
    std::shared_ptr<DynamicInbox> inbox_ = std::make_shared<DynamicInbox>();
    uint64_t last_sample_ = 0;
    uint32_t buttons_ = 0;
    uint32_t hats_ = 0;
    int64_t pointer_seq_ = 0;
    // The newest pointer message's way through the server (docs/studio.md, "Latency"):
    // read from the socket, handed to the hand, the first report whose force moved, the
    // frame that shows it. Each state frame says how long ago it was read, and the frame
    // that first shows the change carries the hops, so the latency bench can tell the
    // server's share from the browser's and the sockets'.
    struct PointerTrace {
        Clock::time_point read{};     // the socket's read completion
        Clock::time_point applied{};  // set_hand_target returned
        float force[kMaxAxes] = {};   // the newest report's force when it was applied
        bool answered = true;         // a frame showed its force change
        float min_fade = 1;           // the lowest safety fade in the reports since applied
        // The device's software path, apart from the hand's physics: the take of the
        // previous target (device time), and when the report of the tick that took this
        // one reached the sampler (steady µs; unset until then).
        int64_t taken_before_us = -1;
        std::optional<int64_t> take_reported_us;
    };
    PointerTrace pointer_;
    // The smallest (sampler time - device time) seen: a report's transit from its tick to
    // the sampler is its own (sampler - device) less this (the clocks' offset plus the
    // fastest transit), which splits the device hop into the device's loop and the way
    // back (pointer_hops.transit_us).
    std::optional<int64_t> min_offset_us_;
    nlohmann::json pointer_written_;  // the answering frame's write, for the next frame
    std::chrono::steady_clock::time_point effect_states_at_{};  // when last_effect_states_ was read
    nlohmann::json last_effect_states_ = nlohmann::json::array();
    // What the last frame showed, to tell a frame with news from one without.
    struct Shown {
        bool any = false;  // a frame with a report was built
        long force[kMaxAxes] = {};
        long position[kMaxAxes] = {};
        uint32_t buttons = 0;
        std::string effects;  // each effect's state, start count and arming
    };
    Shown shown_;
    // The newest report of the frames without news since the last frame with news; null
    // when none, or when a keep-alive carried it (frame_sent_without_news()).
    nlohmann::json quiet_row_;

public:
    // The server sent the last frame although it had no news (the keep-alive).
    void frame_sent_without_news() { quiet_row_ = nullptr; }
};

}  // namespace feel::studio
