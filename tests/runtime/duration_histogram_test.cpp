// The loop's jitter histogram: every duration falls in a bucket that contains it, no
// bucket is wider than 1/64 of what it holds, and quantiles of known distributions come
// out within the 1/128 the bucketing promises.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "duration_histogram.hpp"

namespace feel::runtime {
namespace {

using H = DurationHistogram;

TEST(DurationHistogram, EveryDurationLandsInABucketThatHoldsIt) {
    auto check = [](uint64_t ns) {
        const int b = H::bucket_of(ns);
        ASSERT_GE(b, 0);
        ASSERT_LT(b, H::kBuckets - 1) << ns;
        ASSERT_LE(H::bucket_low(b), ns) << ns;
        ASSERT_LT(ns, H::bucket_low(b) + H::bucket_width(b)) << ns;
        // Resolution: exact below 64 ns, then a width of at most 1/64 of the bucket's start.
        ASSERT_LE(H::bucket_width(b) * 64, std::max<uint64_t>(64, H::bucket_low(b))) << ns;
    };
    for (uint64_t ns = 0; ns < 100'000; ++ns) check(ns);
    for (uint64_t ns = 100'000; ns < (uint64_t{1} << 40); ns = ns * 9 / 8 + 1) check(ns);
    check((uint64_t{1} << 40) - 1);
    // Buckets tile the line: each starts where the previous ends.
    for (int b = 1; b < H::kBuckets; ++b) {
        ASSERT_EQ(H::bucket_low(b), H::bucket_low(b - 1) + H::bucket_width(b - 1)) << b;
    }
    // Beyond 2^40 ns everything shares the overflow bucket.
    EXPECT_EQ(H::bucket_of(uint64_t{1} << 40), H::kBuckets - 1);
    EXPECT_EQ(H::bucket_of(~uint64_t{0}), H::kBuckets - 1);
}

TEST(DurationHistogram, EmptyReadsZero) {
    const auto h = std::make_unique<H>();
    EXPECT_EQ(h->count(), 0u);
    EXPECT_EQ(h->quantile(0.5), 0.0);
    EXPECT_EQ(h->max(), 0u);
}

TEST(DurationHistogram, QuantilesOfAUniformDistribution) {
    // 1..100000 ns once each: the q-quantile is q · 100000 ns.
    const auto h = std::make_unique<H>();
    for (uint64_t ns = 1; ns <= 100'000; ++ns) h->record(ns);
    EXPECT_EQ(h->count(), 100'000u);
    EXPECT_EQ(h->max(), 100'000u);
    for (const double q : {0.5, 0.9, 0.99, 0.999}) {
        const double exact = q * 100'000;
        EXPECT_NEAR(h->quantile(q), exact, exact / 128 + 1) << q;
    }
    EXPECT_EQ(h->quantile(1.0), 100'000.0);  // capped at the exact maximum
}

TEST(DurationHistogram, QuantilesOfASkewedDistribution) {
    // 990 ticks of 2 µs, 9 of 50 µs, 1 of 3 ms: p50 = 2 µs, p99 = 2 µs (the 990th value),
    // p99.9 = 50 µs (the 999th), max 3 ms.
    const auto h = std::make_unique<H>();
    for (int i = 0; i < 990; ++i) h->record(2'000);
    for (int i = 0; i < 9; ++i) h->record(50'000);
    h->record(3'000'000);
    EXPECT_NEAR(h->quantile(0.5), 2'000, 2'000.0 / 128);
    EXPECT_NEAR(h->quantile(0.99), 2'000, 2'000.0 / 128);
    EXPECT_NEAR(h->quantile(0.999), 50'000, 50'000.0 / 128);
    EXPECT_EQ(h->max(), 3'000'000u);
    EXPECT_EQ(h->quantile(1.0), 3'000'000.0);
}

TEST(DurationHistogram, ClearForgetsEverything) {
    const auto h = std::make_unique<H>();
    h->record(5);
    h->record(uint64_t{1} << 50);
    EXPECT_EQ(h->quantile(1.0), static_cast<double>(uint64_t{1} << 50));  // overflow reads the max
    h->clear();
    EXPECT_EQ(h->count(), 0u);
    EXPECT_EQ(h->max(), 0u);
}

}  // namespace
}  // namespace feel::runtime
