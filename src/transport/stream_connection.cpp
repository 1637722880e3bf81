// A Connection over a connected stream socket (Unix domain or TCP).
//
// Two roles. The host's end (made by connect()) sends with back-pressure: a send waits while
// the device's socket is full, as a USB host waits for its device. The device's end (made
// by a Listener) must never be held by its peer (transport.hpp), so:
//
//   * Receiving reads at most one chunk from the socket per wait, and only when no whole
//     frame is buffered: what a flooding peer sends stays in the socket, whose buffer fills
//     and pushes back on the peer. The FrameReader so holds at most one partial frame and
//     one chunk (kMaxBufferedInputBytes).
//   * A partial frame has kPartialFrameTimeout to become whole, counted from its first
//     bytes. Before declaring it late the socket is read once more, so a caller that did not
//     call receive() for a while (its inbox was full) never blames its peer for the pause.
//   * Sending never blocks: the bytes the socket does not take at once wait in an outgoing
//     buffer of at most kMaxOutgoingBytes, flushed by every send and every receive. A peer
//     that lets it overflow, or takes none of it for kSendStallTimeout, is not reading: the
//     connection is closed. send_or_drop() drops a frame while anything waits, so the
//     frames that matter (answers) are not stuck behind ones that do not (state reports).
//   * With a token, the first frame must be a `hello` carrying it (compared in constant
//     time); a hello is the transport's own and never reaches the caller.
//
// Sends are serialized by a mutex, so frames from two sending threads never interleave;
// MSG_NOSIGNAL turns a vanished peer into EPIPE (TransportError disconnected) instead of
// SIGPIPE killing the process. The frames already buffered are handed out before the end of
// the stream is reported, so a peer's last frames are never lost to its close.
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <mutex>

#include "socket_util.hpp"

namespace feel::transport::detail {
namespace {

using Clock = std::chrono::steady_clock;

// Compares without an early exit, so that the time taken does not tell how much matched.
bool same_secret(const std::vector<uint8_t>& presented, const std::string& token) {
    uint8_t difference = presented.size() == token.size() ? 0 : 1;
    const std::size_t n = std::max(presented.size(), token.size());
    for (std::size_t i = 0; i < n; ++i) {
        const uint8_t a = i < presented.size() ? presented[i] : 0;
        const uint8_t b = i < token.size() ? static_cast<uint8_t>(token[i]) : 0;
        difference = static_cast<uint8_t>(difference | (a ^ b));
    }
    return difference == 0;
}

class StreamConnection final : public Connection {
public:
    StreamConnection(UniqueFd socket, std::string peer, StreamRole role, std::string token)
        : socket_(std::move(socket)), peer_(std::move(peer)), role_(role), token_(std::move(token)) {
        set_blocking(socket_.get(), true);
    }
    ~StreamConnection() override { close(); }

    StreamConnection(const StreamConnection&) = delete;
    StreamConnection& operator=(const StreamConnection&) = delete;

    void send(const Frame& frame) override {
        const std::vector<uint8_t> bytes = checked_encode(frame);
        std::lock_guard lock(send_mutex_);
        if (role_ == StreamRole::host) {
            send_blocking(bytes);
            return;
        }
        flush_locked();
        queue_locked(bytes);
    }

    bool send_or_drop(const Frame& frame) override {
        if (role_ == StreamRole::host) {
            send(frame);
            return true;
        }
        const std::vector<uint8_t> bytes = checked_encode(frame);
        std::lock_guard lock(send_mutex_);
        flush_locked();
        if (waiting_bytes() > 0) return false;
        queue_locked(bytes);
        return true;
    }

    std::optional<Frame> receive(std::chrono::milliseconds timeout) override {
        const auto deadline = deadline_after(timeout);
        for (;;) {
            if (closed_.load(std::memory_order_acquire))
                throw TransportError(TransportError::Kind::disconnected, peer_ + " was closed here");
            flush_if_free();
            if (auto frame = take_buffered()) return frame;
            if (peer_closed_) {
                if (reader_.pending_bytes() > 0) {
                    throw TransportError(TransportError::Kind::disconnected,
                                         peer_ + " closed the connection in the middle of a frame (" +
                                             std::to_string(reader_.pending_bytes()) + " bytes of it came)");
                }
                throw TransportError(TransportError::Kind::disconnected, peer_ + " closed the connection");
            }
            if (partial_since_ && Clock::now() - *partial_since_ >= kPartialFrameTimeout) {
                read_available();  // the rest may be waiting in the socket: a pause here is not the peer's
                if (auto frame = take_buffered()) return frame;
                if (!peer_closed_) fail_partial_frame();
                continue;
            }
            auto wait_until = deadline;
            if (partial_since_) wait_until = std::min(wait_until, *partial_since_ + kPartialFrameTimeout);
            switch (wait_readable(socket_.get(), wake_, wait_until)) {
                case WaitResult::woken:
                    continue;  // closed_ is set: the loop's first line reports it
                case WaitResult::timed_out:
                    if (partial_since_ && Clock::now() - *partial_since_ >= kPartialFrameTimeout) continue;
                    return std::nullopt;
                case WaitResult::readable:
                    read_available();
                    break;
            }
        }
    }

    void close() noexcept override {
        if (closed_.exchange(true, std::memory_order_acq_rel)) return;
        // Shut down, do not close: another thread may be inside poll() or send() on this
        // descriptor. Both return now; the destructor closes it.
        ::shutdown(socket_.get(), SHUT_RDWR);
        wake_.raise();
    }

    [[nodiscard]] std::string peer() const override { return peer_; }

private:
    std::vector<uint8_t> checked_encode(const Frame& frame) const {
        if (frame.payload.size() > kMaxFramePayload) {
            throw std::invalid_argument("a " + std::string(frame_kind_name(frame.kind)) + " frame of " +
                                        std::to_string(frame.payload.size()) + " bytes is too large for " + peer_ +
                                        " (allowed 0.." + std::to_string(kMaxFramePayload) + " bytes)");
        }
        return encode_frame(frame);
    }

    void throw_if_closed() const {
        if (closed_.load(std::memory_order_acquire))
            throw TransportError(TransportError::Kind::disconnected, peer_ + " was closed here");
    }

    [[noreturn]] void fail_disconnected(int error_number) {
        throw TransportError(TransportError::Kind::disconnected,
                             peer_ + " is disconnected (" + errno_text(error_number) + ")");
    }

    void send_blocking(const std::vector<uint8_t>& bytes) {
        std::size_t sent = 0;
        while (sent < bytes.size()) {
            throw_if_closed();
            const ssize_t n = ::send(socket_.get(), bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n < 0) {
                if (errno == EINTR) continue;
                fail_disconnected(errno);
            }
            sent += static_cast<std::size_t>(n);
        }
    }

    [[nodiscard]] std::size_t waiting_bytes() const noexcept { return outgoing_.size() - outgoing_offset_; }

    // Writes what the socket takes now; returns the bytes written. send_mutex_ held.
    std::size_t write_now(const uint8_t* bytes, std::size_t count) {
        std::size_t written = 0;
        while (written < count) {
            const ssize_t n = ::send(socket_.get(), bytes + written, count - written, MSG_NOSIGNAL | MSG_DONTWAIT);
            if (n < 0) {
                if (errno == EINTR) continue;
                if (errno == EAGAIN || errno == EWOULDBLOCK) break;
                fail_disconnected(errno);
            }
            written += static_cast<std::size_t>(n);
        }
        return written;
    }

    // Hands the socket what waits; a peer that took nothing for kSendStallTimeout is not
    // reading. send_mutex_ held.
    void flush_locked() {
        throw_if_closed();
        if (waiting_bytes() == 0) return;
        const std::size_t written = write_now(outgoing_.data() + outgoing_offset_, waiting_bytes());
        const Clock::time_point now = Clock::now();
        if (written > 0) {
            outgoing_offset_ += written;
            progress_at_ = now;
            if (waiting_bytes() == 0) {
                outgoing_.clear();
                outgoing_offset_ = 0;
            }
            return;
        }
        if (now - progress_at_ >= kSendStallTimeout) {
            fail_not_reading("took none of the " + std::to_string(waiting_bytes()) + " bytes waiting for it in " +
                             std::to_string(kSendStallTimeout.count()) + " ms");
        }
    }

    // Sends `bytes` after what waits, keeping what the socket does not take. send_mutex_ held.
    void queue_locked(const std::vector<uint8_t>& bytes) {
        std::size_t written = 0;
        if (waiting_bytes() == 0) {
            written = write_now(bytes.data(), bytes.size());
            if (written == bytes.size()) return;
            progress_at_ = Clock::now();  // the stall clock starts with the first byte that waits
        }
        const std::size_t rest = bytes.size() - written;
        if (waiting_bytes() + rest > kMaxOutgoingBytes) {
            fail_not_reading("let " + std::to_string(waiting_bytes() + rest) + " bytes pile up (allowed " +
                             std::to_string(kMaxOutgoingBytes) + ")");
        }
        if (outgoing_offset_ > 0) {
            outgoing_.erase(outgoing_.begin(), outgoing_.begin() + static_cast<std::ptrdiff_t>(outgoing_offset_));
            outgoing_offset_ = 0;
        }
        outgoing_.insert(outgoing_.end(), bytes.begin() + static_cast<std::ptrdiff_t>(written), bytes.end());
    }

    [[noreturn]] void fail_not_reading(const std::string& what) {
        close();
        throw TransportError(TransportError::Kind::disconnected,
                             peer_ + " does not read what is sent to it: it " + what + "; the connection is closed");
    }

    // The receiving thread flushes too (a device's service thread, which also sends, or a
    // host's I/O thread), unless a sender holds the lock right now.
    void flush_if_free() {
        if (role_ == StreamRole::host) return;
        std::unique_lock lock(send_mutex_, std::try_to_lock);
        if (lock.owns_lock()) flush_locked();
    }

    [[noreturn]] void fail_partial_frame() {
        const std::size_t pending = reader_.pending_bytes();
        close();
        throw TransportError(TransportError::Kind::bad_frame,
                             peer_ + " sent " + std::to_string(pending) + " bytes of a frame and not the rest within " +
                                 std::to_string(kPartialFrameTimeout.count()) + " ms; the connection is closed");
    }

    // The next frame for the caller: hellos are taken here (the device's end checks the
    // token), and a partial frame's clock is kept.
    std::optional<Frame> take_buffered() {
        try {
            for (;;) {
                std::optional<Frame> frame = reader_.next(peer_);
                if (!frame) {
                    if (reader_.pending_bytes() == 0) partial_since_.reset();
                    else if (!partial_since_) partial_since_ = Clock::now();
                    return std::nullopt;
                }
                partial_since_.reset();
                if (role_ == StreamRole::host) return frame;
                if (frame->kind == FrameKind::hello) {
                    if (!token_.empty() && !authenticated_) {
                        if (!same_secret(frame->payload, token_)) {
                            throw TransportError(TransportError::Kind::bad_frame,
                                                 peer_ + " presented a wrong token; the connection is closed");
                        }
                        authenticated_ = true;
                    }
                    continue;  // a device without a secret, or one already satisfied, ignores it
                }
                if (!token_.empty() && !authenticated_) {
                    throw TransportError(TransportError::Kind::bad_frame,
                                         peer_ + " sent a " + std::string(frame_kind_name(frame->kind)) +
                                             " frame before presenting the device's token (a hello frame); the "
                                             "connection is closed");
                }
                return frame;
            }
        } catch (const TransportError&) {
            close();  // a protocol violation: never read another byte from this peer
            throw;
        }
    }

    // One read, of at most one chunk: the rest waits in the socket (back-pressure).
    void read_available() {
        uint8_t chunk[kReceiveChunkBytes];
        for (;;) {
            const ssize_t n = ::recv(socket_.get(), chunk, sizeof chunk, MSG_DONTWAIT);
            if (n > 0) {
                reader_.append(chunk, static_cast<std::size_t>(n));
                return;
            }
            if (n == 0) {
                peer_closed_ = true;
                return;
            }
            if (errno == EINTR) continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK) return;
            // ECONNRESET and the like: the peer is gone as surely as with an orderly close.
            peer_closed_ = true;
            return;
        }
    }

    UniqueFd socket_;
    std::string peer_;
    StreamRole role_;
    std::string token_;  // device's end: the secret a hello must carry (empty: none)
    WakeSignal wake_;
    std::atomic<bool> closed_{false};
    // Sending, under send_mutex_ (device's end): the bytes waiting for the peer from
    // outgoing_offset_ on, and when the peer last took some.
    std::mutex send_mutex_;
    std::vector<uint8_t> outgoing_;
    std::size_t outgoing_offset_ = 0;
    Clock::time_point progress_at_{};
    // Receiving thread only.
    FrameReader reader_;
    bool peer_closed_ = false;
    bool authenticated_ = false;
    std::optional<Clock::time_point> partial_since_;  // when the buffered partial frame began
};

}  // namespace

std::unique_ptr<Connection> make_stream_connection(UniqueFd socket, std::string peer, StreamRole role,
                                                   std::string token) {
    return std::make_unique<StreamConnection>(std::move(socket), std::move(peer), role, std::move(token));
}

}  // namespace feel::transport::detail
