// The message checker (protocol_check.hpp); the same rules as studio/src/protocol/check.ts.
#include "protocol_check.hpp"

#include <cmath>
#include <stdexcept>

#include "studio_assets.hpp"

namespace feel::studio {

using json = nlohmann::json;

const ProtocolSchema& ProtocolSchema::embedded() {
    static const ProtocolSchema schema = [] {
        const Asset* a = find_web_asset("/protocol.json");
        if (a == nullptr) throw std::runtime_error("the Studio's protocol.json is not embedded (build problem)");
        return ProtocolSchema(json::parse(a->text()));
    }();
    return schema;
}

ProtocolSchema::ProtocolSchema(json description) : description_(std::move(description)) {}

std::optional<std::string> ProtocolSchema::problem(std::string_view side, const json& m) const {
    if (!m.is_object()) return "a message is a JSON object";
    const json& table = description_.at(std::string(side));
    const auto type = m.find("type");
    if (type == m.end() || !type->is_string() || !table.contains(type->get<std::string>())) {
        std::string allowed;
        for (const auto& [k, v] : table.items()) allowed += (allowed.empty() ? "" : ", ") + k;
        return "unknown message type " + (type == m.end() ? std::string("(none)") : type->dump()) +
               " (allowed: " + allowed + ")";
    }
    const std::string name = type->get<std::string>();
    const json& rules = table.at(name);
    for (const auto& [key, value] : m.items()) {
        if (key != "type" && !rules.contains(key)) return name + ": unknown field \"" + key + "\"";
    }
    for (const auto& [key, rule] : rules.items()) {
        const auto v = m.find(key);
        if (v == m.end()) {
            if (rule.value("optional", false)) continue;
            return name + ": missing field \"" + key + "\"";
        }
        const std::string at = name + "." + key;
        const std::string kind = rule.at("type").get<std::string>();
        if (kind == "integer" || kind == "number") {
            if (!v->is_number()) return at + ": expected a number";
            const double d = v->get<double>();
            if (!std::isfinite(d)) return at + ": expected a number";
            if (kind == "integer" && !v->is_number_integer()) return at + ": expected an integer";
            if (rule.contains("min") && rule.contains("max") &&
                (d < rule["min"].get<double>() || d > rule["max"].get<double>())) {
                return at + " = " + v->dump() + " is out of range (allowed " + rule["min"].dump() + ".." +
                       rule["max"].dump() + ")";
            }
        } else if (kind == "boolean") {
            if (!v->is_boolean()) return at + ": expected true or false";
        } else if (kind == "string") {
            if (!v->is_string()) return at + ": expected a string";
            const auto& s = v->get_ref<const std::string&>();
            if (rule.contains("maxLength") && s.size() > rule["maxLength"].get<size_t>()) {
                return at + ": longer than " + rule["maxLength"].dump();
            }
            if (rule.contains("enum")) {
                bool found = false;
                std::string allowed;
                for (const json& e : rule["enum"]) {
                    found = found || e == *v;
                    allowed += (allowed.empty() ? "" : ", ") + e.get<std::string>();
                }
                if (!found) return at + ": expected one of " + allowed;
            }
        } else if (kind == "array") {
            if (!v->is_array()) return at + ": expected an array";
            if (rule.contains("maxItems") && v->size() > rule["maxItems"].get<size_t>()) {
                return at + ": more than " + rule["maxItems"].dump() + " items";
            }
        } else if (kind == "object") {
            if (!v->is_object()) return at + ": expected an object";
        }
    }
    return std::nullopt;
}

}  // namespace feel::studio
