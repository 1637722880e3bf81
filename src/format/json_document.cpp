// Building bounded JsonValue trees from SAX events, strictly.
#include "json_document.hpp"

#include <nlohmann/json.hpp>

namespace feel::format::detail {

const JsonValue* JsonValue::find(std::string_view key) const noexcept {
    for (size_t i = 0; i < keys.size(); ++i) {
        if (keys[i] == key) return &items[i];
    }
    return nullptr;
}

JsonValue* JsonValue::find(std::string_view key) noexcept {
    return const_cast<JsonValue*>(static_cast<const JsonValue&>(*this).find(key));
}

namespace {

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

}  // namespace

JsonValue number_literal(const std::string& literal) {
    JsonValue v;
    // nlohmann reads an integer literal that overflows int64/uint64 as a float; the raw
    // token tells them apart.
    v.kind = literal.find_first_of(".eE") == std::string::npos ? JsonValue::Kind::big_integer
                                                                : JsonValue::Kind::real;
    v.text = literal;
    return v;
}

void TreeBuilder::begin(std::string pointer, int depth) {
    pointer_ = std::move(pointer);
    depth_ = depth;
    building_ = true;
    values_ = 0;
    root_ = JsonValue{};
    stack_.clear();
    pending_key_.clear();
    error_ = Error{};
}

JsonValue TreeBuilder::take() {
    building_ = false;
    return std::move(root_);
}

bool TreeBuilder::fail_at_field(std::string path, std::string problem) {
    error_ = Error{true, std::move(path), std::move(problem)};
    return false;
}

bool TreeBuilder::count_value() {
    if (++values_ <= kMaxTreeValues) return true;
    return fail_at_field(next_path(), "more than " + std::to_string(kMaxTreeValues) +
                                          " JSON values in one effect (a valid one holds at most " +
                                          std::to_string(kMaxTreeArrayItems) + " samples and its fields)");
}

bool TreeBuilder::put(JsonValue v) {
    if (stack_.empty()) {
        root_ = std::move(v);
        return true;
    }
    JsonValue& parent = *stack_.back();
    if (parent.kind == JsonValue::Kind::object) {
        parent.keys.push_back(std::move(pending_key_));
        pending_key_.clear();
    } else if (parent.items.size() >= kMaxTreeArrayItems) {
        return fail_at_field(path_to(stack_.size(), false),
                             "more than " + std::to_string(kMaxTreeArrayItems) +
                                 " values in one array (the longest array of the format, a force profile's "
                                 "samples, holds at most " +
                                 std::to_string(kMaxTreeArrayItems) + ")");
    }
    parent.items.push_back(std::move(v));
    return true;
}

bool TreeBuilder::scalar(JsonValue v) {
    if (!count_value() || !put(std::move(v))) return false;
    if (stack_.empty()) building_ = false;  // a scalar root is complete at once
    return true;
}

bool TreeBuilder::open(JsonValue::Kind kind) {
    if (depth_ + static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
        error_ = Error{false, {},
                       "nesting deeper than " + std::to_string(kMaxJsonDepth) + " arrays and objects at " +
                           pointer_to_top()};
        return false;
    }
    if (!count_value()) return false;
    JsonValue v;
    v.kind = kind;
    if (!put(std::move(v))) return false;
    // The new container is the last item of its parent (or the root); the parent does not
    // grow again until the new container closes, so the pointer is stable.
    stack_.push_back(stack_.empty() ? &root_ : &stack_.back()->items.back());
    return true;
}

bool TreeBuilder::key(std::string& k) {
    const JsonValue& object = *stack_.back();
    for (const std::string& seen : object.keys) {
        if (seen == k) {
            error_ = Error{false, {}, "duplicate key " + quote(k) + " in the object at " + pointer_to_top()};
            return false;
        }
    }
    if (object.keys.size() >= kMaxTreeObjectMembers) {
        return fail_at_field(path_to(stack_.size(), false),
                             "more than " + std::to_string(kMaxTreeObjectMembers) +
                                 " members in one object (no object of the format has that many)");
    }
    if (!count_value()) return false;
    pending_key_ = std::move(k);
    return true;
}

bool TreeBuilder::close() {
    stack_.pop_back();
    if (stack_.empty()) building_ = false;
    return true;
}

// The path of the container open at `level` (1 = the root); with_next, of the value
// that goes next into the innermost one.
std::string TreeBuilder::path_to(size_t level, bool with_next) const {
    std::string out;
    const size_t steps = with_next ? stack_.size() : level - 1;
    for (size_t i = 0; i < steps; ++i) {
        const JsonValue& c = *stack_[i];
        const bool last = i + 1 == stack_.size();  // only when with_next
        if (c.kind == JsonValue::Kind::object) {
            if (!out.empty()) out += '.';
            out += last ? pending_key_ : c.keys.back();
        } else {
            out += '[' + std::to_string(last ? c.items.size() : c.items.size() - 1) + ']';
        }
    }
    return out;
}

std::string TreeBuilder::next_path() const { return path_to(stack_.size(), true); }

// The JSON pointer of the innermost open container.
std::string TreeBuilder::pointer_to_top() const {
    std::string out = pointer_;
    for (size_t i = 0; i + 1 < stack_.size(); ++i) {
        const JsonValue& c = *stack_[i];
        if (c.kind == JsonValue::Kind::object) {
            append_pointer_token(out, c.keys.back());
        } else {
            append_pointer_token(out, std::to_string(c.items.size() - 1));
        }
    }
    return out.empty() ? "the top level" : out;
}

std::string describe(const JsonValue& v) {
    switch (v.kind) {
        case JsonValue::Kind::null: return "null";
        case JsonValue::Kind::boolean: return v.boolean ? "true" : "false";
        case JsonValue::Kind::integer: return std::to_string(v.integer);
        case JsonValue::Kind::big_integer: return abbreviate_literal(v.text);
        case JsonValue::Kind::real: return abbreviate_literal(v.text);
        case JsonValue::Kind::string: return "the string " + quote(v.text);
        case JsonValue::Kind::array: return "an array";
        case JsonValue::Kind::object: return "an object";
    }
    return "a value";
}

std::string quote(std::string_view s) {
    constexpr size_t kWhole = 80;
    constexpr size_t kShown = 64;
    using Json = nlohmann::json;
    if (s.size() <= kWhole) return Json(std::string(s)).dump(-1, ' ', false, Json::error_handler_t::replace);
    size_t cut = kShown;
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 sequence
    std::string shown = Json(std::string(s.substr(0, cut)) + "...").dump(-1, ' ', false, Json::error_handler_t::replace);
    return shown + " (" + std::to_string(s.size()) + " bytes)";
}

std::string abbreviate_literal(std::string_view literal) {
    constexpr size_t kWhole = 40;
    constexpr size_t kShown = 24;
    if (literal.size() <= kWhole) return std::string(literal);
    return std::string(literal.substr(0, kShown)) + "... (" + std::to_string(literal.size()) + " characters)";
}

}  // namespace feel::format::detail
