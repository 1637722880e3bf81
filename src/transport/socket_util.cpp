#include "socket_util.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

namespace feel::transport::detail {

void UniqueFd::reset() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
}

WakeSignal::WakeSignal() {
    int fds[2] = {-1, -1};
    if (::pipe2(fds, O_NONBLOCK | O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe2");
    read_ = UniqueFd(fds[0]);
    write_ = UniqueFd(fds[1]);
}

void WakeSignal::raise() noexcept {
    const uint8_t byte = 1;
    // A full pipe is already readable: nothing more to do then.
    [[maybe_unused]] const ssize_t written = ::write(write_.get(), &byte, 1);
}

std::chrono::steady_clock::time_point deadline_after(std::chrono::milliseconds timeout) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point now = Clock::now();
    if (timeout.count() <= 0) return now;
    const auto room = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::time_point::max() - now);
    if (timeout >= room) return Clock::time_point::max();
    return now + timeout;
}

WaitResult wait_readable(int fd, const WakeSignal& wake, std::chrono::steady_clock::time_point deadline) {
    for (;;) {
        const auto now = std::chrono::steady_clock::now();
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
        const int timeout_ms = left.count() <= 0 ? 0 : static_cast<int>(std::min<int64_t>(left.count(), 1 << 30));
        pollfd fds[2] = {{wake.read_fd(), POLLIN, 0}, {fd, POLLIN, 0}};
        const int ready = ::poll(fds, 2, timeout_ms);
        if (ready < 0) {
            if (errno == EINTR) continue;
            throw std::system_error(errno, std::generic_category(), "poll");
        }
        if (fds[0].revents != 0) return WaitResult::woken;
        if (fds[1].revents != 0) return WaitResult::readable;
        if (timeout_ms == 0 || std::chrono::steady_clock::now() >= deadline) return WaitResult::timed_out;
    }
}

std::vector<uint8_t> encode_frame(const Frame& frame) {
    std::vector<uint8_t> bytes(kFrameHeaderBytes + frame.payload.size());
    const auto length = static_cast<uint16_t>(frame.payload.size());
    bytes[0] = static_cast<uint8_t>(frame.kind);
    bytes[1] = static_cast<uint8_t>(length & 0xFFu);
    bytes[2] = static_cast<uint8_t>(length >> 8);
    std::copy(frame.payload.begin(), frame.payload.end(), bytes.begin() + kFrameHeaderBytes);
    return bytes;
}

void FrameReader::append(const uint8_t* bytes, std::size_t count) {
    // Drop the frames already taken before growing, so the buffer never holds more than one
    // read's worth plus one partial frame.
    if (read_offset_ > 0) {
        buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(read_offset_));
        read_offset_ = 0;
    }
    buffer_.insert(buffer_.end(), bytes, bytes + count);
}

std::optional<Frame> FrameReader::next(const std::string& peer) {
    const std::size_t available = pending_bytes();
    if (available < kFrameHeaderBytes) return std::nullopt;
    const uint8_t* header = buffer_.data() + read_offset_;
    if (!is_frame_kind(header[0])) {
        throw TransportError(TransportError::Kind::bad_frame,
                             peer + " sent a frame of unknown kind " + std::to_string(header[0]) + " (allowed 1.." +
                                 std::to_string(kFrameKindCount) + "); the connection is closed");
    }
    const std::size_t length = static_cast<std::size_t>(header[1]) | (static_cast<std::size_t>(header[2]) << 8);
    if (length > kMaxFramePayload) {
        throw TransportError(TransportError::Kind::bad_frame,
                             peer + " sent a " + std::string(frame_kind_name(static_cast<FrameKind>(header[0]))) +
                                 " frame of " + std::to_string(length) + " bytes (allowed 0.." +
                                 std::to_string(kMaxFramePayload) + "); the connection is closed");
    }
    if (available < kFrameHeaderBytes + length) return std::nullopt;
    Frame frame;
    frame.kind = static_cast<FrameKind>(header[0]);
    frame.payload.assign(header + kFrameHeaderBytes, header + kFrameHeaderBytes + length);
    read_offset_ += kFrameHeaderBytes + length;
    return frame;
}

std::string errno_text(int error_number) { return std::generic_category().message(error_number); }

void set_blocking(int fd, bool blocking) {
    const int flags = ::fcntl(fd, F_GETFL, 0);
    if (flags < 0) throw std::system_error(errno, std::generic_category(), "fcntl(F_GETFL)");
    const int wanted = blocking ? (flags & ~O_NONBLOCK) : (flags | O_NONBLOCK);
    if (wanted != flags && ::fcntl(fd, F_SETFL, wanted) != 0)
        throw std::system_error(errno, std::generic_category(), "fcntl(F_SETFL)");
}

}  // namespace feel::transport::detail
