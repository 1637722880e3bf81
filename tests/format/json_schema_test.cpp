// docs/feel-1.schema.json is what format::json_schema() generates from the field table
// (regenerate with `feel schema > docs/feel-1.schema.json`), and the schema speaks of the
// fields the format's documentation lists.
#include <fstream>
#include <iterator>
#include <string>

#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

using ::testing::HasSubstr;

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(JsonSchema, ThePublishedSchemaIsUpToDate) {
    const std::string published = read_file(FEEL_SOURCE_DIR "/docs/feel-1.schema.json");
    ASSERT_FALSE(published.empty()) << "docs/feel-1.schema.json is missing";
    EXPECT_EQ(published, json_schema())
        << "docs/feel-1.schema.json is stale: regenerate it with `feel schema > docs/feel-1.schema.json`";
}

// Names from docs/sensation-format.md and the primer (§6.3, §6.4), not from the table.
TEST(JsonSchema, NamesTheDocumentedFieldsTypesAndAliases) {
    const std::string schema = json_schema();
    for (const char* name : {"\"feel/1\"", "\"trigger_repeat_interval_us\"", "\"impulse_level\"", "\"attack_level\"",
                             "\"settle_time_us\"", "\"attack_time_us\"", "\"fade_level\"", "\"dynamic_recoil\"",
                             "\"angle_spring\"", "\"force_profile\"", "\"samples\"", "\"control_law\"", "\"hat4\"",
                             "\"infinite\"", "\"unevaluatedProperties\"", "2020-12"}) {
        EXPECT_THAT(schema, HasSubstr(name));
    }
}

}  // namespace
}  // namespace feel::format::test
