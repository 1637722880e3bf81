// The report table's vocabulary: one FieldSpec per field of a report, one ReportSpec per
// report. Private to the protocol library (and its tests).
//
// Design. Every report is described once, as data: its fields in wire order, each with the
// HID usage it carries, its width, its logical range and a pair of accessor functions that
// read and write the struct member it stands for. Three consumers walk the same data:
//
//   encode()             get() each element, check the range, write its bits;
//   decode()             read the bits, check the range, set() the element;
//   report_descriptor()  one HID main item per field, with its usages, range and size.
//
// So the bytes on the wire, the ranges the decoder enforces and what the descriptor tells
// the host cannot drift apart: there is nothing to keep in sync by hand.
//
// Values travel between the struct and the wire as int64_t. Enums go as their underlying
// value, bool as 0/1, char as its byte 0..255, uint64_t as its bit pattern (64-bit fields
// are never range checked: every pattern is a value).
//
// 64-bit fields. HID's Logical Minimum/Maximum items hold at most 32 bits, so a 64-bit
// field cannot state its range. The descriptor declares it as two 32-bit elements, low
// dword first, each 0..0xFFFFFFFF; the bytes are those of the 64-bit little-endian value.
//
// Null values. A field may have one wire value outside its logical range that still means
// something: the all-ones pattern of its width for "infinite" (or_infinite: a duration
// that never ends, a loop count without end), or 0 for "none" (or_none: Block Load's
// block when no block was allocated). The descriptor sets the main item's Null State
// flag, which is how HID spells "this field may hold no value".
//
// Mapped fields. Most fields are a struct member written as is (FEEL_FIELD). A few wire
// fields are a function of a member (FEEL_MAPPED): PID's times in milliseconds plus a
// vendor field with the microseconds below the millisecond, the Effect Type array's
// 1-based index, the direction split into PID's angles and feel's vectors. Their getter
// and setter are written next to the table entry; decode() applies setters in wire
// order, so a setter may read what an earlier field of the same report set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

#include "feel/protocol/reports.hpp"
#include "feel/units.hpp"

namespace feel::protocol::detail {

// The HID Unit (and Unit Exponent) a field declares.
enum class FieldUnit : uint8_t {
    none,
    microseconds,       // s, exponent -6
    milliseconds,       // s, exponent -3
    centidegrees,       // degrees, exponent -2
    hertz,              // 1/s
    centihertz,         // 1/s, exponent -2
    millihertz,         // 1/s, exponent -3
};

using FieldGetter = int64_t (*)(const void* report, int index) noexcept;
// A setter returns false to refuse a value that is in range but contradicts a field set
// before it (decode() then refuses with the field's invalid_rule): decode is lossless, so
// whatever it accepts encodes back to the same bytes.
using FieldSetter = bool (*)(void* report, int index, int64_t value) noexcept;
using ValueCheck = bool (*)(int64_t value) noexcept;

struct FieldSpec {
    // The member's path in the struct, "[i]" standing for the element index:
    // "gain", "axes[i]", "texture.spacing", "axes[i].half_travel_micro".
    std::string_view path;
    // The field's usage (extended form, usage.hpp); every element carries it.
    uint32_t usage = 0;
    // When not empty: one usage per element (a Var field whose elements differ, like the
    // axes X..Rz), or, with named_array, the usages the value selects from.
    std::span<const uint32_t> usage_list{};
    // Non-zero: a PID "named array". The descriptor wraps the field in a Logical
    // collection with this usage, and the field is an HID Array item: value v selects
    // usage_list[v - min].
    uint32_t named_array = 0;
    // Non-zero: the descriptor wraps this (Variable) field in a Logical collection with
    // this usage (PID's Direction 0x57, a collection of Ordinals).
    uint32_t wrap = 0;
    uint8_t bits = 8;   // 1, 4 (hats), 8, 16, 32 or 64 per element; padding 1..7
    uint8_t count = 1;  // elements, 1..255
    Range range{0, 0};  // logical min/max, inclusive (ignored for 64-bit fields)
    FieldUnit unit = FieldUnit::none;
    // The null value (see above): none, the width's all-ones ("infinite") or 0 ("none").
    enum class Null : uint8_t { none, all_ones, zero };
    Null null = Null::none;
    // Constant padding to a byte boundary: no usage, written 0, ignored when read.
    bool padding = false;
    // Enums whose valid values have holes: the range is checked first, then this.
    ValueCheck valid = nullptr;
    const char* invalid_rule = "";  // the Error rule when `valid` or the setter refuses a value
    FieldGetter get = nullptr;
    FieldSetter set = nullptr;

    [[nodiscard]] constexpr bool is_signed() const noexcept { return bits < 64 && range.min < 0; }
    [[nodiscard]] constexpr bool has_null() const noexcept { return null != Null::none; }
    // The wire value of the null (meaningful when has_null()).
    [[nodiscard]] constexpr int64_t null_value() const noexcept {
        return null == Null::zero ? 0 : static_cast<int64_t>((uint64_t{1} << bits) - 1);
    }
    [[nodiscard]] constexpr std::size_t total_bits() const noexcept {
        return static_cast<std::size_t>(bits) * count;
    }

    // Builders for the table, each returning a changed copy.
    [[nodiscard]] constexpr FieldSpec times(int n) const noexcept {
        FieldSpec f = *this;
        f.count = static_cast<uint8_t>(n);
        return f;
    }
    [[nodiscard]] constexpr FieldSpec in(FieldUnit u) const noexcept {
        FieldSpec f = *this;
        f.unit = u;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec or_infinite() const noexcept {
        FieldSpec f = *this;
        f.null = Null::all_ones;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec or_none() const noexcept {
        FieldSpec f = *this;
        f.null = Null::zero;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec refusing(const char* rule) const noexcept {
        FieldSpec f = *this;
        f.invalid_rule = rule;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec wrapped_in(uint32_t collection_usage) const noexcept {
        FieldSpec f = *this;
        f.wrap = collection_usage;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec usages(std::span<const uint32_t> list) const noexcept {
        FieldSpec f = *this;
        f.usage_list = list;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec selects(uint32_t array_usage,
                                              std::span<const uint32_t> list) const noexcept {
        FieldSpec f = *this;
        f.named_array = array_usage;
        f.usage_list = list;
        return f;
    }
    [[nodiscard]] constexpr FieldSpec only(ValueCheck check, const char* rule) const noexcept {
        FieldSpec f = *this;
        f.valid = check;
        f.invalid_rule = rule;
        return f;
    }
};

// Element widths.
[[nodiscard]] constexpr FieldSpec field(uint32_t usage, uint8_t bits, Range range) noexcept {
    FieldSpec f;
    f.usage = usage;
    f.bits = bits;
    f.range = range;
    return f;
}
[[nodiscard]] constexpr FieldSpec u8(uint32_t usage, Range r) noexcept { return field(usage, 8, r); }
[[nodiscard]] constexpr FieldSpec u16(uint32_t usage, Range r) noexcept { return field(usage, 16, r); }
[[nodiscard]] constexpr FieldSpec i16(uint32_t usage, Range r) noexcept { return field(usage, 16, r); }
[[nodiscard]] constexpr FieldSpec u32(uint32_t usage, Range r) noexcept { return field(usage, 32, r); }
[[nodiscard]] constexpr FieldSpec i32(uint32_t usage, Range r) noexcept { return field(usage, 32, r); }
// 64-bit: every pattern is a value.
[[nodiscard]] constexpr FieldSpec x64(uint32_t usage) noexcept {
    return field(usage, 64, Range{0, 0xFFFF'FFFFLL});
}
[[nodiscard]] constexpr FieldSpec flag(uint32_t usage) noexcept { return field(usage, 8, Range{0, 1}); }
// Text: NUL-padded bytes.
[[nodiscard]] constexpr FieldSpec text(uint32_t usage, int bytes) noexcept {
    return field(usage, 8, Range{0, 255}).times(bytes);
}

// Common ranges beyond units.hpp's.
inline constexpr Range kAnyU8{0, 0xFF};
inline constexpr Range kAnyU16{0, 0xFFFF};
inline constexpr Range kAnyU32{0, 0xFFFF'FFFFLL};
inline constexpr Range kAnyI32{INT32_MIN, INT32_MAX};
inline constexpr Range kBlock{1, 0xFFFF};       // an Effect Block Index
inline constexpr Range kBlockOrNone{0, 0xFFFF};  // 0 = no block
inline constexpr Range kAxisIndex{0, kMaxAxes - 1};

// Converting a member to and from its wire value.
template <class T>
[[nodiscard]] constexpr int64_t to_wire(T v) noexcept {
    if constexpr (std::is_same_v<T, bool>) {
        return v ? 1 : 0;
    } else if constexpr (std::is_enum_v<T>) {
        return static_cast<int64_t>(static_cast<std::underlying_type_t<T>>(v));
    } else if constexpr (std::is_same_v<T, char>) {
        return static_cast<int64_t>(static_cast<unsigned char>(v));
    } else {
        return static_cast<int64_t>(v);  // uint64_t keeps its bit pattern
    }
}

template <class T>
[[nodiscard]] constexpr T from_wire(int64_t v) noexcept {
    if constexpr (std::is_same_v<T, bool>) {
        return v != 0;
    } else if constexpr (std::is_enum_v<T>) {
        return static_cast<T>(static_cast<std::underlying_type_t<T>>(v));
    } else if constexpr (std::is_same_v<T, char>) {
        return static_cast<char>(static_cast<unsigned char>(v));
    } else {
        return static_cast<T>(v);
    }
}

// Binds a FieldSpec to a struct member. `Access` is a captureless lambda
// `(auto& report, int i) -> auto&` naming the member (FEEL_FIELD writes it).
template <class Report, auto Access>
[[nodiscard]] constexpr FieldSpec bind(std::string_view path, FieldSpec f) noexcept {
    f.path = path;
    f.get = [](const void* r, int i) noexcept -> int64_t {
        return to_wire(Access(*static_cast<const Report*>(r), i));
    };
    f.set = [](void* r, int i, int64_t v) noexcept {
        auto& member = Access(*static_cast<Report*>(r), i);
        member = from_wire<std::remove_cvref_t<decltype(member)>>(v);
        return true;
    };
    return f;
}

// Binds a FieldSpec to a mapping of the struct: `Get` is `(const Report&, int i) -> int64_t`
// giving the wire value, `Set` is `(Report&, int i, int64_t wire) -> bool` storing it (false:
// refused, see FieldSetter).
template <class Report, auto Get, auto Set>
[[nodiscard]] constexpr FieldSpec bind_mapped(std::string_view path, FieldSpec f) noexcept {
    f.path = path;
    f.get = [](const void* r, int i) noexcept -> int64_t {
        return Get(*static_cast<const Report*>(r), i);
    };
    f.set = [](void* r, int i, int64_t v) noexcept -> bool { return Set(*static_cast<Report*>(r), i, v); };
    return f;
}

// FEEL_MAPPED(Report, "name", spec, getter, setter): a mapped field entry (functions or
// captureless lambdas).
#define FEEL_MAPPED(Report, name, spec, getter, setter) \
    ::feel::protocol::detail::bind_mapped<Report, getter, setter>(name, spec)

// FEEL_FIELD(Report, member path, spec): the table's one-line field entry. The path may
// use `i`, the element index: FEEL_FIELD(SetEffectReport, axes[i], ...).
#define FEEL_FIELD(Report, path, spec)                                                    \
    ::feel::protocol::detail::bind<Report, [](auto& r, [[maybe_unused]] int i) -> auto& { \
        return r.path;                                                                    \
    }>(#path, spec)

struct ReportSpec {
    ReportId id;
    ReportKind kind;
    std::string_view name;  // "Set Effect"
    std::string_view key;   // "set_effect": the prefix of field names in errors
    uint32_t usage;         // the report's collection usage
    std::span<const FieldSpec> fields;
    std::size_t variant_index;                     // its alternative in AnyReport
    void* (*emplace)(AnyReport& out) noexcept;     // makes `out` hold a default report
    const void* (*view)(const AnyReport& in) noexcept;

    [[nodiscard]] std::size_t payload_bits() const noexcept {
        std::size_t bits = 0;
        for (const FieldSpec& f : fields) bits += f.total_bits();
        return bits;
    }
    // Bytes on the wire, the id byte included.
    [[nodiscard]] std::size_t size() const noexcept { return 1 + payload_bits() / 8; }
};

template <class T, std::size_t I = 0>
[[nodiscard]] consteval std::size_t variant_index_of() {
    static_assert(I < std::variant_size_v<AnyReport>, "not an AnyReport alternative");
    if constexpr (std::is_same_v<T, std::variant_alternative_t<I, AnyReport>>) {
        return I;
    } else {
        return variant_index_of<T, I + 1>();
    }
}

template <class T>
void* emplace_report(AnyReport& out) noexcept {
    return &out.emplace<T>();
}
template <class T>
const void* view_report(const AnyReport& in) noexcept {
    return std::get_if<T>(&in);
}

template <class T>
[[nodiscard]] constexpr ReportSpec report(ReportId id, ReportKind kind, std::string_view name,
                                          std::string_view key, uint32_t usage,
                                          std::span<const FieldSpec> fields) noexcept {
    return ReportSpec{id,     kind, name, key, usage, fields, variant_index_of<T>(),
                      &emplace_report<T>, &view_report<T>};
}

}  // namespace feel::protocol::detail
