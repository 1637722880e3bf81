// The standard PID form of feel's reports (standard_pid.hpp): the table of standard fields
// (standard_pid_table.hpp), built once from feel's report table, and the translation both
// ways. The translation copies each PID field's bits between its place in feel's layout and
// its place in the standard one; vendor fields are 0 in feel's report from a standard host
// and absent from the standard report; Effect Type's index is mapped between PID's list of
// eleven and feel's list of 33.
#include "feel/protocol/standard_pid.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string>

#include "hid_usages.hpp"
#include "report_table.hpp"
#include "standard_pid_table.hpp"
#include "wire_bits.hpp"

namespace feel::protocol {
namespace detail {
namespace {

// Effect Type's list: PID 1.0's eleven types in the order of its usage table (0x26 .. 0x43),
// then ET Custom Force Data. The device plays the eleven; the twelfth is listed because
// hid-pidff reads one entry past each type it finds (it indexes the usage array with the
// 1-based value), so the last type it uses must not end the list. A Create New Effect for
// it is refused like any type the device does not play (feel's custom force needs vendor
// fields: Set Custom Force and Custom Force Data are not in the standard descriptor).
constexpr EffectType kListedTypes[] = {
    EffectType::constant, EffectType::ramp,     EffectType::square,  EffectType::sine,
    EffectType::triangle, EffectType::saw_up,   EffectType::saw_down, EffectType::spring,
    EffectType::damper,   EffectType::inertia,  EffectType::friction, EffectType::force_profile,
};
constexpr uint32_t kStandardTypeUsages[] = {
    usage::pid::kEtConstantForce, usage::pid::kEtRamp,         usage::pid::kEtSquare,
    usage::pid::kEtSine,          usage::pid::kEtTriangle,     usage::pid::kEtSawtoothUp,
    usage::pid::kEtSawtoothDown,  usage::pid::kEtSpring,       usage::pid::kEtDamper,
    usage::pid::kEtInertia,       usage::pid::kEtFriction,     usage::pid::kEtCustomForceData,
};
static_assert(std::size(kListedTypes) == std::size(kStandardTypeUsages));
// The types the standard device plays: the list but its last.
constexpr std::span<const EffectType> kStandardTypes{kListedTypes, std::size(kListedTypes) - 1};

// The reports of a standard PID device, by feel's id. Joystick Input is not here (its
// layout is the device's own; it has no vendor field).
constexpr ReportId kStandardIds[] = {
    ReportId::set_effect,        ReportId::set_envelope,   ReportId::set_condition,  ReportId::set_periodic,
    ReportId::set_constant_force, ReportId::set_ramp_force, ReportId::effect_operation, ReportId::block_free,
    ReportId::device_control,    ReportId::device_gain,    ReportId::create_new_effect, ReportId::block_load,
    ReportId::pid_pool,          ReportId::pid_state,
};

bool is_vendor_usage(uint32_t u) noexcept { return usage::page_of(u) >= usage::kPageVendor; }

StandardReport standard_form(const ReportSpec& spec) {
    StandardReport out;
    out.feel = &spec;
    std::size_t feel_offset = 8;
    for (const FieldSpec& f : spec.fields) {
        if (!is_vendor_field(f)) {
            StandardField s;
            s.spec = f;
            s.feel_offset = feel_offset;
            if (f.named_array == usage::pid::kEffectType) {
                s.effect_type = true;
                s.spec.usage_list = kStandardTypeUsages;
                s.spec.range = Range{1, static_cast<int64_t>(std::size(kStandardTypeUsages))};
            }
            out.fields.push_back(s);
        }
        feel_offset += f.total_bits();
    }
    // hid-pidff files an output or feature report under the Logical collection of its first
    // field. In feel's Create New Effect the vendor sequence comes first; without it Effect
    // Type would, whose own collection (0x25) names no report: Byte Count goes first.
    if (out.fields.size() > 1 && out.fields.front().effect_type) {
        std::rotate(out.fields.begin(), out.fields.begin() + 1, out.fields.end());
    }
    std::size_t offset = 8;
    for (StandardField& s : out.fields) {
        s.offset = offset;
        offset += s.spec.total_bits();
    }
    out.bytes = offset / 8;  // every report's PID fields fill whole bytes (the tests check it)
    return out;
}

struct Table {
    std::vector<StandardReport> reports;
    std::array<int, 256> by_id{};  // index + 1; 0: none
};

const Table& table() {
    static const Table built = [] {
        Table t;
        for (const ReportId id : kStandardIds) {
            t.reports.push_back(standard_form(*find_report(static_cast<uint8_t>(id))));
            t.by_id[static_cast<uint8_t>(id)] = static_cast<int>(t.reports.size());
        }
        return t;
    }();
    return built;
}

// Effect Type's value: feel's 1-based index (EffectType + 1) <-> PID's list's.
std::optional<int64_t> standard_type_index(int64_t feel_index) noexcept {
    for (std::size_t k = 0; k < std::size(kListedTypes); ++k) {
        if (static_cast<int64_t>(kListedTypes[k]) + 1 == feel_index) return static_cast<int64_t>(k) + 1;
    }
    return std::nullopt;
}

}  // namespace

bool is_vendor_field(const FieldSpec& field) noexcept {
    if (field.padding) return false;
    if (field.named_array != 0) return is_vendor_usage(field.named_array);
    if (field.usage != 0) return is_vendor_usage(field.usage);
    return !field.usage_list.empty() && is_vendor_usage(field.usage_list[0]);
}

std::span<const StandardReport> standard_reports() noexcept { return table().reports; }

const StandardReport* find_standard_report(uint8_t id) noexcept {
    const int at = table().by_id[id];
    return at == 0 ? nullptr : &table().reports[static_cast<std::size_t>(at - 1)];
}

std::span<const EffectType> standard_effect_types() noexcept { return kStandardTypes; }
std::span<const EffectType> listed_effect_types() noexcept { return kListedTypes; }
std::span<const uint32_t> standard_effect_type_usages() noexcept { return kStandardTypeUsages; }

}  // namespace detail

std::span<const EffectType> standard_pid_effect_types() noexcept { return detail::standard_effect_types(); }

uint64_t standard_pid_effect_type_bits() noexcept {
    uint64_t bits = 0;
    for (const EffectType t : detail::standard_effect_types()) bits |= effect_type_bit(t);
    return bits;
}

bool is_standard_pid_report(uint8_t id) noexcept {
    return id == static_cast<uint8_t>(ReportId::joystick_input) || detail::find_standard_report(id) != nullptr;
}

Error standard_pid_to_feel(std::span<const uint8_t> bytes, std::vector<uint8_t>& feel) {
    if (bytes.empty()) return Error::invalid("report.length", "is 0: a report starts with its id byte");
    if (bytes[0] == static_cast<uint8_t>(ReportId::joystick_input)) {
        feel.assign(bytes.begin(), bytes.end());
        return {};
    }
    const detail::StandardReport* r = detail::find_standard_report(bytes[0]);
    if (r == nullptr) {
        Error e = Error::invalid("report.id", "names no report of a standard PID device (docs/usb-device.md)");
        e.value = bytes[0];
        return e;
    }
    if (bytes.size() != r->bytes) {
        return Error::out_of_range("report.length", static_cast<int64_t>(bytes.size()),
                                   Range{static_cast<int64_t>(r->bytes), static_cast<int64_t>(r->bytes)});
    }
    std::vector<uint8_t> out(r->feel->size(), 0);
    out[0] = bytes[0];
    for (const detail::StandardField& f : r->fields) {
        const unsigned bits = static_cast<unsigned>(f.spec.total_bits());
        uint64_t raw = detail::read_bits(bytes, f.offset, bits);
        if (f.effect_type) {
            const auto index = static_cast<int64_t>(raw);
            if (index < f.spec.range.min || index > f.spec.range.max) {
                const std::string field = std::string(r->feel->key) + ".type";
                return Error::out_of_range(field, index, f.spec.range);
            }
            raw = static_cast<uint64_t>(detail::listed_effect_types()[static_cast<std::size_t>(index - 1)]) + 1;
        }
        detail::write_bits(out, f.feel_offset, bits, raw);
    }
    feel = std::move(out);
    return {};
}

bool feel_to_standard_pid(std::span<const uint8_t> bytes, std::vector<uint8_t>& standard) {
    if (bytes.empty()) return false;
    if (bytes[0] == static_cast<uint8_t>(ReportId::joystick_input)) {
        standard.assign(bytes.begin(), bytes.end());
        return true;
    }
    const detail::StandardReport* r = detail::find_standard_report(bytes[0]);
    if (r == nullptr || bytes.size() != r->feel->size()) return false;
    std::vector<uint8_t> out(r->bytes, 0);
    out[0] = bytes[0];
    for (const detail::StandardField& f : r->fields) {
        const unsigned bits = static_cast<unsigned>(f.spec.total_bits());
        uint64_t raw = detail::read_bits(bytes, f.feel_offset, bits);
        if (f.effect_type) {
            const std::optional<int64_t> index = detail::standard_type_index(static_cast<int64_t>(raw));
            if (!index) return false;
            raw = static_cast<uint64_t>(*index);
        }
        detail::write_bits(out, f.offset, bits, raw);
    }
    standard = std::move(out);
    return true;
}

}  // namespace feel::protocol
