// A Connection over a connected stream socket (Unix domain or TCP).
//
// Sending writes the frame's header and payload with one blocking send loop under a mutex,
// so frames from two sending threads never interleave; MSG_NOSIGNAL turns a vanished peer
// into EPIPE (TransportError disconnected) instead of SIGPIPE killing the process.
// Receiving reads whatever the socket has (non-blocking recv after poll) into a FrameReader
// that reassembles frames across reads; the frames already buffered are handed out before
// the end of the stream is reported, so a peer's last frames are never lost to its close.
#include <sys/socket.h>

#include <atomic>
#include <cerrno>
#include <mutex>

#include "socket_util.hpp"

namespace feel::transport::detail {
namespace {

class StreamConnection final : public Connection {
public:
    StreamConnection(UniqueFd socket, std::string peer) : socket_(std::move(socket)), peer_(std::move(peer)) {
        set_blocking(socket_.get(), true);
    }
    ~StreamConnection() override { close(); }

    StreamConnection(const StreamConnection&) = delete;
    StreamConnection& operator=(const StreamConnection&) = delete;

    void send(const Frame& frame) override {
        if (frame.payload.size() > kMaxFramePayload) {
            throw std::invalid_argument("a " + std::string(frame_kind_name(frame.kind)) + " frame of " +
                                        std::to_string(frame.payload.size()) + " bytes is too large for " + peer_ +
                                        " (allowed 0.." + std::to_string(kMaxFramePayload) + " bytes)");
        }
        const std::vector<uint8_t> bytes = encode_frame(frame);
        std::lock_guard lock(send_mutex_);
        std::size_t sent = 0;
        while (sent < bytes.size()) {
            if (closed_.load(std::memory_order_acquire))
                throw TransportError(TransportError::Kind::disconnected, peer_ + " was closed here");
            const ssize_t n = ::send(socket_.get(), bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n < 0) {
                if (errno == EINTR) continue;
                throw TransportError(TransportError::Kind::disconnected,
                                     peer_ + " is disconnected (" + errno_text(errno) + ")");
            }
            sent += static_cast<std::size_t>(n);
        }
    }

    std::optional<Frame> receive(std::chrono::milliseconds timeout) override {
        const auto deadline = deadline_after(timeout);
        for (;;) {
            if (closed_.load(std::memory_order_acquire))
                throw TransportError(TransportError::Kind::disconnected, peer_ + " was closed here");
            if (auto frame = take_buffered()) return frame;
            if (peer_closed_) {
                if (reader_.pending_bytes() > 0) {
                    throw TransportError(TransportError::Kind::disconnected,
                                         peer_ + " closed the connection in the middle of a frame (" +
                                             std::to_string(reader_.pending_bytes()) + " bytes of it came)");
                }
                throw TransportError(TransportError::Kind::disconnected, peer_ + " closed the connection");
            }
            switch (wait_readable(socket_.get(), wake_, deadline)) {
                case WaitResult::woken:
                    continue;  // closed_ is set: the loop's first line reports it
                case WaitResult::timed_out:
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
    std::optional<Frame> take_buffered() {
        try {
            return reader_.next(peer_);
        } catch (const TransportError&) {
            close();  // a protocol violation: never read another byte from this peer
            throw;
        }
    }

    void read_available() {
        uint8_t chunk[16384];
        for (;;) {
            const ssize_t n = ::recv(socket_.get(), chunk, sizeof chunk, MSG_DONTWAIT);
            if (n > 0) {
                reader_.append(chunk, static_cast<std::size_t>(n));
                if (static_cast<std::size_t>(n) < sizeof chunk) return;
                continue;
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
    WakeSignal wake_;
    std::atomic<bool> closed_{false};
    std::mutex send_mutex_;
    // Receiving thread only.
    FrameReader reader_;
    bool peer_closed_ = false;
};

}  // namespace

std::unique_ptr<Connection> make_stream_connection(UniqueFd socket, std::string peer) {
    return std::make_unique<StreamConnection>(std::move(socket), std::move(peer));
}

}  // namespace feel::transport::detail
