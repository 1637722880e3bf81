// Building a JsonValue from nlohmann's SAX events, strictly.
#include "json_document.hpp"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <unordered_set>

#include "feel/format/sensation_file.hpp"

namespace feel::format::detail {

const JsonValue* JsonValue::find(std::string_view key) const noexcept {
    for (size_t i = 0; i < keys.size(); ++i) {
        if (keys[i] == key) return &items[i];
    }
    return nullptr;
}

namespace {

using Json = nlohmann::json;

// nlohmann reads an integer literal that overflows int64/uint64 as a float; the raw
// token tells them apart.
bool is_integer_literal(const std::string& s) {
    return s.find_first_of(".eE") == std::string::npos;
}

// Escapes one pointer token (RFC 6901).
void append_pointer_token(std::string& out, std::string_view token) {
    out += '/';
    for (char c : token) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
}

class DomBuilder final : public nlohmann::json_sax<Json> {
public:
    explicit DomBuilder(std::string_view text) : text_(text) {}

    JsonValue root;
    std::string error;  // set when a callback stops the parse

    bool null() override { return put(JsonValue{}); }

    bool boolean(bool val) override {
        JsonValue v;
        v.kind = JsonValue::Kind::boolean;
        v.boolean = val;
        return put(std::move(v));
    }

    bool number_integer(number_integer_t val) override {
        JsonValue v;
        v.kind = JsonValue::Kind::integer;
        v.integer = val;
        return put(std::move(v));
    }

    bool number_unsigned(number_unsigned_t val) override {
        JsonValue v;
        if (val > static_cast<number_unsigned_t>(std::numeric_limits<int64_t>::max())) {
            v.kind = JsonValue::Kind::big_integer;
            v.text = std::to_string(val);
        } else {
            v.kind = JsonValue::Kind::integer;
            v.integer = static_cast<int64_t>(val);
        }
        return put(std::move(v));
    }

    bool number_float(number_float_t, const string_t& s) override {
        JsonValue v;
        v.kind = is_integer_literal(s) ? JsonValue::Kind::big_integer : JsonValue::Kind::real;
        v.text = s;
        return put(std::move(v));
    }

    bool string(string_t& val) override {
        JsonValue v;
        v.kind = JsonValue::Kind::string;
        v.text = std::move(val);
        return put(std::move(v));
    }

    bool binary(binary_t&) override {
        error = "binary values are not JSON";  // only binary formats produce them
        return false;
    }

    bool start_object(std::size_t) override { return open(JsonValue::Kind::object); }

    bool key(string_t& val) override {
        Open& top = stack_.back();
        if (!top.keys_seen.insert(val).second) {
            error = "duplicate key " + quote(val) + " in the object at " + pointer_to_top();
            return false;
        }
        pending_key_ = std::move(val);
        return true;
    }

    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(JsonValue::Kind::array); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) override {
        // Syntax errors read "[json.exception.parse_error.101] parse error at line 2,
        // column 5: syntax error ..."; keep nlohmann's position and explanation.
        const std::string what = ex.what();
        const std::string marker = "parse error at ";
        if (const size_t at = what.find(marker); at != std::string::npos) {
            error = "invalid JSON " + what.substr(at + marker.size() - 3);
            return false;
        }
        // Others (a number too large for a double: "[json.exception.out_of_range.406]
        // number overflow parsing '1e999'") carry no line: derive it from the offset.
        const size_t end = std::min(position, text_.size());
        const std::string_view before = text_.substr(0, end);
        const size_t line = 1 + static_cast<size_t>(std::count(before.begin(), before.end(), '\n'));
        const size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
        const size_t bracket = what.find("] ");
        error = "invalid JSON at line " + std::to_string(line) + ", column " + std::to_string(end - line_start) +
                ": " + (bracket == std::string::npos ? what : what.substr(bracket + 2));
        return false;
    }

private:
    struct Open {
        JsonValue* value;
        std::unordered_set<std::string> keys_seen;  // objects only
    };

    bool put(JsonValue v) {
        if (stack_.empty()) {
            root = std::move(v);
            return true;
        }
        JsonValue& parent = *stack_.back().value;
        if (parent.kind == JsonValue::Kind::object) parent.keys.push_back(std::move(pending_key_));
        parent.items.push_back(std::move(v));
        return true;
    }

    bool open(JsonValue::Kind kind) {
        if (static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
            error = "nesting deeper than " + std::to_string(kMaxJsonDepth) +
                    " arrays and objects at " + pointer_to_top();
            return false;
        }
        JsonValue v;
        v.kind = kind;
        put(std::move(v));
        // The new container is the last item of its parent (or the root); the parent
        // does not grow again until the new container closes, so the pointer is stable.
        JsonValue* opened = stack_.empty() ? &root : &stack_.back().value->items.back();
        stack_.push_back(Open{opened, {}});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    // The JSON pointer of the innermost open container.
    std::string pointer_to_top() const {
        std::string out;
        for (size_t i = 0; i + 1 < stack_.size(); ++i) {
            const JsonValue& c = *stack_[i].value;
            if (c.kind == JsonValue::Kind::object) {
                append_pointer_token(out, c.keys.back());
            } else {
                append_pointer_token(out, std::to_string(c.items.size() - 1));
            }
        }
        return out.empty() ? "the top level" : out;
    }

    std::string_view text_;  // for positions nlohmann does not give
    std::vector<Open> stack_;
    std::string pending_key_;
};

}  // namespace

JsonValue parse_json(std::string_view text, std::string_view origin) {
    DomBuilder builder(text);
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder);
    if (!ok) {
        throw FormatError(std::string(origin) + ": " +
                          (builder.error.empty() ? std::string("invalid JSON") : builder.error));
    }
    return std::move(builder.root);
}

std::string describe(const JsonValue& v) {
    switch (v.kind) {
        case JsonValue::Kind::null: return "null";
        case JsonValue::Kind::boolean: return v.boolean ? "true" : "false";
        case JsonValue::Kind::integer: return std::to_string(v.integer);
        case JsonValue::Kind::big_integer: return v.text;
        case JsonValue::Kind::real: return v.text;
        case JsonValue::Kind::string: return "the string " + quote(v.text);
        case JsonValue::Kind::array: return "an array";
        case JsonValue::Kind::object: return "an object";
    }
    return "a value";
}

std::string quote(std::string_view s) {
    return Json(std::string(s)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace feel::format::detail
