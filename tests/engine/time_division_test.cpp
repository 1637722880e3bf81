// time_quotient_in_32_bits (the firmware's time / length) against the plain 64-bit division:
// the same quotient around 2³² (where it changes method), at the extremes of
// both operands, at exact multiples and one either side, and on random values of every
// magnitude.
#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <limits>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "time_division.hpp"

namespace feel::detail {
namespace {

void expect_plain_division(int64_t t, int32_t d) {
    EXPECT_EQ(time_quotient_in_32_bits(t, d), t / d) << t << " / " << d;
}

TEST(TimeDivision, MatchesThePlainDivisionAtEveryBoundary) {
    constexpr int64_t kMaxTime = std::numeric_limits<int64_t>::max();
    constexpr int32_t kMaxLength = std::numeric_limits<int32_t>::max();
    const int64_t two32 = int64_t{1} << 32;
    for (const int32_t d : {1, 2, 3, 7, 1000, 65535, 65536, 1'000'000, 0x800000, 0xffffff, kMaxLength - 1, kMaxLength}) {
        for (const int64_t t : {int64_t{0}, int64_t{1}, int64_t{d} - 1, int64_t{d}, two32 - 1, two32, two32 + 1,
                                kMaxTime - 1, kMaxTime}) {
            expect_plain_division(t, d);
        }
        // Exact multiples of d beyond 2³², and one either side of them.
        for (const int64_t k : {two32 / d + 1, kMaxTime / d / 3, kMaxTime / d}) {
            for (const int64_t delta : {int64_t{-1}, int64_t{0}, int64_t{1}}) {
                if (delta > 0 && k * d > kMaxTime - delta) continue;  // past int64
                expect_plain_division(k * d + delta, d);
            }
        }
    }
}

RC_GTEST_PROP(TimeDivision, MatchesThePlainDivisionOnRandomValues, ()) {
    // Every magnitude of both equally often: random bits shifted right by a random amount.
    const auto t = static_cast<int64_t>(*rc::gen::arbitrary<uint64_t>() >> *rc::gen::inRange(1, 64));
    const auto d = static_cast<int32_t>(std::max(1u, *rc::gen::arbitrary<uint32_t>() >> *rc::gen::inRange(1, 32)));
    RC_ASSERT(time_quotient_in_32_bits(t, d) == t / d);
}

}  // namespace
}  // namespace feel::detail
