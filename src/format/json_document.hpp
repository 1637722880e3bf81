// feel::format — JSON trees read for validation, not for general use.
//
// Why not nlohmann::json's own DOM? A sensation file must be read strictly, and the
// stock DOM forgets exactly what strict reading needs: it keeps the last of two equal
// keys, turns an integer too large for 64 bits into a float, and has no depth limit.
// JsonValue trees are built by TreeBuilder from nlohmann's SAX events (nlohmann does the
// lexing, UTF-8 checks and error positions), and keep all of that:
//   - duplicate keys are an error naming the object they appear in,
//   - numbers keep their kind: an integer, an integer too large for int64 (with its
//     literal), or a real (with its literal, so messages quote what the file says),
//   - object members keep file order.
//
// Why trees of one sensation, not of the file? Memory. A JsonValue costs about 100 bytes
// and the JSON text of a value can be 2 bytes ("0,"), so a tree of a whole 64 MiB file
// could take gigabytes. The file reader (sensation_reader.cpp) builds one tree per
// sensation, or per effect of a compound, turns it into the model and drops it; and every
// tree is bounded while it is read, before anything is kept (kMaxTree*): nesting, array
// length, object size and its total number of values. No valid sensation comes near them.
#pragma once

#include <cstddef>
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
    [[nodiscard]] JsonValue* find(std::string_view key) noexcept;
};

// Deepest nesting of arrays and objects accepted, counted from the top of the file; a
// valid file needs 8.
inline constexpr int kMaxJsonDepth = 32;
// The longest array of a tree: the longest array of the format is a force profile's
// samples (range::kSampleCount, 65535).
inline constexpr size_t kMaxTreeArrayItems = 65535;
// The most members of one object: no object of the format has 20.
inline constexpr size_t kMaxTreeObjectMembers = 64;
// The most values in one tree (containers, scalars and object keys): a force profile's
// samples and room for every field.
inline constexpr size_t kMaxTreeValues = kMaxTreeArrayItems + 4096;

// A number literal nlohmann reads as a float: an integer too large for 64 bits (no '.',
// 'e' or 'E') or a real.
[[nodiscard]] JsonValue number_literal(const std::string& literal);

// Builds one JsonValue from SAX-like events, enforcing the rules above. Each event
// returns false when the tree breaks one; error() then says what and where.
class TreeBuilder {
public:
    struct Error {
        // Either a field path relative to the tree's root in the reader's style
        // ("custom.samples", "conditions[1].x"; "" for the root) with a problem to go
        // after it, or (field_path_valid false) a whole sentence about the file that
        // names the place by JSON pointer ("duplicate key \"gain\" in the object at
        // /sensations/hum").
        bool field_path_valid = false;
        std::string path;
        std::string problem;
    };

    // Starts a tree for the value at `pointer` in the file (RFC 6901, "/sensations/hum"),
    // which is `depth` containers deep (1 for a member of the top-level object).
    void begin(std::string pointer, int depth);
    // A tree is begun and its root not complete.
    [[nodiscard]] bool building() const noexcept { return building_; }
    // Open containers of the tree (1 inside the root).
    [[nodiscard]] size_t depth() const noexcept { return stack_.size(); }
    // The innermost open container.
    [[nodiscard]] const JsonValue& top() const noexcept { return *stack_.back(); }
    // The root, once complete (building() false); leaves the builder empty.
    [[nodiscard]] JsonValue take();

    bool scalar(JsonValue v);
    bool open(JsonValue::Kind kind);
    bool key(std::string& k);
    bool close();

    // Where the next value goes, relative to the root, in the reader's style.
    [[nodiscard]] std::string next_path() const;
    [[nodiscard]] const Error& error() const noexcept { return error_; }

private:
    bool count_value();
    bool put(JsonValue v);
    [[nodiscard]] std::string path_to(size_t level, bool with_next) const;
    [[nodiscard]] std::string pointer_to_top() const;
    bool fail_at_field(std::string path, std::string problem);

    std::string pointer_;
    int depth_ = 0;
    bool building_ = false;
    size_t values_ = 0;
    JsonValue root_;
    std::vector<JsonValue*> stack_;  // open containers, root first
    std::string pending_key_;
    Error error_;
};

// For messages: "a string \"abc\"", "1.5", "true", "an array", ... Long strings and
// literals are shortened (quote()).
[[nodiscard]] std::string describe(const JsonValue& v);

// A JSON string literal with quotes and escapes, safe to put in a message. A string
// longer than 80 bytes is cut: "\"abc...\" (100000 bytes)".
[[nodiscard]] std::string quote(std::string_view s);

// A number literal for a message: whole when short, else its start and its length.
[[nodiscard]] std::string abbreviate_literal(std::string_view literal);

}  // namespace feel::format::detail
