// Properties of decode() over arbitrary bytes: it never crashes, and whatever it accepts
// re-encodes to exactly the bytes it was given (so no two byte strings decode to the same
// report, and nothing is silently normalized). And every in-range value of every field is
// accepted.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "sample_reports.hpp"

namespace feel::protocol {
namespace {

void check_reencodes(const std::vector<uint8_t>& bytes) {
    AnyReport out;
    const Error e = decode(bytes, out);
    if (e.ok()) {
        RC_ASSERT(encode(out) == bytes);
    } else {
        RC_ASSERT(e.code == ErrorCode::invalid_parameter);
        RC_ASSERT(e.field[0] != '\0');
    }
}

RC_GTEST_PROP(DecodeProperty, ArbitraryBytesNeverCrashAndAcceptedOnesReencode, ()) {
    check_reencodes(*rc::gen::container<std::vector<uint8_t>>(rc::gen::arbitrary<uint8_t>()));
}

RC_GTEST_PROP(DecodeProperty, RandomPayloadsOfRightSizeReencodeWhenAccepted, ()) {
    const std::vector<AnyReport> samples = test::sample_reports();
    const auto which = *rc::gen::inRange<std::size_t>(0, samples.size());
    const auto id = static_cast<uint8_t>(report_id_of(samples[which]));
    std::vector<uint8_t> bytes =
        *rc::gen::container<std::vector<uint8_t>>(report_size(id), rc::gen::arbitrary<uint8_t>());
    bytes[0] = id;
    check_reencodes(bytes);
}

RC_GTEST_PROP(DecodeProperty, MutatedValidReportsReencodeWhenAccepted, ()) {
    const std::vector<AnyReport> samples = test::sample_reports();
    const auto which = *rc::gen::inRange<std::size_t>(0, samples.size());
    std::vector<uint8_t> bytes = encode(samples[which]);
    const auto flips = *rc::gen::inRange(1, 4);
    for (int k = 0; k < flips; ++k) {
        const auto at = *rc::gen::inRange<std::size_t>(1, bytes.size());
        bytes[at] = *rc::gen::arbitrary<uint8_t>();
    }
    check_reencodes(bytes);
}

// Every element set to a random value inside the logical range the descriptor declares
// (read by the independent parser): decode accepts the report, and it re-encodes.
RC_GTEST_PROP(DecodeProperty, InRangeValuesAreAccepted, ()) {
    static const hid::DescriptorParse parse = hid::parse_report_descriptor(report_descriptor());
    RC_ASSERT(parse.ok());
    const std::vector<AnyReport> samples = test::sample_reports();
    const auto which = *rc::gen::inRange<std::size_t>(0, samples.size());
    std::vector<uint8_t> bytes = encode(samples[which]);
    const hid::DescriptorReport* layout = nullptr;
    for (const hid::DescriptorReport& r : parse.descriptor.reports) {
        if (r.id == bytes[0]) layout = &r;
    }
    RC_ASSERT(layout != nullptr);
    for (const hid::DescriptorField& f : layout->fields) {
        if (f.is_constant()) continue;  // padding: no value
        for (uint32_t i = 0; i < f.report_count; ++i) {
            int64_t v = *rc::gen::inRange<int64_t>(f.logical_min, f.logical_max + 1);
            // Command Status and its text name a report that exists: keep the sample's id for it.
            if ((bytes[0] == static_cast<uint8_t>(ReportId::command_status) ||
                 bytes[0] == static_cast<uint8_t>(ReportId::command_error_text)) &&
                f.bit_offset == 32) {
                continue;
            }
            // Fields bound by a rule between fields keep the sample's values: Set Effect's
            // Direction Enable (PID 0x56), its Ordinal angles (page 0x0A), feel's direction
            // form and vector (vendor 0x113, 0x115), a feel hat (north or centred, GD 0x39).
            const uint32_t u = f.usage_of(0);
            if (u == 0x000F0056u || (u >> 16) == 0x000Au || u == 0xFF000113u || u == 0xFF000115u ||
                u == 0x00010039u) {
                continue;
            }
            const std::size_t offset = 8 + f.bit_offset + i * f.report_size;
            for (uint32_t k = 0; k < f.report_size; ++k) {
                const std::size_t at = offset + k;
                const auto mask = static_cast<uint8_t>(1u << (at % 8));
                const bool one = ((static_cast<uint64_t>(v) >> k) & 1u) != 0;
                bytes[at / 8] = static_cast<uint8_t>(one ? (bytes[at / 8] | mask) : (bytes[at / 8] & ~mask));
            }
        }
    }
    AnyReport out;
    const Error e = decode(bytes, out);
    RC_ASSERT_FALSE(static_cast<bool>(e));
    RC_ASSERT(encode(out) == bytes);
}

}  // namespace
}  // namespace feel::protocol
