// PidLayout: a PID device's reports found by usage in its own descriptor; PidReportWriter:
// feel's values scaled into those fields. pid_layout.hpp says why and how.
#include "feel/protocol/pid_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hid_usages.hpp"

namespace feel::protocol::pid {
namespace {

namespace u = usage::pid;
using hid::DescriptorField;
using hid::MainItemKind;

struct ReportKey {
    PidReport report;
    MainItemKind kind;
    uint32_t collection;
    uint32_t alternative;  // another collection usage that names it (0: none)
    std::string_view name;
};

constexpr ReportKey kReports[kPidReportCount] = {
    {PidReport::set_effect, MainItemKind::output, u::kSetEffectReport, 0, "Set Effect"},
    {PidReport::set_envelope, MainItemKind::output, u::kSetEnvelopeReport, 0, "Set Envelope"},
    {PidReport::set_condition, MainItemKind::output, u::kSetConditionReport, 0, "Set Condition"},
    {PidReport::set_periodic, MainItemKind::output, u::kSetPeriodicReport, 0, "Set Periodic"},
    {PidReport::set_constant_force, MainItemKind::output, u::kSetConstantForceReport, 0, "Set Constant Force"},
    {PidReport::set_ramp_force, MainItemKind::output, u::kSetRampForceReport, 0, "Set Ramp Force"},
    {PidReport::effect_operation, MainItemKind::output, u::kEffectOperationReport, 0, "Effect Operation"},
    {PidReport::block_free, MainItemKind::output, u::kPidBlockFreeReport, 0, "PID Block Free"},
    // hid-pidff looks for the 0x96 array; some descriptors name the report 0x95 around it.
    {PidReport::device_control, MainItemKind::output, u::kPidDeviceControl, u::kPidDeviceControlReport,
     "PID Device Control"},
    {PidReport::device_gain, MainItemKind::output, u::kDeviceGainReport, 0, "Device Gain"},
    {PidReport::create_new_effect, MainItemKind::feature, u::kCreateNewEffectReport, 0, "Create New Effect"},
    {PidReport::block_load, MainItemKind::feature, u::kPidBlockLoadReport, 0, "PID Block Load"},
    {PidReport::pool, MainItemKind::feature, u::kPidPoolReport, 0, "PID Pool"},
    {PidReport::state, MainItemKind::input, u::kPidStateReport, 0, "PID State"},
    {PidReport::set_custom_force, MainItemKind::output, u::kSetCustomForceReport, 0, "Set Custom Force"},
    {PidReport::custom_force_data, MainItemKind::output, u::kCustomForceDataReport, 0, "Custom Force Data"},
    {PidReport::download_force_sample, MainItemKind::output, u::kDownloadForceSample, 0, "Download Force Sample"},
};

// PID 1.0's effect types (Effect Type's usages) and feel's types for them.
struct TypeUsage {
    uint32_t usage;
    EffectType type;
    PidReport parameters;  // the report that carries its type-specific block
};
constexpr TypeUsage kTypes[] = {
    {u::kEtConstantForce, EffectType::constant, PidReport::set_constant_force},
    {u::kEtRamp, EffectType::ramp, PidReport::set_ramp_force},
    {u::kEtSquare, EffectType::square, PidReport::set_periodic},
    {u::kEtSine, EffectType::sine, PidReport::set_periodic},
    {u::kEtTriangle, EffectType::triangle, PidReport::set_periodic},
    {u::kEtSawtoothUp, EffectType::saw_up, PidReport::set_periodic},
    {u::kEtSawtoothDown, EffectType::saw_down, PidReport::set_periodic},
    {u::kEtSpring, EffectType::spring, PidReport::set_condition},
    {u::kEtDamper, EffectType::damper, PidReport::set_condition},
    {u::kEtInertia, EffectType::inertia, PidReport::set_condition},
    {u::kEtFriction, EffectType::friction, PidReport::set_condition},
    // feel's force profile is PID's custom force: Set Custom Force, its samples in Custom
    // Force Data, in the format of Download Force Sample (checked in map()).
    {u::kEtCustomForceData, EffectType::force_profile, PidReport::set_custom_force},
};

bool in_collection(const DescriptorField& f, uint32_t collection) {
    return std::find(f.collections.begin(), f.collections.end(), collection) != f.collections.end();
}

bool mentions(const hid::DescriptorReport& r, uint32_t collection) {
    return std::any_of(r.fields.begin(), r.fields.end(),
                       [&](const DescriptorField& f) { return in_collection(f, collection); });
}

bool has_pid_usage(const hid::ParsedDescriptor& d) {
    for (const hid::DescriptorReport& r : d.reports) {
        for (const DescriptorField& f : r.fields) {
            for (uint32_t c : f.collections)
                if (usage::page_of(c) == usage::kPagePid) return true;
            for (uint32_t x : f.usages)
                if (usage::page_of(x) == usage::kPagePid) return true;
        }
    }
    return false;
}

std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%X", v);
    return buf;
}

// The array field of `r` that lists `choice` among its usages.
const DescriptorField* array_listing(const ReportLayout& r, uint32_t array, uint32_t choice) {
    for (const DescriptorField& f : r.fields) {
        if (f.is_variable() || f.is_constant()) continue;
        if (array != 0 && !in_collection(f, array)) continue;
        if (std::find(f.usages.begin(), f.usages.end(), choice) != f.usages.end()) return &f;
    }
    return nullptr;
}

const DescriptorField* array_field(const ReportLayout& r, uint32_t array) {
    for (const DescriptorField& f : r.fields) {
        if (!f.is_variable() && !f.is_constant() && in_collection(f, array)) return &f;
    }
    return nullptr;
}

uint64_t read_bits(std::span<const uint8_t> bytes, std::size_t bit, uint32_t size) {
    uint64_t v = 0;
    for (uint32_t i = 0; i < size && i < 64; ++i) {
        const std::size_t b = bit + i;
        if ((bytes[b / 8] >> (b % 8)) & 1u) v |= uint64_t{1} << i;
    }
    return v;
}

// Where a report's fields start in its bytes: after the ID byte (always there in feel's
// buffers, 0 for an unnumbered device, as hidraw wants it).
constexpr std::size_t kIdBits = 8;

// The first Input report with a Generic Desktop axis, mapped (JoystickInputLayout).
JoystickInputLayout map_joystick(const hid::ParsedDescriptor& d) {
    JoystickInputLayout out;
    for (const hid::DescriptorReport& r : d.reports) {
        if (r.kind != MainItemKind::input) continue;
        JoystickInputLayout j;
        j.id = r.id;
        j.bytes = 1 + (r.bit_length + 7) / 8;
        j.fields = r.fields;
        for (std::size_t i = 0; i < r.fields.size(); ++i) {
            const DescriptorField& f = r.fields[i];
            if (f.is_constant() || !f.is_variable()) continue;
            for (uint32_t k = 0; k < f.report_count; ++k) {
                const uint32_t use = f.usage_of(k);
                if (use >= usage::gd::kX && use <= usage::gd::kRz) {
                    j.axes.push_back({use, i, k});
                } else if (use == usage::gd::kHatSwitch && j.hats.size() < 4) {
                    j.hats.push_back({use, i, k});
                } else if (usage::page_of(use) == usage::kPageButton && usage::id_of(use) >= 1 &&
                           usage::id_of(use) <= 32 && f.report_size == 1) {
                    j.buttons.push_back({use, i, k});
                }
            }
        }
        if (j.axes.empty()) continue;
        j.present = true;
        return j;
    }
    return out;
}

int64_t read_element(const DescriptorField& f, uint32_t element, std::span<const uint8_t> bytes) {
    const uint32_t size = std::min<uint32_t>(f.report_size, 63);
    uint64_t raw = read_bits(bytes, kIdBits + f.bit_offset + static_cast<std::size_t>(element) * f.report_size, size);
    if (f.logical_min < 0 && size > 0 && ((raw >> (size - 1)) & 1u)) raw |= ~uint64_t{0} << size;  // sign-extend
    return static_cast<int64_t>(raw);
}

}  // namespace

std::string_view pid_report_name(PidReport report) noexcept { return kReports[static_cast<int>(report)].name; }

std::optional<uint32_t> pid_type_usage(EffectType type) noexcept {
    for (const TypeUsage& t : kTypes)
        if (t.type == type) return t.usage;
    return std::nullopt;
}

std::optional<PidLayout> PidLayout::from_bytes(std::span<const uint8_t> descriptor, std::string& error) {
    const hid::DescriptorParse parse = hid::parse_report_descriptor(descriptor);
    if (!parse.ok()) {
        error = "the report descriptor does not parse: " + parse.error;
        return std::nullopt;
    }
    return map(parse.descriptor, error);
}

std::optional<PidLayout> PidLayout::map(const hid::ParsedDescriptor& d, std::string& error) {
    if (!has_pid_usage(d)) {
        error = "not a force-feedback device: its report descriptor has no usage of the PID page (0x0F)";
        return std::nullopt;
    }
    PidLayout out;
    out.uses_report_ids_ = d.uses_report_ids;
    out.joystick_ = map_joystick(d);
    for (const ReportKey& key : kReports) {
        ReportLayout& slot = out.reports_[static_cast<int>(key.report)];
        for (const hid::DescriptorReport& r : d.reports) {
            if (r.kind != key.kind) continue;
            if (!mentions(r, key.collection) && (key.alternative == 0 || !mentions(r, key.alternative))) continue;
            slot.present = true;
            slot.kind = r.kind;
            slot.id = r.id;
            slot.bytes = 1 + (r.bit_length + 7) / 8;
            slot.fields = r.fields;
            break;
        }
    }
    for (const PidReport required : {PidReport::set_effect, PidReport::effect_operation, PidReport::block_free,
                                     PidReport::create_new_effect, PidReport::block_load}) {
        if (!out.report(required).present) {
            error = "a PID device this host cannot drive: its descriptor declares no " +
                    std::string(pid_report_name(required)) + " report (" +
                    hex(kReports[static_cast<int>(required)].collection & 0xFFFF) + ")";
            return std::nullopt;
        }
    }
    const ReportLayout& set_effect = out.report(PidReport::set_effect);
    const DescriptorField* types = array_field(set_effect, u::kEffectType);
    if (types == nullptr) {
        error = "a PID device this host cannot drive: its Set Effect report has no Effect Type array (0x25)";
        return std::nullopt;
    }
    if (const FieldPlace block = out.find(PidReport::set_effect, u::kEffectBlockIndex)) {
        out.max_block_ = block.field->logical_max;
    } else {
        error = "a PID device this host cannot drive: its Set Effect report has no Effect Block Index (0x22)";
        return std::nullopt;
    }
    const ReportLayout& create = out.report(PidReport::create_new_effect);
    for (const uint32_t usage_value : types->usages) {
        EffectTypeEntry entry;
        entry.usage = usage_value;
        const TypeUsage* known = nullptr;
        for (const TypeUsage& t : kTypes)
            if (t.usage == usage_value) known = &t;
        if (known == nullptr) {
            entry.why_not = "usage " + hex(usage_value) + " is not one of PID 1.0's effect types";
        } else {
            entry.type = known->type;
            if (!out.report(known->parameters).present) {
                entry.why_not = "the descriptor declares no " + std::string(pid_report_name(known->parameters)) + " report";
            } else if (known->type == EffectType::force_profile && !out.custom_force_ready(entry.why_not)) {
                // why_not says what the samples lack
            } else if (array_listing(create, u::kEffectType, usage_value) == nullptr) {
                entry.why_not = "Create New Effect's Effect Type does not list it";
            } else {
                entry.usable = true;
                out.supported_ |= effect_type_bit(known->type);
            }
        }
        out.types_.push_back(std::move(entry));
    }
    for (const DescriptorField& f : set_effect.fields) {
        if (!f.is_variable() || f.is_constant() || !in_collection(f, u::kAxesEnable)) continue;
        for (uint32_t k = 0; k < f.report_count; ++k) {
            const uint32_t a = f.usage_of(k);
            if (a >= usage::gd::kX && a <= usage::gd::kRz) out.axes_.push_back(static_cast<Axis>(a - usage::gd::kX));
        }
    }
    return out;
}

bool PidLayout::custom_force_ready(std::string& why_not) const {
    const FieldPlace data = find(PidReport::custom_force_data, u::kCustomForceData);
    if (!report(PidReport::custom_force_data).present || !data) {
        why_not = "the descriptor declares no Custom Force Data report with Custom Force Data (0x69), where the samples go";
        return false;
    }
    if (!find(PidReport::custom_force_data, u::kCustomForceDataOffset)) {
        why_not = "its Custom Force Data report has no Custom Force Data Offset (0x6C)";
        return false;
    }
    if (!find(PidReport::set_custom_force, u::kSampleCount) || !find(PidReport::set_custom_force, u::kSamplePeriod)) {
        why_not = "its Set Custom Force report lacks Sample Count (0x6D) or Sample Period (0x51)";
        return false;
    }
    if (sample_axes().empty()) {
        why_not = "the descriptor declares no Download Force Sample report with axes (Generic Desktop X..Rz): "
                  "the format of a sample";
        return false;
    }
    return true;
}

std::vector<Axis> PidLayout::sample_axes() const {
    std::vector<Axis> out;
    for (const DescriptorField& f : report(PidReport::download_force_sample).fields) {
        if (f.is_constant() || !f.is_variable()) continue;
        for (uint32_t k = 0; k < f.report_count; ++k) {
            const uint32_t a = f.usage_of(k);
            if (a >= usage::gd::kX && a <= usage::gd::kRz) out.push_back(static_cast<Axis>(a - usage::gd::kX));
        }
    }
    return out;
}

FieldPlace PidLayout::find(PidReport r, uint32_t usage_value, uint32_t within) const noexcept {
    const ReportLayout& layout = report(r);
    for (const DescriptorField& f : layout.fields) {
        if (f.is_constant()) continue;
        if (within != 0 && !in_collection(f, within)) continue;
        if (f.is_variable()) {
            for (uint32_t k = 0; k < f.report_count && k < f.usages.size(); ++k)
                if (f.usages[k] == usage_value) return {&f, k};
        } else if (std::find(f.usages.begin(), f.usages.end(), usage_value) != f.usages.end()) {
            return {&f, 0};
        }
    }
    return {};
}

// --- values into fields -----------------------------------------------------------------

std::optional<int64_t> level_to_logical(const DescriptorField& f, int64_t v) noexcept {
    const double scale = static_cast<double>(v) / kFullScale;
    if (f.logical_min < 0) {
        const double bound = v >= 0 ? static_cast<double>(f.logical_max) : -static_cast<double>(f.logical_min);
        return static_cast<int64_t>(std::llround(scale * bound));
    }
    if (v < 0) return std::nullopt;
    return f.logical_min + static_cast<int64_t>(std::llround(scale * static_cast<double>(f.logical_max - f.logical_min)));
}

int64_t time_to_logical(const DescriptorField& f, int64_t us) noexcept {
    // HID units (HID 1.11 §6.2.2.7): nibble 0 the system, nibble 3 time's exponent.
    const bool is_seconds = (f.unit & 0xFu) != 0 && ((f.unit >> 12) & 0xFu) == 1 && (f.unit & 0xFFFF0FF0u) == 0;
    if (!is_seconds) return (us + 500) / 1000;  // ms, hid-pidff's unit whatever the descriptor says
    // counts of 10^e s: us * 10^-6 / 10^e = us * 10^(-6-e).
    const int shift = -6 - f.unit_exponent;
    double v = static_cast<double>(us);
    v *= std::pow(10.0, shift);
    return static_cast<int64_t>(std::llround(v));
}

int64_t angle_to_logical(const DescriptorField& f, int64_t centidegrees) noexcept {
    const double turn = static_cast<double>(f.logical_max - f.logical_min);
    return f.logical_min + static_cast<int64_t>(std::llround(static_cast<double>(centidegrees) * turn / 36000.0));
}

PidReportWriter::PidReportWriter(const PidLayout& layout, PidReport report) : layout_(layout), report_(report) {
    const ReportLayout& r = layout.report(report);
    bytes_.assign(std::max<std::size_t>(r.bytes, 1), 0);
    bytes_[0] = r.id;
    if (!r.present) error_ = "the device declares no " + std::string(pid_report_name(report)) + " report";
}

bool PidReportWriter::fail(std::string message) {
    if (error_.empty()) error_ = std::string(pid_report_name(report_)) + ": " + std::move(message);
    return false;
}

bool PidReportWriter::write(const FieldPlace& place, int64_t logical, uint32_t usage_value) {
    const DescriptorField& f = *place.field;
    const uint32_t size = std::min<uint32_t>(f.report_size, 64);
    if (logical < f.logical_min || logical > f.logical_max) {
        // The field's null (all ones, out of range) is written only by set_time_or_infinite.
        return fail("usage " + hex(usage_value) + " would be " + std::to_string(logical) + ", the device's field holds " +
                    std::to_string(f.logical_min) + ".." + std::to_string(f.logical_max));
    }
    const uint64_t bits = static_cast<uint64_t>(logical);
    const std::size_t at = kIdBits + f.bit_offset + static_cast<std::size_t>(place.element) * f.report_size;
    for (uint32_t i = 0; i < size; ++i) {
        const std::size_t b = at + i;
        if (b / 8 >= bytes_.size()) return fail("field " + hex(usage_value) + " runs past the report's end");
        const auto mask = static_cast<uint8_t>(1u << (b % 8));
        if ((bits >> i) & 1u) bytes_[b / 8] = static_cast<uint8_t>(bytes_[b / 8] | mask);
        else bytes_[b / 8] = static_cast<uint8_t>(bytes_[b / 8] & ~mask);
    }
    return true;
}

bool PidReportWriter::set(uint32_t usage_value, int64_t value, Scale scale, bool required, uint32_t within) {
    if (!ok()) return false;
    const FieldPlace place = layout_.find(report_, usage_value, within);
    if (!place) return required ? fail("the device's report has no field " + hex(usage_value)) : true;
    return scaled_write(place, value, scale, usage_value);
}

bool PidReportWriter::set_element(uint32_t usage_value, uint32_t element, int64_t value, Scale scale) {
    if (!ok()) return false;
    FieldPlace place = layout_.find(report_, usage_value);
    if (!place) return fail("the device's report has no field " + hex(usage_value));
    place.element += element;
    if (place.element >= place.field->report_count) {
        return fail("usage " + hex(usage_value) + " has " + std::to_string(place.field->report_count) +
                    " elements, element " + std::to_string(place.element) + " asked");
    }
    return scaled_write(place, value, scale, usage_value);
}

bool PidReportWriter::scaled_write(const FieldPlace& place, int64_t value, Scale scale, uint32_t usage_value) {
    const DescriptorField& f = *place.field;
    int64_t logical = value;
    switch (scale) {
        case Scale::raw: break;
        case Scale::level: {
            const std::optional<int64_t> l = level_to_logical(f, value);
            if (!l) {
                return fail("usage " + hex(usage_value) + " is " + std::to_string(value) + ", the device's field holds " +
                            std::to_string(f.logical_min) + ".." + std::to_string(f.logical_max) +
                            " for levels 0..10000 (it takes no negative level)");
            }
            logical = *l;
            break;
        }
        case Scale::time: logical = time_to_logical(f, value); break;
        case Scale::angle: logical = angle_to_logical(f, value); break;
    }
    return write(place, logical, usage_value);
}

bool PidReportWriter::select(uint32_t array, uint32_t choice) {
    if (!ok()) return false;
    const DescriptorField* f = array_listing(layout_.report(report_), array, choice);
    if (f == nullptr) return fail("its array " + hex(array) + " does not list usage " + hex(choice));
    const auto index = static_cast<int64_t>(std::find(f->usages.begin(), f->usages.end(), choice) - f->usages.begin());
    return write(FieldPlace{f, 0}, f->logical_min + index, array);
}

bool PidReportWriter::set_time_or_infinite(uint32_t usage_value, int64_t us, bool required) {
    if (!ok()) return false;
    if (us != kInfiniteUs) return set(usage_value, us, Scale::time, required);
    const FieldPlace place = layout_.find(report_, usage_value);
    if (!place) return required ? fail("the device's report has no field " + hex(usage_value)) : true;
    const DescriptorField& f = *place.field;
    const uint32_t size = std::min<uint32_t>(f.report_size, 63);
    const int64_t all_ones = (int64_t{1} << size) - 1;
    if (all_ones <= f.logical_max) {
        return fail("usage " + hex(usage_value) + " cannot be infinite: its field (" + std::to_string(size) +
                    " bits, " + std::to_string(f.logical_min) + ".." + std::to_string(f.logical_max) +
                    ") has no null value out of its range");
    }
    const std::size_t at = kIdBits + f.bit_offset + static_cast<std::size_t>(place.element) * f.report_size;
    for (uint32_t i = 0; i < size; ++i) {
        const std::size_t b = at + i;
        if (b / 8 >= bytes_.size()) return fail("field " + hex(usage_value) + " runs past the report's end");
        bytes_[b / 8] = static_cast<uint8_t>(bytes_[b / 8] | (1u << (b % 8)));
    }
    return true;
}

std::optional<int64_t> read_field(const PidLayout& layout, PidReport report, std::span<const uint8_t> bytes,
                                  uint32_t usage_value) {
    const FieldPlace place = layout.find(report, usage_value);
    if (!place) return std::nullopt;
    const DescriptorField& f = *place.field;
    const uint32_t size = std::min<uint32_t>(f.report_size, 63);
    const std::size_t at = kIdBits + f.bit_offset + static_cast<std::size_t>(place.element) * f.report_size;
    if ((at + size + 7) / 8 > bytes.size()) return std::nullopt;
    uint64_t raw = read_bits(bytes, at, size);
    if (f.logical_min < 0 && size > 0 && ((raw >> (size - 1)) & 1u)) raw |= ~uint64_t{0} << size;  // sign-extend
    return static_cast<int64_t>(raw);
}

std::vector<Axis> PidLayout::input_axes() const {
    std::vector<Axis> out;
    for (const JoystickInputLayout::Place& p : joystick_.axes) out.push_back(static_cast<Axis>(p.usage - usage::gd::kX));
    return out;
}

bool read_joystick(const PidLayout& layout, std::span<const uint8_t> bytes, JoystickReading& out) noexcept {
    const JoystickInputLayout& j = layout.joystick_input();
    if (!j.present || bytes.size() < j.bytes || bytes[0] != j.id) return false;
    out = JoystickReading{};
    for (const JoystickInputLayout::Place& p : j.axes) {
        const DescriptorField& f = j.fields[p.field];
        const double span = static_cast<double>(f.logical_max - f.logical_min);
        const double middle = (static_cast<double>(f.logical_max) + static_cast<double>(f.logical_min)) / 2;
        const double v = static_cast<double>(read_element(f, p.element, bytes));
        const double normalized = span > 0 ? (v - middle) * (2.0 * kFullScale) / span : 0.0;
        out.position[p.usage - usage::gd::kX] = static_cast<float>(std::clamp(normalized, -1.0 * kFullScale, 1.0 * kFullScale));
    }
    for (const JoystickInputLayout::Place& p : j.buttons) {
        if (read_element(j.fields[p.field], p.element, bytes) != 0) out.buttons |= 1u << (usage::id_of(p.usage) - 1);
    }
    for (std::size_t h = 0; h < j.hats.size(); ++h) {
        const DescriptorField& f = j.fields[j.hats[h].field];
        const int64_t v = read_element(f, j.hats[h].element, bytes);
        if (v >= f.logical_min && v <= f.logical_max) out.hats |= 1u << h;
    }
    return true;
}

std::optional<uint32_t> read_selection(const PidLayout& layout, PidReport report, std::span<const uint8_t> bytes,
                                       uint32_t array) {
    const DescriptorField* f = array_field(layout.report(report), array);
    if (f == nullptr) return std::nullopt;
    const std::size_t at = kIdBits + f->bit_offset;
    if ((at + f->report_size + 7) / 8 > bytes.size()) return std::nullopt;
    const auto value = static_cast<int64_t>(read_bits(bytes, at, std::min<uint32_t>(f->report_size, 63)));
    const int64_t index = value - f->logical_min;
    if (index < 0 || index >= static_cast<int64_t>(f->usages.size())) return std::nullopt;
    return f->usages[static_cast<std::size_t>(index)];
}

}  // namespace feel::protocol::pid
