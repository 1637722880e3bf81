// feel::host — InputQueue: one input subscriber's bounded queue of state rounds.
//
// The producer is the device's I/O thread (DeviceCore, with its `mu` held); the consumers
// are InputSubscription's take() and wait() on any threads. The ring is allocated once, at
// subscription, so the I/O thread never allocates for it and a subscriber that stops
// reading costs a fixed amount of memory: when the ring is full the oldest round is
// overwritten and counted as dropped. Lock order: DeviceCore::mu, then InputQueue::mu;
// a consumer takes only InputQueue::mu.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <vector>

#include "feel/host/device.hpp"

namespace feel::host {

struct InputQueue {
    explicit InputQueue(size_t capacity) : ring(capacity) {}

    // The I/O thread: one more round (never blocks for long, never allocates).
    void push(const InputState& state) noexcept;
    // The device is gone: waiters return what is queued, then `disconnected`.
    void close() noexcept;
    // Moves everything queued into a batch, with the drops since the last one.
    InputBatch take_locked();

    mutable std::mutex mu;
    std::condition_variable cv;
    std::vector<InputState> ring;  // fixed size: the capacity
    size_t head = 0;               // index of the oldest queued round
    size_t count = 0;              // rounds queued
    uint64_t dropped = 0;          // since the last batch
    uint64_t dropped_total = 0;
    bool closed = false;
};

}  // namespace feel::host
