// encode(): a report struct to its bytes, walking the report table (field_spec.hpp).
#include <stdexcept>

#include "feel/protocol/codec.hpp"
#include "field_check.hpp"
#include "joystick_layout.hpp"
#include "report_table.hpp"
#include "wire_bits.hpp"


namespace feel::protocol {
namespace detail {

std::vector<uint8_t> encode_fields(const ReportSpec& spec, const void* fields) {
    std::vector<uint8_t> bytes(spec.size(), 0);
    bytes[0] = static_cast<uint8_t>(spec.id);
    std::size_t offset = 8;
    for (const FieldSpec& field : spec.fields) {
        for (int i = 0; i < field.count; ++i) {
            const int64_t value = field.get(fields, i);
            if (const Error e = check_field(spec, field, i, value)) {
                throw std::invalid_argument("cannot encode " + std::string(spec.name) + ": " + e.message());
            }
            write_bits(bytes, offset, field.bits, low_bits(value, field.bits));
            offset += field.bits;
        }
    }
    return bytes;
}

}  // namespace detail

std::vector<uint8_t> encode(const AnyReport& report) {
    const detail::ReportSpec& spec = detail::report_of(report);
    return detail::encode_fields(spec, spec.view(report));
}

std::vector<uint8_t> encode(const JoystickInputReport& report, const JoystickLayout& layout) {
    if (const Error e = check_layout(layout)) {
        throw std::invalid_argument("cannot encode Joystick Input: " + e.message());
    }
    detail::JoystickSpec spec;
    detail::build_joystick_spec(layout, spec);
    return detail::encode_fields(spec.spec, &report);
}

}  // namespace feel::protocol
