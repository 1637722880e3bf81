// The doorbell's futex (doorbell.hpp).
//
// The sleeping flag spares the ringer a system call while the waiter is awake (the common
// case under load: it is pumping). Its correctness is the store-load pattern both sides
// run in sequentially consistent order: the waiter stores sleeping = 1 and then loads the
// count; the ringer adds to the count and then loads sleeping. At least one sees the
// other's store: either the waiter sees the new count and does not sleep, or the ringer
// sees the flag and wakes it. FUTEX_WAIT itself sleeps only if the word still holds
// `seen`, atomically in the kernel, so a ring between the load and the sleep is not lost.
#include "feel/transport/doorbell.hpp"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <ctime>

namespace feel::transport {
namespace {

uint32_t* word(std::atomic<uint32_t>& a) noexcept {
    static_assert(sizeof(std::atomic<uint32_t>) == sizeof(uint32_t) && std::atomic<uint32_t>::is_always_lock_free);
    return reinterpret_cast<uint32_t*>(&a);
}

}  // namespace

void Doorbell::ring() noexcept {
    rings_.fetch_add(1, std::memory_order_seq_cst);
    if (sleeping_.load(std::memory_order_seq_cst) != 0) {
        ::syscall(SYS_futex, word(rings_), FUTEX_WAKE_PRIVATE, 1, nullptr, nullptr, 0);
    }
}

void Doorbell::wait(uint32_t seen, std::chrono::microseconds timeout) noexcept {
    if (timeout.count() <= 0) return;
    sleeping_.store(1, std::memory_order_seq_cst);
    if (rings_.load(std::memory_order_seq_cst) == seen) {
        timespec ts{};
        ts.tv_sec = static_cast<time_t>(timeout.count() / 1000000);
        ts.tv_nsec = static_cast<long>((timeout.count() % 1000000) * 1000);
        // EAGAIN (the word changed), EINTR or ETIMEDOUT: every one means "look again"
        ::syscall(SYS_futex, word(rings_), FUTEX_WAIT_PRIVATE, seen, &ts, nullptr, 0);
    }
    sleeping_.store(0, std::memory_order_relaxed);
}

}  // namespace feel::transport
