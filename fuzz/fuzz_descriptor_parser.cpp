// libFuzzer target: the HID report descriptor parser (descriptor_parser.hpp) against
// arbitrary bytes. It must refuse or accept without a crash or sanitizer finding, and what
// it accepts must be self-consistent: each report's length is the sum of its fields, each
// field starts where the previous one ended, every data field's range is ordered.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "feel/protocol/descriptor_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace feel::protocol::hid;
    const DescriptorParse p = parse_report_descriptor(std::span<const uint8_t>(data, size));
    if (!p.ok()) {
        if (p.error_offset > size) {
            std::fprintf(stderr, "error offset %zu past the end (%zu): %s\n", p.error_offset, size,
                         p.error.c_str());
            std::abort();
        }
        return 0;
    }
    for (const DescriptorReport& r : p.descriptor.reports) {
        uint64_t bits = 0;
        for (const DescriptorField& f : r.fields) {
            if (f.bit_offset != bits || f.report_size == 0 || f.report_count == 0 ||
                (!f.is_constant() && f.logical_min > f.logical_max)) {
                std::fprintf(stderr, "inconsistent field in report %u\n", static_cast<unsigned>(r.id));
                std::abort();
            }
            bits += uint64_t{f.report_size} * f.report_count;
        }
        if (bits != r.bit_length || bits > kMaxReportBits) {
            std::fprintf(stderr, "report %u length %u, fields %llu\n", static_cast<unsigned>(r.id),
                         r.bit_length, static_cast<unsigned long long>(bits));
            std::abort();
        }
    }
    return 0;
}
