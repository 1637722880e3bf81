// feel::protocol — a device's answer to one command, whole: its CommandStatus and, for a
// refusal, the field's name and the rule's sentence (docs/protocol.md, "Sequences and
// Command Status").
//
// Every input report fits one 64-byte interrupt packet, and a refusal's text (a 48-byte
// field name, a 96-byte rule) does not fit beside the status. So a device sends the text
// first, in CommandErrorTextReport parts with the refusal's sequence and command, and the
// CommandStatus last: the answer stays pushed (no round trip, no race between two
// refusals in flight), and every transport delivers a connection's input reports in order.
// error_text_parts() cuts an answer into those reports; CommandAnswerJoiner puts them back
// together on the host.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "feel/protocol/reports.hpp"

namespace feel::protocol {

// A CommandStatus with its error text. The text is NUL-padded, empty for a success.
struct CommandAnswer : CommandStatusReport {
    char field[kErrorFieldBytes] = {};
    char rule[kErrorRuleBytes] = {};

    [[nodiscard]] std::string_view field_text() const noexcept;
    [[nodiscard]] std::string_view rule_text() const noexcept;
};

// The text reports a device sends before a refusal's CommandStatus: part 0 (the field)
// always, parts 1 and 2 when the rule reaches into them. None for a success.
struct ErrorTextParts {
    std::array<CommandErrorTextReport, 3> parts{};
    std::size_t count = 0;
};
[[nodiscard]] ErrorTextParts error_text_parts(const CommandAnswer& answer) noexcept;

// The host's side: text parts are held until the CommandStatus they precede arrives.
// Parts for another sequence or command than the status (a device that sent none for
// this refusal) are not attached to it.
class CommandAnswerJoiner {
public:
    void add(const CommandErrorTextReport& part) noexcept;
    // The whole answer; forgets the parts held.
    [[nodiscard]] CommandAnswer finish(const CommandStatusReport& status) noexcept;

private:
    bool holding_ = false;
    uint32_t sequence_ = 0;
    ReportId command_ = ReportId::keep_alive;
    char field_[kErrorFieldBytes] = {};
    char rule_[kErrorRuleBytes] = {};
};

}  // namespace feel::protocol
