// feel::transport — a doorbell: one thread sleeps on it, any thread rings it.
//
// The device's service thread (peripheral.cpp) serves two sources: the host's frames
// arriving on its connection, and the reports the device's real-time loop posts to the
// runtime's queue. It used to sleep in the connection's receive() with a 1 ms timeout, so
// a report posted just after it fell asleep waited up to 1 ms to leave (docs/studio.md,
// "Latency"). With a doorbell it sleeps on one futex word that both sources ring: a
// connection that can ring on arrival (BellOnArrival: the in-process one) rings it when a
// frame comes, and the loop rings it after a tick that left reports.
//
// The loop may ring it because ring() is real-time safe: one atomic add, and only when
// the waiter is asleep a FUTEX_WAKE system call, which never blocks, locks a user-space
// lock or allocates (the kernel takes its hash bucket's spinlock for the wake-up). Rings
// are counted, not queued: a ring between the waiter's reading of rings() and its wait()
// makes the wait return at once, so none is lost. Linux only (a futex).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>

namespace feel::transport {

class Doorbell {
public:
    // Any thread, any time, the device's real-time loop included: never blocks, locks or
    // allocates.
    void ring() noexcept;
    // The rings so far: read it before looking at the sources, then wait() with it.
    [[nodiscard]] uint32_t rings() const noexcept { return rings_.load(std::memory_order_seq_cst); }
    // The one waiting thread: returns once rings() differs from `seen`, or after `timeout`
    // (or spuriously, early: the caller looks at its sources again either way).
    void wait(uint32_t seen, std::chrono::microseconds timeout) noexcept;

private:
    std::atomic<uint32_t> rings_{0};       // the futex word
    std::atomic<uint32_t> sleeping_{0};    // 1 while the waiter may be in FUTEX_WAIT
};

// A connection that rings a doorbell when a frame arrives for this end, or the
// connection closes, so that its reader may sleep on the doorbell (with its other sources)
// instead of in receive(). Connections that cannot (sockets, hidraw) do not implement it;
// a reader finds out with dynamic_cast.
class BellOnArrival {
public:
    // Rings `bell` from now on (nullptr: no more); rings it once at once, so a frame
    // already waiting is not missed.
    virtual void ring_on_arrival(std::shared_ptr<Doorbell> bell) = 0;

protected:
    ~BellOnArrival() = default;
};

}  // namespace feel::transport
