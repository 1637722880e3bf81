// The in-process transport: two queues between two ends of one process.
//
// It is what the tests and the default device (sim:PROFILE) use, so it keeps the stream
// transports' semantics exactly: frames arrive whole and in order; a closed end sees
// "disconnected" at once, its peer only after it has received every frame sent before the
// close (a USB unplug loses nothing already delivered to the host controller). A mutex and
// a condition variable are enough: this is never on the device's real-time loop. An end's
// reader may also have a doorbell rung when a frame arrives for it (doorbell.hpp): the
// simulated device's service thread sleeps on one that its loop rings too.
#include <condition_variable>
#include <deque>
#include <mutex>

#include "feel/transport/doorbell.hpp"
#include "feel/transport/transport.hpp"
#include "socket_util.hpp"

namespace feel::transport {
namespace {

struct SharedPair {
    std::mutex mutex;
    std::condition_variable arrived;  // a frame was queued or the pair was closed
    std::deque<Frame> to_host;
    std::deque<Frame> to_device;
    std::shared_ptr<Doorbell> host_bell;    // rung when a frame arrives for the host's end
    std::shared_ptr<Doorbell> device_bell;  // ... for the device's end
    bool closed = false;  // either end closed: no more sends, receivers drain then stop
};

class InProcessConnection final : public Connection, public BellOnArrival {
public:
    InProcessConnection(std::shared_ptr<SharedPair> shared, bool is_host, std::string name)
        : shared_(std::move(shared)), is_host_(is_host), name_(std::move(name)) {}
    ~InProcessConnection() override { close(); }

    InProcessConnection(const InProcessConnection&) = delete;
    InProcessConnection& operator=(const InProcessConnection&) = delete;

    void send(const Frame& frame) override {
        if (frame.payload.size() > kMaxFramePayload) {
            throw std::invalid_argument("a " + std::string(frame_kind_name(frame.kind)) + " frame of " +
                                        std::to_string(frame.payload.size()) + " bytes is too large for " +
                                        name_ + " (allowed 0.." + std::to_string(kMaxFramePayload) + " bytes)");
        }
        std::shared_ptr<Doorbell> bell;
        {
            std::lock_guard lock(shared_->mutex);
            if (shared_->closed) throw TransportError(TransportError::Kind::disconnected, name_ + " is closed");
            outbox().push_back(frame);
            bell = peer_bell();  // a copy: the reader may drop its bell meanwhile
        }
        shared_->arrived.notify_all();
        if (bell) bell->ring();
    }

    void ring_on_arrival(std::shared_ptr<Doorbell> bell) override {
        {
            std::lock_guard lock(shared_->mutex);
            own_bell() = bell;
        }
        if (bell) bell->ring();
    }

    std::optional<Frame> receive(std::chrono::milliseconds timeout) override {
        std::unique_lock lock(shared_->mutex);
        const auto ready = [&] { return closed_here_ || !inbox().empty() || shared_->closed; };
        if (!shared_->arrived.wait_until(lock, detail::deadline_after(timeout), ready)) return std::nullopt;
        if (closed_here_) throw TransportError(TransportError::Kind::disconnected, name_ + " was closed here");
        if (!inbox().empty()) {
            Frame frame = std::move(inbox().front());
            inbox().pop_front();
            return frame;
        }
        throw TransportError(TransportError::Kind::disconnected, name_ + ": the peer closed the connection");
    }

    void close() noexcept override {
        std::shared_ptr<Doorbell> bells[2];
        {
            std::lock_guard lock(shared_->mutex);
            closed_here_ = true;
            shared_->closed = true;
            inbox().clear();  // nobody will read them: this end is gone
            bells[0] = own_bell();
            bells[1] = peer_bell();
        }
        shared_->arrived.notify_all();
        for (const auto& b : bells) {
            if (b) b->ring();
        }
    }

    [[nodiscard]] std::string peer() const override { return name_; }

private:
    std::deque<Frame>& inbox() { return is_host_ ? shared_->to_host : shared_->to_device; }
    std::deque<Frame>& outbox() { return is_host_ ? shared_->to_device : shared_->to_host; }
    std::shared_ptr<Doorbell>& own_bell() { return is_host_ ? shared_->host_bell : shared_->device_bell; }
    std::shared_ptr<Doorbell>& peer_bell() { return is_host_ ? shared_->device_bell : shared_->host_bell; }

    std::shared_ptr<SharedPair> shared_;
    bool is_host_;
    std::string name_;
    bool closed_here_ = false;  // guarded by shared_->mutex
};

}  // namespace

ConnectionPair in_process_pair(std::string name) {
    auto shared = std::make_shared<SharedPair>();
    ConnectionPair pair;
    pair.host = std::make_unique<InProcessConnection>(shared, true, name);
    pair.device = std::make_unique<InProcessConnection>(shared, false, std::move(name));
    return pair;
}

}  // namespace feel::transport
