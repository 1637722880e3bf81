// decode(): bytes to a report struct, walking the report table (field_spec.hpp). The
// device's first line of defence: the length is checked before a single field is read, so
// no read can leave the span; nothing allocates or throws.
#include "feel/protocol/codec.hpp"
#include "field_check.hpp"
#include "report_table.hpp"
#include "wire_bits.hpp"

namespace feel::protocol {

Error decode(std::span<const uint8_t> bytes, AnyReport& out) noexcept {
    if (bytes.empty()) return Error::invalid("report.length", "is 0: a report starts with its id byte");
    const detail::ReportSpec* spec = detail::find_report(bytes[0]);
    if (spec == nullptr) {
        Error e = Error::invalid("report.id", "names no feel report (docs/protocol.md lists them)");
        e.value = bytes[0];
        return e;
    }
    const std::size_t size = spec->size();
    if (bytes.size() != size) {
        return Error::out_of_range("report.length", static_cast<int64_t>(bytes.size()),
                                   Range{static_cast<int64_t>(size), static_cast<int64_t>(size)});
    }
    void* fields = spec->emplace(out);
    std::size_t offset = 8;
    for (const detail::FieldSpec& field : spec->fields) {
        for (int i = 0; i < field.count; ++i) {
            const uint64_t raw = detail::read_bits(bytes, offset, field.bits);
            offset += field.bits;
            const int64_t value = field.is_signed() ? detail::sign_extend(raw, field.bits)
                                                    : static_cast<int64_t>(raw);
            if (Error e = detail::check_field(*spec, field, i, value)) return e;
            field.set(fields, i, value);
        }
    }
    return {};
}

}  // namespace feel::protocol
