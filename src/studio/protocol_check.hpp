// feel::studio — checks a browser's message against the protocol's one description.
//
// The description is studio/src/protocol/schema.ts, written by the front end's build as
// protocol.json into the assets embedded in feel (so the server and the browser check the
// same rules). Every message is a JSON object with a "type" the schema lists, only the
// fields the schema gives that type, each of its kind and in its range.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace feel::studio {

class ProtocolSchema {
public:
    // The embedded protocol.json. Throws std::runtime_error if it is missing or broken
    // (a build problem, not a user's).
    static const ProtocolSchema& embedded();
    explicit ProtocolSchema(nlohmann::json description);

    // Why `message` breaks the rules for its sender ("client" or "server"), or nothing.
    [[nodiscard]] std::optional<std::string> problem(std::string_view side, const nlohmann::json& message) const;

private:
    nlohmann::json description_;
};

}  // namespace feel::studio
