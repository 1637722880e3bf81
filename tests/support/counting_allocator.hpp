// A global allocator that counts, for the tests that prove a real-time path never
// allocates.
//
// Replacement operator new and delete cannot be inline, so this header defines them:
// include it in exactly one source file of a test executable (each *_alloc_test.cpp and
// *_allocation_test.cpp is its own executable for that reason). Allocations are counted,
// from any thread, only while `counting` is true.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace feel::test {

inline std::atomic<bool> counting{false};
inline std::atomic<long> allocations{0};

namespace detail {

inline void count_one() noexcept {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
}

inline void* counted_malloc(std::size_t n) {
    count_one();
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}

inline void* counted_aligned(std::size_t n, std::align_val_t align) {
    count_one();
    const auto a = static_cast<std::size_t>(align);
    if (void* p = std::aligned_alloc(a, (n + a - 1) / a * a)) return p;
    throw std::bad_alloc();
}

}  // namespace detail
}  // namespace feel::test

// Tests name the counter without qualification.
using feel::test::allocations;
using feel::test::counting;

void* operator new(std::size_t n) { return feel::test::detail::counted_malloc(n); }
void* operator new[](std::size_t n) { return feel::test::detail::counted_malloc(n); }
void* operator new(std::size_t n, std::align_val_t a) { return feel::test::detail::counted_aligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return feel::test::detail::counted_aligned(n, a); }

// GCC cannot see that these deletes pair with the malloc-based news above.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop
