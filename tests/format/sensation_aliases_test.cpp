// DirectInput's and evdev's names for the envelope's attack (attack_level, attack_time_us)
// are accepted as aliases of the primer's impulse_level and settle_time_us (§6.4); the
// writer keeps the primer's names; giving a field under both names is an error naming both.
#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

using ::testing::HasSubstr;

std::string sine_with_envelope(const std::string& envelope) {
    return file_with(R"({"type": "sine", "duration_us": 100000, "axes": ["x"], "envelope": {)" + envelope +
                     R"(}, "periodic": {"magnitude": 2000, "period_us": 10000}})");
}

TEST(SensationAliases, AttackLevelAndTimeReadAsImpulseLevelAndSettleTime) {
    const EffectParams p = params_of(sine_with_envelope(R"("attack_level": 7000, "attack_time_us": 25000, "fade_level": 10)"));
    EXPECT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope.impulse_level, 7000);
    EXPECT_EQ(p.envelope.settle_time_us, 25'000);
    EXPECT_EQ(p.envelope.fade_level, 10);
    // One alias and one primer name mix freely.
    const EffectParams q = params_of(sine_with_envelope(R"("impulse_level": 6000, "attack_time_us": 1000)"));
    EXPECT_EQ(q.envelope.impulse_level, 6000);
    EXPECT_EQ(q.envelope.settle_time_us, 1000);
}

TEST(SensationAliases, TheWriterKeepsThePrimersNames) {
    const std::string text = sine_with_envelope(R"("attack_level": 7000, "attack_time_us": 25000)");
    const std::string written = write_sensation_file(parse_sensation_file(text, "alias.json"));
    EXPECT_THAT(written, HasSubstr("\"impulse_level\": 7000"));
    EXPECT_THAT(written, HasSubstr("\"settle_time_us\": 25000"));
    EXPECT_THAT(written, ::testing::Not(HasSubstr("attack")));
}

TEST(SensationAliases, BothNamesAtOnceIsAnErrorNamingBoth) {
    EXPECT_THAT(error_of(sine_with_envelope(R"("impulse_level": 1, "attack_level": 1, "settle_time_us": 1)")),
                HasSubstr(R"(both "impulse_level" and its alias "attack_level" are given)"));
    EXPECT_THAT(error_of(sine_with_envelope(R"("impulse_level": 1, "settle_time_us": 1, "attack_time_us": 2)")),
                HasSubstr(R"(both "settle_time_us" and its alias "attack_time_us")"));
}

TEST(SensationAliases, AnAliasIsCheckedAndNamedLikeItsField) {
    // §6.4: the impulse level is a force 0..10000; the error names the name the file used.
    EXPECT_THAT(error_of(sine_with_envelope(R"("attack_level": 10001, "settle_time_us": 1)")),
                HasSubstr("attack_level"));
    EXPECT_THAT(error_of(sine_with_envelope(R"("attack_level": 1)")), HasSubstr("settle_time_us"));
}

}  // namespace
}  // namespace feel::format::test
