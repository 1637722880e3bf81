// feel::format — the field tables that the reader and the writer share.
//
// Every type-specific block of a sensation file is described once, here: the JSON key
// of the block, its shape, and for each field its name, value kind, whether it may be
// omitted, and how to get and set it in EffectParams. The reader and the writer both
// walk these tables, which is what makes writing lossless: a field cannot be read
// without also being written, in the same canonical order.
//
// Optional fields default to the value of a default-constructed EffectParams (the
// struct defaults of effect.hpp), so the defaults documented in
// docs/sensation-format.md are the ones in effect.hpp.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "feel/effect.hpp"

namespace feel::format::detail {

enum class ValueKind : uint8_t {
    i32,     // a JSON integer stored in an int32_t
    i64,     // a JSON integer stored in an int64_t
    boolean, // true or false
    choice,  // a string naming an enumerator; `choices` lists them in enum order
};

struct FieldSpec {
    std::string_view name;
    ValueKind kind;
    bool required;
    std::span<const std::string_view> choices;
    // `slot` selects the axis for per-axis blocks (conditions, control_law), else 0.
    int64_t (*get)(const EffectParams& p, int slot);
    void (*set)(EffectParams& p, int slot, int64_t value);
    // Another name the reader accepts for this field (DirectInput's and evdev's, e.g.
    // attack_level for impulse_level); empty: none. The writer always writes `name`.
    std::string_view alias;
};

enum class BlockShape : uint8_t {
    object,     // "key": { fields }
    per_axis,   // "key": [ { fields } per axis of the effect ]
    one_block,  // "key": [ { fields } ]  (angle_spring: one condition for the whole plane)
};

// Members of a block that are not plain fields.
enum class BlockExtra : uint8_t {
    none,
    samples,      // custom: "samples": [ints], after the fields
    control_law,  // dynamic_control_law: "control_law": [ {law fields} per axis ], first
};

struct BlockLayout {
    std::string_view key;
    BlockShape shape;
    std::span<const FieldSpec> fields;
    BlockExtra extra = BlockExtra::none;
};

// The block a type reads. Every type has exactly one.
[[nodiscard]] BlockLayout block_layout(EffectType t) noexcept;

// The fields of one control_law entry (dynamic_control_law).
[[nodiscard]] std::span<const FieldSpec> control_law_fields() noexcept;

// The fields of "envelope".
[[nodiscard]] std::span<const FieldSpec> envelope_fields() noexcept;

// Every block key of the format, for "block X does not apply to type Y" messages.
[[nodiscard]] std::span<const std::string_view> all_block_keys() noexcept;

}  // namespace feel::format::detail
