// encode(): a report struct to its bytes, walking the report table (field_spec.hpp).
#include <stdexcept>

#include "feel/protocol/codec.hpp"
#include "field_check.hpp"
#include "report_table.hpp"
#include "wire_bits.hpp"

namespace feel::protocol {

std::vector<uint8_t> encode(const AnyReport& report) {
    const detail::ReportSpec& spec = detail::report_of(report);
    const void* fields = spec.view(report);
    std::vector<uint8_t> bytes(spec.size(), 0);
    bytes[0] = static_cast<uint8_t>(spec.id);
    std::size_t offset = 8;
    for (const detail::FieldSpec& field : spec.fields) {
        for (int i = 0; i < field.count; ++i) {
            const int64_t value = field.get(fields, i);
            if (const Error e = detail::check_field(spec, field, i, value)) {
                throw std::invalid_argument("cannot encode " + std::string(spec.name) + ": " +
                                            e.message());
            }
            detail::write_bits(bytes, offset, field.bits, detail::low_bits(value, field.bits));
            offset += field.bits;
        }
    }
    return bytes;
}

}  // namespace feel::protocol
