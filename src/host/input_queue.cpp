// Per-report input subscriptions (input_queue.hpp, Device::subscribe_input).
#include "input_queue.hpp"

#include <utility>

#include "device_core.hpp"

namespace feel::host {

void InputQueue::push(const InputState& state) noexcept {
    {
        std::lock_guard lock(mu);
        const size_t capacity = ring.size();
        if (count == capacity) {  // full: the oldest round makes room
            head = (head + 1) % capacity;
            --count;
            ++dropped;
            ++dropped_total;
        }
        ring[(head + count) % capacity] = state;
        ++count;
    }
    cv.notify_all();
}

void InputQueue::close() noexcept {
    {
        std::lock_guard lock(mu);
        closed = true;
    }
    cv.notify_all();
}

InputBatch InputQueue::take_locked() {
    InputBatch batch;
    batch.reports.reserve(count);
    for (size_t i = 0; i < count; ++i) batch.reports.push_back(ring[(head + i) % ring.size()]);
    head = (head + count) % ring.size();
    count = 0;
    batch.dropped = std::exchange(dropped, 0);
    return batch;
}

// --- InputSubscription ---------------------------------------------------------------------

InputSubscription::InputSubscription(InputSubscription&& other) noexcept
    : core_(std::move(other.core_)), queue_(std::move(other.queue_)) {}

InputSubscription& InputSubscription::operator=(InputSubscription&& other) noexcept {
    if (this != &other) {
        reset();
        core_ = std::move(other.core_);
        queue_ = std::move(other.queue_);
    }
    return *this;
}

InputSubscription::~InputSubscription() { reset(); }

void InputSubscription::reset() noexcept {
    if (queue_) {
        if (auto core = core_.lock()) core->unsubscribe_input(queue_.get());
    }
    queue_.reset();
    core_.reset();
}

InputBatch InputSubscription::take() {
    if (!queue_) return {};
    std::lock_guard lock(queue_->mu);
    return queue_->take_locked();
}

Result<InputBatch> InputSubscription::wait(std::chrono::milliseconds timeout) {
    if (!queue_) return Status::failure(ErrorKind::invalid_handle, "InputSubscription::wait: the subscription is empty");
    std::unique_lock lock(queue_->mu);
    queue_->cv.wait_for(lock, timeout, [&] { return queue_->count != 0 || queue_->closed; });
    if (queue_->count != 0) return queue_->take_locked();
    if (queue_->closed) {
        lock.unlock();
        if (auto core = core_.lock()) return core->disconnected_status("InputSubscription::wait");
        return Status::failure(ErrorKind::disconnected, "InputSubscription::wait: the device was closed");
    }
    return Status::failure(ErrorKind::timeout, "InputSubscription::wait: no state report within " +
                                                   std::to_string(timeout.count()) + " ms");
}

size_t InputSubscription::capacity() const noexcept { return queue_ ? queue_->ring.size() : 0; }

uint64_t InputSubscription::dropped_total() const {
    if (!queue_) return 0;
    std::lock_guard lock(queue_->mu);
    return queue_->dropped_total;
}

// --- DeviceCore's side ----------------------------------------------------------------------

void DeviceCore::publish_input_round() noexcept {
    for (const std::shared_ptr<InputQueue>& q : input_queues) q->push(input);
}

void DeviceCore::unsubscribe_input(const InputQueue* queue) noexcept {
    std::lock_guard lock(mu);
    std::erase_if(input_queues, [&](const std::shared_ptr<InputQueue>& q) { return q.get() == queue; });
}

Result<InputSubscription> Device::subscribe_input(size_t capacity) {
    if (!core_) return Status::failure(ErrorKind::invalid_handle, "subscribe_input: the Device is empty");
    if (capacity < 1 || capacity > kMaxInputQueue) {
        return Status::failure(ErrorKind::invalid_parameter,
                               "subscribe_input: capacity " + std::to_string(capacity) +
                                   " is out of range (allowed 1.." + std::to_string(kMaxInputQueue) + " rounds)");
    }
    auto queue = std::make_shared<InputQueue>(capacity);
    bool connected = false;
    {
        std::lock_guard lock(core_->mu);
        connected = core_->connected;
        if (connected) core_->input_queues.push_back(queue);
    }
    if (!connected) return core_->disconnected_status("subscribe_input");  // takes mu itself
    return InputSubscription(core_, std::move(queue));
}

}  // namespace feel::host
