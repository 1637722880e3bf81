// A command's answer cut into input reports and joined again (command_answer.hpp).
#include "feel/protocol/command_answer.hpp"

#include <cstring>

namespace feel::protocol {
namespace {

std::string_view padded_text(const char* text, std::size_t size) noexcept {
    return std::string_view(text, strnlen(text, size));
}

}  // namespace

std::string_view CommandAnswer::field_text() const noexcept { return padded_text(field, sizeof field); }
std::string_view CommandAnswer::rule_text() const noexcept { return padded_text(rule, sizeof rule); }

ErrorTextParts error_text_parts(const CommandAnswer& answer) noexcept {
    ErrorTextParts out;
    if (answer.code == ErrorCode::ok) return out;
    const std::size_t rule_length = answer.rule_text().size();
    const std::size_t rule_parts = (rule_length + kErrorTextPartBytes - 1) / kErrorTextPartBytes;
    out.count = 1 + rule_parts;
    for (std::size_t i = 0; i < out.count; ++i) {
        CommandErrorTextReport& part = out.parts[i];
        part.sequence = answer.sequence;
        part.command = answer.command;
        part.part = static_cast<uint8_t>(i);
        const char* from = i == 0 ? answer.field : answer.rule + (i - 1) * kErrorTextPartBytes;
        std::memcpy(part.text, from, kErrorTextPartBytes);
    }
    return out;
}

void CommandAnswerJoiner::add(const CommandErrorTextReport& part) noexcept {
    if (!holding_ || part.sequence != sequence_ || part.command != command_) {
        holding_ = true;
        sequence_ = part.sequence;
        command_ = part.command;
        std::memset(field_, 0, sizeof field_);
        std::memset(rule_, 0, sizeof rule_);
    }
    if (part.part == 0) {
        std::memcpy(field_, part.text, kErrorTextPartBytes);
    } else if (part.part <= 2) {
        std::memcpy(rule_ + (part.part - 1) * kErrorTextPartBytes, part.text, kErrorTextPartBytes);
    }
}

CommandAnswer CommandAnswerJoiner::finish(const CommandStatusReport& status) noexcept {
    CommandAnswer answer;
    static_cast<CommandStatusReport&>(answer) = status;
    if (holding_ && status.code != ErrorCode::ok && status.sequence == sequence_ && status.command == command_) {
        std::memcpy(answer.field, field_, sizeof field_);
        std::memcpy(answer.rule, rule_, sizeof rule_);
    }
    holding_ = false;
    return answer;
}

}  // namespace feel::protocol
