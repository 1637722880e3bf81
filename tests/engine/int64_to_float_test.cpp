// float_of_int64_by_int32 (the firmware's int64 → float) against the plain cast, which x86-64
// rounds correctly in one instruction: the same bits at every boundary of its paths (the
// int32 range, each shift, ties and near-ties below and above a float's last bit) and on
// random values of every magnitude.
#include <bit>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "int64_to_float.hpp"

namespace feel::detail {
namespace {

void expect_same_bits(int64_t v) {
    EXPECT_EQ(std::bit_cast<uint32_t>(float_of_int64_by_int32(v)), std::bit_cast<uint32_t>(static_cast<float>(v)))
        << "value " << v;
}

TEST(Int64ToFloat, MatchesTheCastAtEveryBoundary) {
    std::vector<int64_t> values = {0, 1, -1, INT32_MAX, INT32_MIN, int64_t{INT32_MAX} + 1, int64_t{INT32_MIN} - 1,
                                   std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::min(),
                                   std::numeric_limits<int64_t>::min() + 1};
    for (int bit = 23; bit <= 62; ++bit) {
        const int64_t p = int64_t{1} << bit;
        // A float keeps 24 bits: at 2^bit its last kept bit is 2^(bit - 23), half of it 2^(bit - 24).
        const int64_t half = bit >= 24 ? int64_t{1} << (bit - 24) : 0;
        for (const int64_t base : {p, p + (p >> 1), 2 * (p - 1) + 1}) {
            for (const int64_t d : {int64_t{-1}, int64_t{0}, int64_t{1}, half - 1, half, half + 1, 3 * half - 1, 3 * half,
                                    3 * half + 1}) {
                if (d > 0 && base > std::numeric_limits<int64_t>::max() - d) continue;
                values.push_back(base + d);
                values.push_back(-(base + d));
            }
        }
    }
    for (const int64_t v : values) expect_same_bits(v);
}

RC_GTEST_PROP(Int64ToFloat, MatchesTheCastOnRandomValues, ()) {
    // Every magnitude equally often: a random value shifted right by a random amount.
    const auto raw = *rc::gen::arbitrary<int64_t>();
    const int shift = *rc::gen::inRange(0, 64);
    const int64_t v = raw >> shift;
    RC_ASSERT(std::bit_cast<uint32_t>(float_of_int64_by_int32(v)) == std::bit_cast<uint32_t>(static_cast<float>(v)));
}

}  // namespace
}  // namespace feel::detail
