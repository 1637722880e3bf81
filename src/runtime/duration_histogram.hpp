// A fixed-size histogram of durations in nanoseconds, written by one thread (the loop) and
// read by any thread, for the loop's jitter figures.
//
// Buckets are log-linear, like HdrHistogram's: durations below 64 ns each have a bucket of
// their own; above that, every octave [2^e, 2^(e+1)) is cut into 64 equal buckets, so a
// bucket is never wider than 1/64 of the values it holds. A percentile is reported as the
// middle of its bucket, within 1/128 (0.8%) of the true value. Octaves run up to 2^40 ns
// (18 minutes); anything longer lands in the last bucket, and the exact maximum is kept
// aside.
//
// Recording is a handful of integer operations on a fixed array: no allocation, no lock,
// no system call. Each bucket is an atomic that only the writer modifies (load + store, not
// a read-modify-write: there is one writer), so a reader on another thread never races; a
// reading taken while the writer runs may mix bucket counts from a few records apart,
// which a monitoring figure tolerates, and is exact once the writer has stopped.
#pragma once

#include <atomic>
#include <bit>
#include <cstdint>

namespace feel::runtime {

class DurationHistogram {
public:
    static constexpr int kSubBits = 6;                  // 64 buckets per octave
    static constexpr int kSub = 1 << kSubBits;
    static constexpr int kMaxOctave = 40;               // octaves 2^6 .. 2^39 ns
    // 64 exact buckets, 64 per octave, and one for everything from 2^40 ns on.
    static constexpr int kBuckets = kSub + (kMaxOctave - kSubBits) * kSub + 1;  // 2241

    // The bucket of a duration, ns.
    static constexpr int bucket_of(uint64_t ns) noexcept {
        if (ns < static_cast<uint64_t>(kSub)) return static_cast<int>(ns);
        const int e = 63 - std::countl_zero(ns);  // 2^e <= ns < 2^(e+1), e >= kSubBits
        if (e >= kMaxOctave) return kBuckets - 1;
        const int sub = static_cast<int>(ns >> (e - kSubBits)) - kSub;  // 0..63
        return kSub + (e - kSubBits) * kSub + sub;
    }
    // The smallest duration in bucket i, and the bucket's width, ns.
    static constexpr uint64_t bucket_low(int i) noexcept {
        if (i < kSub) return static_cast<uint64_t>(i);
        const int octave = (i - kSub) / kSub;
        const int sub = (i - kSub) % kSub;
        return static_cast<uint64_t>(kSub + sub) << octave;
    }
    static constexpr uint64_t bucket_width(int i) noexcept {
        return i < kSub ? 1 : uint64_t{1} << ((i - kSub) / kSub);
    }

    // Writer only. Real-time safe.
    void record(uint64_t ns) noexcept {
        std::atomic<uint64_t>& bucket = buckets_[bucket_of(ns)];
        bucket.store(bucket.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
        if (ns > max_.load(std::memory_order_relaxed)) max_.store(ns, std::memory_order_relaxed);
    }

    // Writer only, while no record() runs (before the writer starts).
    void clear() noexcept {
        for (std::atomic<uint64_t>& b : buckets_) b.store(0, std::memory_order_relaxed);
        max_.store(0, std::memory_order_relaxed);
    }

    // Any thread. Durations recorded.
    [[nodiscard]] uint64_t count() const noexcept {
        uint64_t n = 0;
        for (const std::atomic<uint64_t>& b : buckets_) n += b.load(std::memory_order_relaxed);
        return n;
    }
    // Any thread. The largest duration recorded, exact; 0 when empty.
    [[nodiscard]] uint64_t max() const noexcept { return max_.load(std::memory_order_relaxed); }

    // Any thread. The q-quantile (0 < q <= 1) in ns: the ceil(q·count)-th smallest
    // duration, as the middle of its bucket, never more than the exact maximum; the exact
    // maximum when that is the largest one; 0 when empty. Scans the buckets twice; no
    // allocation.
    [[nodiscard]] double quantile(double q) const noexcept {
        const uint64_t n = count();
        if (n == 0) return 0;
        // ceil, forgiving the rounding of q·n (0.99 · 1000 must be rank 990, not 991)
        const double wanted = q * static_cast<double>(n) - 1e-6;
        uint64_t rank = wanted <= 0 ? 1 : static_cast<uint64_t>(wanted);
        if (static_cast<double>(rank) < wanted) ++rank;
        if (rank < 1) rank = 1;
        if (rank >= n) return static_cast<double>(max());
        uint64_t seen = 0;
        for (int i = 0; i < kBuckets; ++i) {
            seen += buckets_[i].load(std::memory_order_relaxed);
            if (seen >= rank) {
                const double mid = static_cast<double>(bucket_low(i)) +
                                   static_cast<double>(bucket_width(i) - 1) / 2.0;
                const double top = static_cast<double>(max());
                return i == kBuckets - 1 || mid > top ? top : mid;
            }
        }
        // A writer raced the two scans; the largest value is the honest answer.
        return static_cast<double>(max());
    }

private:
    std::atomic<uint64_t> buckets_[kBuckets] = {};
    std::atomic<uint64_t> max_{0};
};

}  // namespace feel::runtime
