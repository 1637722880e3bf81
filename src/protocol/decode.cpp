// decode(): bytes to a report struct, walking the report table (field_spec.hpp). The
// device's first line of defence: the length is checked before a single field is read, so
// no read can leave the span; nothing allocates or throws.
#include "feel/protocol/codec.hpp"
#include "field_check.hpp"
#include "joystick_layout.hpp"
#include "report_table.hpp"
#include "wire_bits.hpp"


namespace feel::protocol {
namespace detail {
namespace {

Error refused_by_setter(const ReportSpec& spec, const FieldSpec& field, int index, int64_t value) noexcept {
    char name[48];
    field_name(spec, field, index, name);
    Error e = Error::invalid(name, field.invalid_rule);
    e.value = value;
    return e;
}

}  // namespace

Error decode_fields(const ReportSpec& spec, std::span<const uint8_t> bytes, void* fields) noexcept {
    const std::size_t size = spec.size();
    if (bytes.size() != size) {
        return Error::out_of_range("report.length", static_cast<int64_t>(bytes.size()),
                                   Range{static_cast<int64_t>(size), static_cast<int64_t>(size)});
    }
    std::size_t offset = 8;
    for (const FieldSpec& field : spec.fields) {
        for (int i = 0; i < field.count; ++i) {
            const uint64_t raw = read_bits(bytes, offset, field.bits);
            offset += field.bits;
            const int64_t value = field.is_signed() ? sign_extend(raw, field.bits) : static_cast<int64_t>(raw);
            if (Error e = check_field(spec, field, i, value)) return e;
            if (!field.set(fields, i, value)) return refused_by_setter(spec, field, i, value);
        }
    }
    return {};
}

}  // namespace detail

Error decode(std::span<const uint8_t> bytes, AnyReport& out) noexcept {
    if (bytes.empty()) return Error::invalid("report.length", "is 0: a report starts with its id byte");
    const detail::ReportSpec* spec = detail::find_report(bytes[0]);
    if (spec == nullptr) {
        Error e = Error::invalid("report.id", "names no feel report (docs/protocol.md lists them)");
        e.value = bytes[0];
        return e;
    }
    if (bytes.size() != spec->size()) return detail::decode_fields(*spec, bytes, nullptr);  // the length error
    return detail::decode_fields(*spec, bytes, spec->emplace(out));
}

Error decode(std::span<const uint8_t> bytes, const JoystickLayout& layout, JoystickInputReport& out) noexcept {
    if (const Error e = check_layout(layout)) return e;
    if (bytes.empty()) return Error::invalid("report.length", "is 0: a report starts with its id byte");
    if (bytes[0] != static_cast<uint8_t>(ReportId::joystick_input)) {
        Error e = Error::invalid("report.id", "is not Joystick Input's");
        e.value = bytes[0];
        return e;
    }
    detail::JoystickSpec spec;
    detail::build_joystick_spec(layout, spec);
    out = JoystickInputReport{};
    return detail::decode_fields(spec.spec, bytes, &out);
}

}  // namespace feel::protocol
