// A Connection over a Linux hidraw node (feel/transport/hidraw.hpp): platform code, the only
// file that includes linux/hidraw.h.
//
// Design. Sends happen on the caller's thread: write() for an output report, an ioctl for a
// feature report. A get (feature or descriptor) is an ioctl too, answered at once; its reply
// goes into a small queue that receive() hands out before any input report, so that the
// host sees the reply as the next frame, as over feel's sockets. receive() waits in poll()
// on the node, the close signal and an eventfd that a queued reply raises. A read or write
// failing with ENODEV, EIO or EPIPE means the device is gone (unplugged, or its driver let
// go): the connection says so and is closed.
#include <fcntl.h>
#include <linux/hidraw.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <deque>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "feel/transport/hidraw.hpp"
#include "socket_util.hpp"

namespace feel::transport {
namespace {

using detail::errno_text;
using detail::UniqueFd;

// A descriptor's items: does it use Report IDs (HID 1.11 §6.2.2.7, tag 0x84)? A short
// walk of the item headers, enough to know whether hidraw's buffers carry the ID byte.
bool uses_report_ids(const std::vector<uint8_t>& d) {
    std::size_t i = 0;
    while (i < d.size()) {
        const uint8_t prefix = d[i];
        if (prefix == 0xFE) {  // long item: [0xFE][size][tag][data]
            if (i + 1 >= d.size()) return false;
            i += 3 + d[i + 1];
            continue;
        }
        static constexpr std::size_t kSizes[4] = {0, 1, 2, 4};
        if ((prefix & 0xFCu) == 0x84u) return true;
        i += 1 + kSizes[prefix & 3u];
    }
    return false;
}

// hidraw returns ENODEV once the device is unplugged (ESHUTDOWN while it goes). EPIPE is a
// stall: the device refused the request, and is still there.
bool is_gone(int error_number) { return error_number == ENODEV || error_number == ESHUTDOWN; }

class HidrawConnection final : public Connection {
public:
    HidrawConnection(UniqueFd fd, std::string peer, std::vector<uint8_t> descriptor)
        : fd_(std::move(fd)), peer_(std::move(peer)), descriptor_(std::move(descriptor)),
          numbered_(uses_report_ids(descriptor_)), replies_ready_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
        if (replies_ready_.get() < 0) throw std::runtime_error("hidraw " + peer_ + ": eventfd: " + errno_text(errno));
    }
    ~HidrawConnection() override { close(); }

    void send(const Frame& frame) override {
        if (frame.payload.size() > kMaxFramePayload)
            throw std::invalid_argument("frame payload of " + std::to_string(frame.payload.size()) + " bytes (allowed 0.." +
                                        std::to_string(kMaxFramePayload) + ")");
        std::lock_guard lock(send_mu_);
        check_open();
        switch (frame.kind) {
            case FrameKind::output_report: {
                std::vector<uint8_t> bytes = with_id(frame.payload);
                const ssize_t n = ::write(fd_.get(), bytes.data(), bytes.size());
                if (n < 0) fail_io("write of an output report");
                return;
            }
            case FrameKind::set_feature: {
                std::vector<uint8_t> bytes = with_id(frame.payload);
                if (::ioctl(fd_.get(), HIDIOCSFEATURE(bytes.size()), bytes.data()) < 0) fail_io("SET_REPORT(Feature)");
                return;
            }
            case FrameKind::get_feature: {
                std::vector<uint8_t> bytes(kMaxFramePayload, 0);
                bytes[0] = frame.payload.empty() ? 0 : frame.payload[0];
                const int n = ::ioctl(fd_.get(), HIDIOCGFEATURE(bytes.size()), bytes.data());
                if (n < 0) fail_io("GET_REPORT(Feature) of report " + std::to_string(bytes[0]));
                bytes.resize(static_cast<std::size_t>(n));
                if (!numbered_ && (bytes.empty() || bytes[0] != 0)) bytes.insert(bytes.begin(), 0);
                queue_reply(Frame{FrameKind::feature_reply, std::move(bytes)});
                return;
            }
            case FrameKind::get_descriptor:
                queue_reply(Frame{FrameKind::descriptor_reply, descriptor_});
                return;
            case FrameKind::hello:
                return;  // a hidraw device has no shared secret
            case FrameKind::input_report:
            case FrameKind::feature_reply:
            case FrameKind::descriptor_reply:
            case FrameKind::busy:
                break;
        }
        throw std::invalid_argument("a host does not send " + std::string(frame_kind_name(frame.kind)) + " frames to " +
                                    peer_);
    }

    std::optional<Frame> receive(std::chrono::milliseconds timeout) override {
        const auto deadline = detail::deadline_after(timeout);
        for (;;) {
            {
                std::lock_guard lock(replies_mu_);
                if (!replies_.empty()) {
                    Frame f = std::move(replies_.front());
                    replies_.pop_front();
                    return f;
                }
            }
            check_open();
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline -
                                                                                   std::chrono::steady_clock::now());
            pollfd fds[3] = {{fd_.get(), POLLIN, 0}, {wake_.read_fd(), POLLIN, 0}, {replies_ready_.get(), POLLIN, 0}};
            const int wait_ms = static_cast<int>(std::clamp<int64_t>(left.count(), 0, 1000));
            const int n = ::poll(fds, 3, wait_ms);
            if (n < 0 && errno != EINTR) fail_io("poll");
            if (fds[1].revents != 0 || closed_) throw_disconnected("the connection was closed");
            if (fds[2].revents != 0) {
                uint64_t count = 0;
                (void)::read(replies_ready_.get(), &count, sizeof count);
                continue;
            }
            if (fds[0].revents & (POLLERR | POLLHUP | POLLNVAL)) {
                closed_ = true;
                throw_disconnected("the device is gone (unplugged, or its driver released it)");
            }
            if (fds[0].revents & POLLIN) {
                std::vector<uint8_t> bytes(kMaxFramePayload + 1, 0);
                uint8_t* into = numbered_ ? bytes.data() : bytes.data() + 1;
                const ssize_t got = ::read(fd_.get(), into, numbered_ ? kMaxFramePayload : kMaxFramePayload - 1);
                if (got < 0) {
                    if (errno == EAGAIN || errno == EINTR) continue;
                    fail_io("read of an input report");
                }
                bytes.resize(static_cast<std::size_t>(got) + (numbered_ ? 0 : 1));
                return Frame{FrameKind::input_report, std::move(bytes)};
            }
            if (n == 0 && std::chrono::steady_clock::now() >= deadline) return std::nullopt;
        }
    }

    void close() noexcept override {
        closed_ = true;
        wake_.raise();
    }

    [[nodiscard]] std::string peer() const override { return peer_; }

private:
    // hidraw's buffers start with the report number, 0 for an unnumbered device: feel's
    // frames do too, so the bytes pass unchanged.
    static std::vector<uint8_t> with_id(const std::vector<uint8_t>& payload) {
        if (payload.empty()) return {0};
        return payload;
    }

    void check_open() {
        if (!closed_) return;
        std::string why;
        {
            std::lock_guard lock(replies_mu_);
            why = gone_reason_.empty() ? "the connection was closed" : gone_reason_;
        }
        throw_disconnected(why);
    }

    [[noreturn]] void throw_disconnected(const std::string& why) const {
        throw TransportError(TransportError::Kind::disconnected, peer_ + ": " + why);
    }

    [[noreturn]] void fail_io(const std::string& what) {
        const int error_number = errno;
        if (is_gone(error_number)) {
            const std::string why = "the device is gone (" + what + ": " + errno_text(error_number) + ")";
            {
                std::lock_guard lock(replies_mu_);
                gone_reason_ = why;
            }
            closed_ = true;
            wake_.raise();
            throw_disconnected(why);
        }
        // Not gone: the device refused this one request (a stall, EPIPE) or the kernel did
        // (a timeout). The connection stays open; the caller gets the reason.
        throw std::runtime_error(peer_ + ": " + what + " failed: " + errno_text(error_number) +
                                 (error_number == EPIPE ? " (the device stalled the request: it refused it)" : ""));
    }

    void queue_reply(Frame frame) {
        {
            std::lock_guard lock(replies_mu_);
            replies_.push_back(std::move(frame));
        }
        const uint64_t one = 1;
        (void)::write(replies_ready_.get(), &one, sizeof one);
    }

    UniqueFd fd_;
    std::string peer_;
    std::vector<uint8_t> descriptor_;
    bool numbered_;
    UniqueFd replies_ready_;
    detail::WakeSignal wake_;
    std::mutex send_mu_;
    std::mutex replies_mu_;
    std::deque<Frame> replies_;  // at most one per get the host sent
    std::atomic<bool> closed_{false};
    std::string gone_reason_;  // guarded by replies_mu_
};

// The USB IDs of a node, from sysfs, for the permission message.
const HidrawNode* node_info(const std::vector<HidrawNode>& nodes, const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    for (const HidrawNode& n : nodes)
        if (std::filesystem::path(n.node).filename().string() == name) return &n;
    return nullptr;
}

}  // namespace

std::unique_ptr<Connection> open_hidraw(const Address& address, const HidrawRoots& roots) {
    std::string path;
    if (address.kind == Address::Kind::hidraw) path = address.path;
    else if (address.kind == Address::Kind::usb) path = find_usb_node(address, roots);
    else throw std::invalid_argument("open_hidraw: " + address.to_string() + " is not a hidraw: or usb: address");
    const std::string name = address.to_string();

    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        const int error_number = errno;
        if (error_number == EACCES || error_number == EPERM) {
            const std::vector<HidrawNode> nodes = list_hidraw_nodes(roots);
            const HidrawNode* info = node_info(nodes, path);
            const uint16_t vid = info ? info->vendor_id : 0;
            const uint16_t pid = info ? info->product_id : 0;
            throw TransportError(TransportError::Kind::refused,
                                 "cannot open " + path + " (" + name + "): permission denied. Give your user access "
                                 "with a udev rule: put the line\n  " + hidraw_udev_rule(vid, pid) +
                                 "\ninto /etc/udev/rules.d/70-feel-hidraw.rules, then run `sudo udevadm control "
                                 "--reload && sudo udevadm trigger` and plug the device in again "
                                 "(docs/real-devices.md, \"hidraw permissions\")");
        }
        if (error_number == ENOENT || error_number == ENODEV || error_number == ENXIO) {
            throw TransportError(TransportError::Kind::refused,
                                 "cannot open " + path + " (" + name + "): no such device (unplugged? `feel devices` lists "
                                 "the force-feedback devices present)");
        }
        throw TransportError(TransportError::Kind::refused, "cannot open " + path + ": " + errno_text(error_number));
    }
    UniqueFd owned(fd);
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) {
        throw TransportError(TransportError::Kind::refused, "cannot open " + path + ": not a hidraw device node");
    }
    int size = 0;
    if (::ioctl(fd, HIDIOCGRDESCSIZE, &size) < 0) {
        throw TransportError(TransportError::Kind::refused,
                             "cannot open " + path + ": not a hidraw device node (HIDIOCGRDESCSIZE: " +
                                 errno_text(errno) + ")");
    }
    hidraw_report_descriptor descriptor{};
    descriptor.size = static_cast<uint32_t>(std::clamp(size, 0, HID_MAX_DESCRIPTOR_SIZE));
    if (::ioctl(fd, HIDIOCGRDESC, &descriptor) < 0) {
        throw TransportError(TransportError::Kind::refused,
                             "cannot read the report descriptor of " + path + ": " + errno_text(errno));
    }
    std::vector<uint8_t> bytes(descriptor.value, descriptor.value + descriptor.size);
    return std::make_unique<HidrawConnection>(std::move(owned), name == "hidraw:" + path ? name : name + " (" + path + ")",
                                              std::move(bytes));
}

}  // namespace feel::transport
