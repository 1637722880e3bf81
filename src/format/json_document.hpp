// feel::format — a JSON document read for validation, not for general use.
//
// Why not nlohmann::json's own DOM? A sensation file must be read strictly, and the
// stock DOM forgets exactly what strict reading needs: it keeps the last of two equal
// keys, turns an integer too large for 64 bits into a float, and has no depth limit.
// JsonValue is built by a SAX handler over nlohmann's parser (which does the lexing,
// UTF-8 checks and error positions) and keeps all of that:
//   - duplicate keys are an error naming the object they appear in,
//   - numbers keep their kind: an integer, an integer too large for int64 (with its
//     literal), or a real (with its literal, so messages quote what the file says),
//   - nesting is limited, so hostile input cannot exhaust the stack later,
//   - object members keep file order.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace feel::format::detail {

struct JsonValue {
    enum class Kind : uint8_t { null, boolean, integer, big_integer, real, string, array, object };

    Kind kind = Kind::null;
    bool boolean = false;
    int64_t integer = 0;
    std::string text;              // a string's value; the literal of a big_integer or real
    std::vector<JsonValue> items;  // array elements, or object member values
    std::vector<std::string> keys; // object member keys, parallel to items

    [[nodiscard]] bool is_object() const noexcept { return kind == Kind::object; }
    [[nodiscard]] bool is_array() const noexcept { return kind == Kind::array; }
    [[nodiscard]] bool is_string() const noexcept { return kind == Kind::string; }
    // The member named key, or nullptr. Objects only.
    [[nodiscard]] const JsonValue* find(std::string_view key) const noexcept;
};

// Deepest nesting of arrays and objects accepted; a valid file needs 8.
inline constexpr int kMaxJsonDepth = 32;

// Reads one JSON document. Throws FormatError naming `origin` and, for syntax errors,
// the line and column.
[[nodiscard]] JsonValue parse_json(std::string_view text, std::string_view origin);

// For messages: "a string \"abc\"", "1.5", "true", "an array", ...
[[nodiscard]] std::string describe(const JsonValue& v);

// A JSON string literal with quotes and escapes, safe to put in a message.
[[nodiscard]] std::string quote(std::string_view s);

}  // namespace feel::format::detail
