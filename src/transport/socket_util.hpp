// Pieces the stream transports share: an owned file descriptor, a wake-up signal for
// blocked waits, waiting with a deadline, and the frame codec of the byte stream.
//
// Why poll() under Boost.Asio: Asio sets the sockets up (resolving, binding, connecting with
// a timeout, accepting) but a Connection's contract is blocking calls with timeouts, callable
// from two threads at once (one sending, one receiving) and cancellable from a third by
// close(). Waiting in poll() on the socket and a wake pipe does exactly that with no
// io_context per call; close() never closes a descriptor another thread may be polling (that
// would race with descriptor reuse), it shuts the socket down and wakes the waiters, and the
// descriptor is closed by the destructor.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "feel/transport/transport.hpp"

namespace feel::transport::detail {

// Owns one file descriptor (-1: none).
class UniqueFd {
public:
    UniqueFd() = default;
    explicit UniqueFd(int fd) noexcept : fd_(fd) {}
    ~UniqueFd() { reset(); }
    UniqueFd(UniqueFd&& other) noexcept : fd_(other.release()) {}
    UniqueFd& operator=(UniqueFd&& other) noexcept {
        if (this != &other) {
            reset();
            fd_ = other.release();
        }
        return *this;
    }
    UniqueFd(const UniqueFd&) = delete;
    UniqueFd& operator=(const UniqueFd&) = delete;

    [[nodiscard]] int get() const noexcept { return fd_; }
    int release() noexcept {
        const int fd = fd_;
        fd_ = -1;
        return fd;
    }
    void reset() noexcept;

private:
    int fd_ = -1;
};

// A one-shot wake-up: once raised, its read end stays readable forever, so every present and
// future wait on it returns at once. Used for close().
class WakeSignal {
public:
    WakeSignal();  // throws std::system_error when no pipe can be made
    void raise() noexcept;
    [[nodiscard]] int read_fd() const noexcept { return read_.get(); }

private:
    UniqueFd read_;
    UniqueFd write_;
};

enum class WaitResult : uint8_t { readable, woken, timed_out };

// now + timeout, saturating: a caller's "wait for ever" (milliseconds::max()) must not
// overflow the clock into the past. A negative timeout is 0.
[[nodiscard]] std::chrono::steady_clock::time_point deadline_after(std::chrono::milliseconds timeout);

// Waits until `fd` is readable (data, end of stream, error, or a pending connection), the
// wake signal is raised (checked first), or the deadline passes. Retries on EINTR.
[[nodiscard]] WaitResult wait_readable(int fd, const WakeSignal& wake,
                                       std::chrono::steady_clock::time_point deadline);

// The byte stream's framing: [kind u8][length u16 LE][payload].
[[nodiscard]] std::vector<uint8_t> encode_frame(const Frame& frame);

// Reassembles frames from the bytes a stream delivers in arbitrary pieces. Validates each
// header as soon as its three bytes are there, so a hostile length is refused before any of
// its payload is waited for.
class FrameReader {
public:
    // Appends bytes received from the stream.
    void append(const uint8_t* bytes, std::size_t count);
    // The next whole frame, or nullopt when more bytes are needed. Throws
    // TransportError(bad_frame) naming `peer` for an unknown kind or an oversized length.
    [[nodiscard]] std::optional<Frame> next(const std::string& peer);
    // Bytes of an incomplete frame waiting for the rest.
    [[nodiscard]] std::size_t pending_bytes() const noexcept { return buffer_.size() - read_offset_; }

private:
    std::vector<uint8_t> buffer_;
    std::size_t read_offset_ = 0;  // bytes of buffer_ already taken as frames
};

// "Connection refused", from errno.
[[nodiscard]] std::string errno_text(int error_number);

// Sets or clears O_NONBLOCK. Throws std::system_error.
void set_blocking(int fd, bool blocking);

// Which end of a stream a connection is (stream_connection.cpp): the host's (made by
// connect(): sends wait while the socket is full) or the device's (made by a Listener:
// bounded buffers both ways, partial-frame and stall timeouts, the token check).
enum class StreamRole : uint8_t { host, device };

// A Connection over a connected stream socket (Unix or TCP). `peer` is what peer() says;
// `token` (device's end only) the secret the peer's first frame must carry (empty: none).
[[nodiscard]] std::unique_ptr<Connection> make_stream_connection(UniqueFd socket, std::string peer,
                                                                 StreamRole role, std::string token = {});

}  // namespace feel::transport::detail
