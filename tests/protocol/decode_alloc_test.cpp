// decode() never allocates, whether it accepts or refuses (the device decodes on its
// service thread at up to 1 kHz of force streaming). Its own executable: it replaces the
// global allocator.
#include <gtest/gtest.h>

#include "feel/protocol/codec.hpp"
#include "sample_reports.hpp"
#include "support/counting_allocator.hpp"

namespace feel::protocol {
namespace {

TEST(DecodeAllocation, NoneForValidOrInvalidReports) {
    std::vector<std::vector<uint8_t>> inputs;
    for (const AnyReport& r : test::sample_reports()) {
        inputs.push_back(encode(r));
        std::vector<uint8_t> bad = inputs.back();
        bad.pop_back();
        inputs.push_back(bad);
        bad = inputs[inputs.size() - 2];
        for (std::size_t k = 1; k < bad.size(); ++k) bad[k] = 0xFF;
        inputs.push_back(bad);
    }
    inputs.push_back({});
    inputs.push_back({0x00});
    (void)report_descriptor();  // the one-time tables are built outside the count
    (void)max_report_size();
    AnyReport out;
    (void)decode(inputs.front(), out);

    counting = true;
    int accepted = 0;
    for (const std::vector<uint8_t>& bytes : inputs) accepted += decode(bytes, out).ok() ? 1 : 0;
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    EXPECT_GT(accepted, 30);
}

}  // namespace
}  // namespace feel::protocol
