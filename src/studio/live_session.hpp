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

    // Handles one message (a WebSocket text frame); returns the replies. Never throws.
    std::vector<nlohmann::json> handle(std::string_view text);
    // Where `import_file` saves what it imports (docs/import.md); without one it is refused.
    void set_workspace(Workspace* workspace) noexcept { workspace_ = workspace; }
    // The next state frame: the device's reports since the last frame.
    nlohmann::json state_frame();
    // Whether the device has reported since the last frame.
    [[nodiscard]] bool has_news() const { return device_->newest_seq() > last_sample_; }

    // For tests: the effects the session holds on the device, by index.
    [[nodiscard]] size_t effect_count() const noexcept { return slots_.size(); }
    [[nodiscard]] const host::Effect* effect(size_t i) const noexcept;

private:
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
    // When the newest pointer message arrived: each state frame says how long ago, so the
    // latency bench can tell the server's share from the browser's and the socket's.
    std::chrono::steady_clock::time_point pointer_received_{};
    std::chrono::steady_clock::time_point effect_states_at_{};  // when last_effect_states_ was read
    nlohmann::json last_effect_states_ = nlohmann::json::array();
};

}  // namespace feel::studio
