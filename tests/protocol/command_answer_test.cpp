// A refusal's answer cut into Command Error Text parts and joined again on the host
// (command_answer.hpp): every part is an encodable input report within one interrupt
// packet, the parts come back as the text they were cut from, and parts for another
// command are never attached.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"

namespace feel::protocol {
namespace {

CommandAnswer refusal(uint32_t sequence, const char* field, const std::string& rule) {
    CommandAnswer a;
    a.sequence = sequence;
    a.command = ReportId::set_periodic;
    a.block = 3;
    a.code = ErrorCode::invalid_parameter;
    std::strncpy(a.field, field, sizeof a.field - 1);
    std::strncpy(a.rule, rule.c_str(), sizeof a.rule - 1);
    return a;
}

TEST(CommandAnswer, ARefusalTravelsAsTextPartsThenItsStatus) {
    const std::string rule(90, 'r');  // reaches into the third part (48 + 42 bytes)
    const CommandAnswer sent = refusal(77, "set_periodic.magnitude", rule);
    const ErrorTextParts parts = error_text_parts(sent);
    ASSERT_EQ(parts.count, 3u);
    CommandAnswerJoiner joiner;
    for (std::size_t i = 0; i < parts.count; ++i) {
        EXPECT_EQ(parts.parts[i].part, i);
        const std::vector<uint8_t> bytes = encode(parts.parts[i]);
        EXPECT_LE(bytes.size(), static_cast<std::size_t>(kInterruptPacketBytes));
        AnyReport back;
        ASSERT_TRUE(decode(bytes, back).ok());
        joiner.add(std::get<CommandErrorTextReport>(back));
    }
    const CommandAnswer got = joiner.finish(sent);
    EXPECT_EQ(got.field_text(), "set_periodic.magnitude");
    EXPECT_EQ(got.rule_text(), rule);
    EXPECT_EQ(got.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(got.block, 3);
}

TEST(CommandAnswer, AShortRuleOrNoneSendsFewerParts) {
    EXPECT_EQ(error_text_parts(refusal(1, "report.id", "")).count, 1u);
    EXPECT_EQ(error_text_parts(refusal(1, "report.id", std::string(48, 'x'))).count, 2u);
    CommandAnswer ok;
    ok.code = ErrorCode::ok;
    EXPECT_EQ(error_text_parts(ok).count, 0u);
}

TEST(CommandAnswer, PartsOfAnotherCommandAreNotAttached) {
    CommandAnswerJoiner joiner;
    const CommandAnswer first = refusal(5, "set_effect.gain", "");
    joiner.add(error_text_parts(first).parts[0]);
    const CommandAnswer other = refusal(6, "set_effect.type", "");
    const CommandAnswer got = joiner.finish(other);  // its text never came
    EXPECT_EQ(got.sequence, 6u);
    EXPECT_EQ(got.field_text(), "");
    // And what was held is forgotten once a status arrives.
    EXPECT_EQ(joiner.finish(first).field_text(), "");
}

}  // namespace
}  // namespace feel::protocol
