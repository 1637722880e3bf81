// feel::runtime — a lock-free single-producer/single-consumer ring.
//
// Commands enter the device's real-time loop through one of these and reports leave it
// through another (issue 5, §4). Exactly one thread pushes and exactly one thread pops;
// under that rule neither side ever waits for the other, takes a lock, allocates or makes a
// system call, so both ends are real-time safe.
//
// Design (the classic Lamport ring, with Rigtorp's cached indices):
//  - `tail_` counts the elements ever pushed and is written only by the producer; `head_`
//    counts the elements ever popped and is written only by the consumer. Both grow without
//    bound (64-bit: they cannot wrap in the life of any device) and the slot of element k is
//    k & mask_, with a power-of-two buffer of at least `capacity` slots. tail_ - head_ is the
//    number of elements held, so the queue holds exactly `capacity` elements when full,
//    whatever the capacity; no slot is sacrificed to tell full from empty.
//  - The producer writes the slot, then publishes it with a release store of tail_; the
//    consumer reads tail_ with acquire before it reads the slot. Symmetrically the consumer
//    releases a slot with a release store of head_ after reading it, and the producer
//    acquires head_ before reusing the slot. Those two pairs are the whole synchronization.
//  - Each side keeps a private copy of the other side's index and reloads the shared one
//    only when its copy says full (producer) or empty (consumer). In steady flow this keeps
//    each index's cache line in its owner's cache instead of bouncing on every call.
//  - The producer's fields and the consumer's fields sit on separate cache lines
//    (kCacheLineBytes apart), so the two threads never falsely share a line.
//
// T must be trivially copyable: elements are copied in and out by value, never constructed
// or destroyed, so a push or pop can never throw or allocate. All memory is allocated in
// the constructor; nothing allocates afterwards.
#pragma once

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace feel::runtime {

// The line size that separates the producer's and the consumer's fields, bytes. 64 on
// x86-64 and most ARM cores; a constant rather than std::hardware_destructive_interference_size,
// whose value may differ between translation units built with different flags.
inline constexpr std::size_t kCacheLineBytes = 64;

template <typename T>
class SpscQueue {
    static_assert(std::is_trivially_copyable_v<T>, "SpscQueue holds trivially copyable elements only");

public:
    // The largest capacity accepted, elements.
    static constexpr std::size_t kMaxCapacity = std::size_t{1} << 30;

    // Allocates room for exactly `capacity` elements, 1..kMaxCapacity. Throws
    // std::invalid_argument for a capacity outside that range, std::bad_alloc if the memory
    // is not there. Not real-time safe (it allocates); everything else is.
    explicit SpscQueue(std::size_t capacity)
        : capacity_(checked(capacity)),
          mask_(std::bit_ceil(capacity_) - 1),
          slots_(static_cast<T*>(::operator new((mask_ + 1) * sizeof(T), std::align_val_t{alignof(T)}))) {}

    ~SpscQueue() { ::operator delete(slots_, std::align_val_t{alignof(T)}); }
    SpscQueue(const SpscQueue&) = delete;
    SpscQueue& operator=(const SpscQueue&) = delete;

    // PRODUCER only. Copies `value` in and returns true, or returns false and changes
    // nothing when the queue is full. Real-time safe: no lock, no allocation, no wait.
    [[nodiscard]] bool try_push(const T& value) noexcept {
        const uint64_t tail = producer_.tail.load(std::memory_order_relaxed);
        if (tail - producer_.cached_head >= capacity_) {
            producer_.cached_head = consumer_.head.load(std::memory_order_acquire);
            if (tail - producer_.cached_head >= capacity_) return false;
        }
        ::new (static_cast<void*>(slots_ + (tail & mask_))) T(value);
        producer_.tail.store(tail + 1, std::memory_order_release);
        return true;
    }

    // CONSUMER only. Copies the oldest element into `out` and returns true, or returns
    // false and leaves `out` alone when the queue is empty. Real-time safe.
    [[nodiscard]] bool try_pop(T& out) noexcept {
        const uint64_t head = consumer_.head.load(std::memory_order_relaxed);
        if (head == consumer_.cached_tail) {
            consumer_.cached_tail = producer_.tail.load(std::memory_order_acquire);
            if (head == consumer_.cached_tail) return false;
        }
        out = *std::launder(slots_ + (head & mask_));
        consumer_.head.store(head + 1, std::memory_order_release);
        return true;
    }

    // Any thread. The number of elements held at some moment during the call: exact when
    // neither side is active, otherwise a value the queue really had recently.
    [[nodiscard]] std::size_t size_approx() const noexcept {
        const uint64_t head = consumer_.head.load(std::memory_order_acquire);
        const uint64_t tail = producer_.tail.load(std::memory_order_acquire);
        // head is read first and both only grow, so tail >= head; pops and pushes landing
        // between the two loads can make the difference exceed the capacity, hence the clamp.
        const uint64_t held = tail - head;
        return static_cast<std::size_t>(held > capacity_ ? capacity_ : held);
    }

    // Any thread: the fixed capacity, elements.
    [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }

private:
    static std::size_t checked(std::size_t capacity) {
        if (capacity == 0 || capacity > kMaxCapacity) {
            throw std::invalid_argument("SpscQueue capacity = " + std::to_string(capacity) +
                                        " is out of range (allowed 1.." + std::to_string(kMaxCapacity) +
                                        " elements)");
        }
        return capacity;
    }

    // Written by the producer only (cached_head is private to it).
    struct alignas(kCacheLineBytes) ProducerSide {
        std::atomic<uint64_t> tail{0};  // elements ever pushed
        uint64_t cached_head = 0;       // the producer's last view of head
    };
    // Written by the consumer only (cached_tail is private to it).
    struct alignas(kCacheLineBytes) ConsumerSide {
        std::atomic<uint64_t> head{0};  // elements ever popped
        uint64_t cached_tail = 0;       // the consumer's last view of tail
    };

    // Read-only after construction, shared by both sides on a line of their own.
    alignas(kCacheLineBytes) const std::size_t capacity_;
    const std::size_t mask_;  // buffer slots - 1, buffer slots a power of two >= capacity_
    T* const slots_;
    ProducerSide producer_;
    ConsumerSide consumer_;
};

}  // namespace feel::runtime
