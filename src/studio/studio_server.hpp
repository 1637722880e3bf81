// feel::studio — `feel studio`: the Studio's web server.
//
// Boost.Beast over Asio, one I/O thread. Plain HTTP serves the front end (embedded in the
// binary) and the workspace's files (POST /api/...: JSON in, JSON out); a WebSocket at
// /live carries one browser's live session (live_session.hpp) and its state frames at
// 60 Hz. docs/studio.md describes the protocol and the safety rules; request_guard.hpp
// and workspace.hpp enforce them.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace feel::studio {

struct StudioOptions {
    std::filesystem::path workspace = ".";
    std::string device = "sim:iforce2";  // everything `feel play --device` takes
    std::string listen = "127.0.0.1";    // an IP address to listen on
    uint16_t port = 8750;                // 0: any free port (tests)
    std::string grip = "firm";           // the simulated hand at the start
};

// Bounds (docs/studio.md, "Safety").
inline constexpr size_t kMaxHttpBodyBytes = 3u << 20;     // a JSON request with a 1 MiB file in it
inline constexpr size_t kMaxWebSocketMessageBytes = 1536u << 10;  // an import_file with a 1 MiB file (base64) in it
inline constexpr size_t kMaxQueuedFrames = 64;             // per browser; state frames are skipped past 4
// State frames: 60 a second, and one more as soon as the device reports the force change
// of the newest pointer message: while one is awaited (a pointer message in the last
// kInteractiveWindow, its force not yet shown) the server polls the device every kLivePoll,
// so a pointer move's force is not held back by the frame timer; these answers are at
// most kLiveFrameHz a second, on top of the 60. Only the answer goes early: every frame costs the browser's processes CPU, on
// a machine they share with the device (docs/studio.md, "Latency").
inline constexpr int kStateFrameHz = 60;
inline constexpr int kLiveFrameHz = 250;
// At rest (no frame has news for the page: live_session.hpp) a frame goes out this often.
inline constexpr int kKeepAliveFrameHz = 10;
inline constexpr std::chrono::milliseconds kInteractiveWindow{500};
inline constexpr std::chrono::milliseconds kLivePoll{1};  // the device reports every tick (1 kHz)

class StudioServer {
public:
    // Opens the workspace and the device and binds the port. Throws std::runtime_error
    // (WorkspaceError, a device error, an address in use) with a sentence for the user.
    explicit StudioServer(const StudioOptions& options);
    ~StudioServer();  // stop()
    StudioServer(const StudioServer&) = delete;
    StudioServer& operator=(const StudioServer&) = delete;

    // Serves on a thread of its own until stop().
    void start();
    void stop();

    [[nodiscard]] uint16_t port() const noexcept;
    // "http://127.0.0.1:8750/"
    [[nodiscard]] std::string url() const;
    // Whether the server listens on a loopback address (a warning is due otherwise).
    [[nodiscard]] bool loopback() const noexcept;
    // Browser sessions open now.
    [[nodiscard]] int sessions() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace feel::studio
