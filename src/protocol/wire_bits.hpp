// Reading and writing a field's bits in a report: little-endian, least significant bit
// first, packed without padding (HID's report layout, HID 1.11 §8.4). Private to the
// protocol library.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

namespace feel::protocol::detail {

// Writes the low `bits` bits of `value` at bit `offset` of `out` (the caller guarantees
// offset + bits <= out.size() * 8). Other bits are left as they are.
inline void write_bits(std::span<uint8_t> out, std::size_t offset, unsigned bits,
                       uint64_t value) noexcept {
    unsigned done = 0;
    while (done < bits) {
        const std::size_t at = offset + done;
        const unsigned shift = static_cast<unsigned>(at % 8);
        const unsigned take = std::min(8u - shift, bits - done);
        const auto mask = static_cast<uint8_t>(((1u << take) - 1u) << shift);
        const auto piece = static_cast<uint8_t>(((value >> done) << shift) & mask);
        uint8_t& byte = out[at / 8];
        byte = static_cast<uint8_t>((byte & ~mask) | piece);
        done += take;
    }
}

// Reads `bits` bits at bit `offset` of `in` (the caller guarantees they are inside),
// zero-extended.
[[nodiscard]] inline uint64_t read_bits(std::span<const uint8_t> in, std::size_t offset,
                                        unsigned bits) noexcept {
    uint64_t value = 0;
    unsigned done = 0;
    while (done < bits) {
        const std::size_t at = offset + done;
        const unsigned shift = static_cast<unsigned>(at % 8);
        const unsigned take = std::min(8u - shift, bits - done);
        const uint64_t piece = (static_cast<unsigned>(in[at / 8]) >> shift) & ((1u << take) - 1u);
        value |= piece << done;
        done += take;
    }
    return value;
}

// The value of a `bits`-wide two's-complement pattern.
[[nodiscard]] constexpr int64_t sign_extend(uint64_t raw, unsigned bits) noexcept {
    if (bits >= 64) return static_cast<int64_t>(raw);
    const uint64_t sign = uint64_t{1} << (bits - 1);
    return static_cast<int64_t>((raw ^ sign) - sign);
}

// The low `bits` bits of a value (its two's-complement pattern when negative).
[[nodiscard]] constexpr uint64_t low_bits(int64_t value, unsigned bits) noexcept {
    const auto pattern = static_cast<uint64_t>(value);
    return bits >= 64 ? pattern : pattern & ((uint64_t{1} << bits) - 1);
}

}  // namespace feel::protocol::detail
