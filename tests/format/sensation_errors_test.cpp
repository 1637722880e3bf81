// Every way a sensation file can be wrong gets a message that names the file, the
// sensation, the field path and what is allowed (docs/sensation-format.md, "Errors").
// The expected messages are written out in full from the documented format; ranges are
// the primer's (§6.3, §6.6, §8).
#include <filesystem>
#include <string>

#include "format_test_util.hpp"

namespace feel::format::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// A valid sine on x, to which the cases add one mistake.
std::string sine_with(std::string_view extra, std::string_view periodic = R"("magnitude": 2000, "period_us": 10000)") {
    return file_with(R"({"type": "sine", "duration_us": 2000000, "axes": ["x"], )" + std::string(extra) +
                     R"("periodic": {)" + std::string(periodic) + "}}");
}

// --- JSON itself ---

TEST(SensationFileErrors, MalformedJsonGivesLineAndColumn) {
    const std::string text = "{\"format\": \"feel/1\",\n  \"sensations\": {,}}";
    // Line 2, the comma is the 18th character: two spaces, "sensations" in quotes (12),
    // the colon, a space, the brace, the comma.
    EXPECT_THAT(error_of(text), StartsWith("bad.json: invalid JSON at line 2, column 18: syntax error"));
}

TEST(SensationFileErrors, EmptyAndTruncatedInput) {
    EXPECT_THAT(error_of(""), StartsWith("bad.json: invalid JSON at line 1, column "));
    EXPECT_THAT(error_of("{\"format\": \"feel/1\""), HasSubstr("invalid JSON at line 1"));
    EXPECT_THAT(error_of("{} trailing"), HasSubstr("invalid JSON at line 1"));
    EXPECT_THAT(error_of("{\"format\": \"feel/1\" /* comment */}"), HasSubstr("invalid JSON"));
}

TEST(SensationFileErrors, NumbersTooLargeForADoubleNameTheirField) {
    // nlohmann stops at a number no double holds; the reader names the field like for any
    // value that does not fit (before, "invalid JSON at line 2, column 6: number overflow").
    EXPECT_EQ(error_of("{\"format\":\n 1e999}"), R"(bad.json: "format" must be "feel/1", found 1e999)");
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "phase": 1e400)")),
              R"(bad.json: sensation "hum": periodic.phase: 1e400 is beyond the range of every field (the format's numbers are 64-bit integers))");
    // A 100 000-digit integer, quoted by its start and its length.
    const std::string huge(100'000, '7');
    EXPECT_EQ(error_of(sine_with(R"("gain": )" + huge + ", ")),
              R"(bad.json: sensation "hum": gain: 777777777777777777777777... (100000 characters) does not fit in a 64-bit integer)");
    EXPECT_EQ(error_of(file_with(R"({"effects": [{"type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}},
        {"type": "ramp", "duration_us": 1000, "axes": ["x"], "ramp": {"start": -1e400}}]})")),
              R"(bad.json: sensation "hum": effects[1].ramp.start: -1e400 is beyond the range of every field (the format's numbers are 64-bit integers))");
    EXPECT_EQ(error_of(file_with(R"({"type": "force_profile", "duration_us": 1000, "axes": ["x"],
        "custom": {"sample_period_us": 1000, "samples": [1, 2, )" + huge + "]}}")),
              R"(bad.json: sensation "hum": custom.samples[2]: 777777777777777777777777... (100000 characters) does not fit in a 64-bit integer)");
    // Where no number belongs, the usual message.
    EXPECT_EQ(error_of(file_with("1e400")),
              R"(bad.json: sensation "hum": expected an object (one effect, or {"effects": [...]} for a compound), found 1e400)");
    // Long literals that a double holds are shortened in messages too.
    EXPECT_EQ(error_of(sine_with(R"("gain": 0.)" + std::string(1000, '0') + "1, ")),
              R"(bad.json: sensation "hum": gain: expected an integer, found 0.0000000000000000000000... (1003 characters))");
}

TEST(SensationFileErrors, InvalidUtf8IsInvalidJson) {
    const std::string text = file_with(R"({"description": "caf)" + std::string("\xC3\x28") + R"(", "type": "sine"})");
    EXPECT_THAT(error_of(text), StartsWith("bad.json: invalid JSON at line 1"));
}

TEST(SensationFileErrors, TopLevelMustBeAnObject) {
    EXPECT_EQ(error_of("[1, 2]"), "bad.json: expected a JSON object at the top level, found an array");
    EXPECT_EQ(error_of("42"), "bad.json: expected a JSON object at the top level, found 42");
}

TEST(SensationFileErrors, FormatMember) {
    EXPECT_EQ(error_of(R"({"format": "feel/2", "sensations": {}})"),
              R"(bad.json: "format" must be "feel/1", found the string "feel/2")");
    EXPECT_EQ(error_of(R"({"format": 1, "sensations": {}})"), R"(bad.json: "format" must be "feel/1", found 1)");
    EXPECT_EQ(error_of(R"({"sensations": {}})"), R"(bad.json: missing "format": "feel/1")");
    EXPECT_EQ(error_of(R"({"format": "feel/1", "version": 2, "sensations": {}})"),
              R"(bad.json: unknown top-level field "version" (allowed: format, sensations))");
}

TEST(SensationFileErrors, SensationsMember) {
    EXPECT_EQ(error_of(R"({"format": "feel/1", "sensations": {}})"),
              R"(bad.json: "sensations" is empty: a file defines at least one sensation)");
    EXPECT_EQ(error_of(R"({"format": "feel/1"})"),
              R"(bad.json: missing "sensations" (an object of named sensations))");
    EXPECT_EQ(error_of(R"({"format": "feel/1", "sensations": []})"),
              R"(bad.json: "sensations" must be an object of named sensations, found an array)");
}

TEST(SensationFileErrors, DuplicateKeysAreDetected) {
    // nlohmann's DOM would keep the last one silently; the reader refuses.
    const std::string twice = R"({"format": "feel/1", "sensations": {
        "hum": {"type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}},
        "hum": {"type": "constant", "duration_us": 2000, "axes": ["x"], "constant": {"magnitude": 2}}}})";
    EXPECT_EQ(error_of(twice), R"(bad.json: duplicate key "hum" in the object at /sensations)");
    EXPECT_EQ(error_of(sine_with(R"("gain": 1, "gain": 2, )")),
              R"(bad.json: duplicate key "gain" in the object at /sensations/hum)");
    EXPECT_EQ(error_of(R"({"format": "feel/1", "format": "feel/1"})"),
              R"(bad.json: duplicate key "format" in the object at the top level)");
}

TEST(SensationFileErrors, DeeplyNestedGarbageIsRefusedWithoutCrashing) {
    const std::string deep = file_with(R"({"type": "sine", "x": )" + std::string(100000, '[') + "]}");
    EXPECT_THAT(error_of(deep), StartsWith("bad.json: nesting deeper than 32 arrays and objects at /sensations/hum/x/0/0/"));
    EXPECT_THAT(error_of(std::string(1'000'000, '{')), HasSubstr("invalid JSON"));  // a key is missing first
    // Refused at its first byte, before any nesting.
    EXPECT_EQ(error_of(std::string(1'000'000, '[')), "bad.json: expected a JSON object at the top level, found an array");
}

// --- sensations ---

TEST(SensationFileErrors, SensationNames) {
    EXPECT_EQ(error_of(file_with(R"({"type": "sine"})", "after burner")),
              R"(bad.json: sensation name "after burner" is not valid (use 1 to 64 letters, digits, '_', '-' or '.'))");
    EXPECT_THAT(error_of(file_with(R"({"type": "sine"})", "")), HasSubstr(R"(sensation name "" is not valid)"));
    EXPECT_THAT(error_of(file_with(R"({"type": "sine"})", std::string(65, 'a'))), HasSubstr("is not valid"));
}

TEST(SensationFileErrors, SensationShape) {
    EXPECT_EQ(error_of(file_with("7")),
              R"(bad.json: sensation "hum": expected an object (one effect, or {"effects": [...]} for a compound), found 7)");
    EXPECT_EQ(error_of(file_with(R"({"description": 5, "type": "sine"})")),
              R"(bad.json: sensation "hum": description: expected a string, found 5)");
    EXPECT_EQ(error_of(file_with(R"({"effects": []})")),
              R"(bad.json: sensation "hum": effects: a compound sensation needs at least one effect)");
    EXPECT_EQ(error_of(file_with(R"({"effects": {}})")),
              R"(bad.json: sensation "hum": effects: expected an array of effects, found an object)");
    EXPECT_EQ(error_of(file_with(R"({"effects": [3]})")),
              R"(bad.json: sensation "hum": effects[0]: expected an effect object, found 3)");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "effects": []})")),
              R"(bad.json: sensation "hum": unknown field "type" in a compound sensation (allowed here: description, effects; each effect's fields go inside "effects"))");
}

TEST(SensationFileErrors, CompoundErrorsNameTheEffect) {
    const std::string text = file_with(R"({"effects": [
        {"type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}},
        {"type": "sine", "duration_us": 1000, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 10, "phase": 36000}}]})",
                                       "gun_burst");
    EXPECT_EQ(error_of(text, "fx.json"),
              R"(fx.json: sensation "gun_burst": effects[1].periodic.phase = 36000 is out of range (allowed 0..35999))");
    // A description belongs to the sensation, not to one of its effects.
    const std::string described = file_with(R"({"effects": [
        {"description": "x", "type": "constant", "duration_us": 1000, "axes": ["x"], "constant": {"magnitude": 1}}]})");
    EXPECT_THAT(error_of(described), StartsWith(R"(bad.json: sensation "hum": effects[0]: unknown field "description" (allowed here: type, )"));
    const std::string nested = file_with(R"({"effects": [{"effects": []}]})");
    EXPECT_THAT(error_of(nested), StartsWith(R"(bad.json: sensation "hum": effects[0].type: required field is missing)"));
}

// --- effect fields ---

TEST(SensationFileErrors, UnknownType) {
    const std::string msg = error_of(file_with(R"({"type": "sinus", "axes": ["x"]})"));
    EXPECT_THAT(msg, StartsWith(R"(bad.json: sensation "hum": type: "sinus" is not an effect type (the types are: spring, damper, )"));
    EXPECT_THAT(msg, HasSubstr("sweep_saw_down, force_profile, ramp, dynamic_recoil"));
    EXPECT_THAT(msg, HasSubstr("dynamic_paddle)"));
    EXPECT_EQ(error_of(file_with(R"({"type": 3})")),
              R"(bad.json: sensation "hum": type: expected the name of an effect type, found 3)");
    EXPECT_THAT(error_of(file_with(R"({"axes": ["x"]})")),
                StartsWith(R"(bad.json: sensation "hum": type: required field is missing)"));
}

TEST(SensationFileErrors, UnknownFieldIsNamed) {
    EXPECT_EQ(error_of(sine_with(R"("colour": "red", )")),
              R"(bad.json: sensation "hum": unknown field "colour" (allowed here: description, type, duration_us, start_delay_us, iterations, axes, direction, gain, trigger_button, trigger_repeat_interval_us, envelope, periodic))");
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "frequency": 100)")),
              R"(bad.json: sensation "hum": periodic: unknown field "frequency" (allowed here: magnitude, offset, period_us, phase))");
    // A sweep field in a plain periodic wave is not a field of that block.
    EXPECT_THAT(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "sweep_sense": "clockwise")")),
                HasSubstr(R"(periodic: unknown field "sweep_sense")"));
    EXPECT_THAT(error_of(sine_with(R"("envelope": {"impulse_level": 1, "settle_time_us": 1, "attack": 2}, )")),
                HasSubstr(R"(envelope: unknown field "attack" (allowed here: impulse_level, settle_time_us, fade_level, fade_time_us))"));
}

TEST(SensationFileErrors, AnEmptyOrOddKeyIsQuoted) {
    EXPECT_THAT(error_of(sine_with(R"("": 1, )")), StartsWith(R"(bad.json: sensation "hum": unknown field "" (allowed here: )"));
    EXPECT_THAT(error_of(sine_with(R"("a\nb": 1, )")), StartsWith(R"(bad.json: sensation "hum": unknown field "a\nb" )"));
}

TEST(SensationFileErrors, BlockOfAnotherType) {
    EXPECT_EQ(error_of(sine_with(R"("constant": {"magnitude": 5}, )")),
              R"(bad.json: sensation "hum": constant: block "constant" does not apply to type "sine" (a sine takes "periodic"))");
    EXPECT_EQ(error_of(file_with(R"({"type": "angle_spring", "duration_us": 1, "axes": ["x", "y"], "periodic": {}})")),
              R"(bad.json: sensation "hum": periodic: block "periodic" does not apply to type "angle_spring" (an angle_spring takes "conditions"))");
}

TEST(SensationFileErrors, MissingRequiredFields) {
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})")),
              R"(bad.json: sensation "hum": duration_us: required field is missing (1..65000000 microseconds or "infinite"))");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "periodic": {"magnitude": 1, "period_us": 1}})")),
              R"(bad.json: sensation "hum": axes: required field is missing (e.g. ["x", "y"]))");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": ["x"]})")),
              R"(bad.json: sensation "hum": periodic: required field is missing (a sine takes its parameters in "periodic"))");
    EXPECT_EQ(error_of(sine_with("", R"("period_us": 10000)")),
              R"(bad.json: sensation "hum": periodic.magnitude: required field is missing)");
    EXPECT_EQ(error_of(sine_with(R"("envelope": {"impulse_level": 5000}, )")),
              R"(bad.json: sensation "hum": envelope.settle_time_us: required field is missing)");
}

TEST(SensationFileErrors, WrongJsonType) {
    EXPECT_EQ(error_of(sine_with(R"("gain": "loud", )")),
              R"(bad.json: sensation "hum": gain: expected an integer, found the string "loud")");
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": [1], "period_us": 10000)")),
              R"(bad.json: sensation "hum": periodic.magnitude: expected an integer, found an array)");
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": null, "period_us": 10000)")),
              R"(bad.json: sensation "hum": periodic.magnitude: expected an integer, found null)");
    EXPECT_EQ(error_of(sine_with(R"("start_delay_us": true, )")),
              R"(bad.json: sensation "hum": start_delay_us: expected an integer, found true)");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": "x", "periodic": {}})")),
              R"(bad.json: sensation "hum": axes: expected an array of axis names, found the string "x")");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": ["x"], "periodic": 5})")),
              R"(bad.json: sensation "hum": periodic: expected an object, found 5)");
    const std::string wall = R"({"type": "axis_wall", "duration_us": 1, "axes": ["x"], "wall": {"hardness": 1, "sense": "up"}})";
    EXPECT_EQ(error_of(file_with(wall)),
              R"(bad.json: sensation "hum": wall.sense: expected "positive" or "negative", found the string "up")");
    const std::string clip =
        R"({"type": "axis_wall", "duration_us": 1, "axes": ["x"], "wall": {"hardness": 1, "sense": "positive", "clipping": 1}})";
    EXPECT_EQ(error_of(file_with(clip)), R"(bad.json: sensation "hum": wall.clipping: expected true or false, found 1)");
}

TEST(SensationFileErrors, NonIntegerNumbers) {
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "phase": 1.5)")),
              R"(bad.json: sensation "hum": periodic.phase: expected an integer, found 1.5)");
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 1e4)")),
              R"(bad.json: sensation "hum": periodic.period_us: expected an integer, found 1e4)");
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000.0, "period_us": 10000)")),
              R"(bad.json: sensation "hum": periodic.magnitude: expected an integer, found 2000.0)");
}

TEST(SensationFileErrors, IntegersTooWide) {
    // Beyond int64: refused before any range check.
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 99999999999999999999)")),
              R"(bad.json: sensation "hum": periodic.period_us: 99999999999999999999 does not fit in a 64-bit integer)");
    EXPECT_EQ(error_of(sine_with(R"("start_delay_us": -9223372036854775809, )")),
              R"(bad.json: sensation "hum": start_delay_us: -9223372036854775809 does not fit in a 64-bit integer)");
    // Beyond int32 for an int32 field: the range error quotes the file's value, unclamped.
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "phase": 5000000000)")),
              R"(bad.json: sensation "hum": periodic.phase = 5000000000 is out of range (allowed 0..35999))");
    EXPECT_EQ(error_of(sine_with(R"("gain": -4294967296, )")),
              R"(bad.json: sensation "hum": gain = -4294967296 is out of range (allowed 0..10000))");
    EXPECT_EQ(error_of(sine_with(R"("trigger_button": 2147483648, )")),
              R"(bad.json: sensation "hum": trigger_button = 2147483648 is out of range (allowed 1..32))");
    // int64 fields keep the value itself.
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 9223372036854775807)")),
              R"(bad.json: sensation "hum": periodic.period_us = 9223372036854775807 is out of range (allowed 1..65000000))");
    // Force-profile samples are int16 in memory; the file's value is still the one quoted.
    const std::string profile = R"({"type": "force_profile", "duration_us": 1000, "axes": ["x"],
        "custom": {"sample_period_us": 100, "samples": [0, 70000]}})";
    EXPECT_EQ(error_of(file_with(profile)),
              R"(bad.json: sensation "hum": custom.samples[1] = 70000 is out of range (allowed -10000..10000))");
}

TEST(SensationFileErrors, ValuesOutOfRange) {
    EXPECT_EQ(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "phase": 36000)")),
              R"(bad.json: sensation "hum": periodic.phase = 36000 is out of range (allowed 0..35999))");
    EXPECT_EQ(error_of(sine_with(R"("envelope": {"impulse_level": 10001, "settle_time_us": 30000}, )")),
              R"(bad.json: sensation "hum": envelope.impulse_level = 10001 is out of range (allowed 0..10000))");
    const std::string spring = R"({"type": "spring", "duration_us": "infinite", "axes": ["x", "y"], "conditions": [
        {"pos_coefficient": 6000, "neg_coefficient": 6000},
        {"pos_coefficient": 6000, "neg_coefficient": 6000, "deadband": -1}]})";
    EXPECT_EQ(error_of(file_with(spring, "stiff_stick")),
              R"(bad.json: sensation "stiff_stick": conditions[1].deadband = -1 is out of range (allowed 0..10000))");
    const std::string law = R"({"type": "dynamic_control_law", "duration_us": 1, "axes": ["x"], "dynamic": {
        "control_law": [{"mass": 0, "k_pos": 1, "k_neg": 1}]}})";
    EXPECT_EQ(error_of(file_with(law)),
              R"(bad.json: sensation "hum": dynamic.control_law[0].mass = 0 is out of range (allowed 1..10000))");
}

TEST(SensationFileErrors, DurationAndIterationsMayBeInfinite) {
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 0, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})")),
              R"(bad.json: sensation "hum": duration_us = 0 is out of range (allowed 1..65000000 or "infinite"))");
    // The engine's sentinel for "infinite" is not a way to write it.
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": -1, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})")),
              R"(bad.json: sensation "hum": duration_us = -1 is out of range (allowed 1..65000000 or "infinite"))");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": "forever", "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})")),
              R"(bad.json: sensation "hum": duration_us: expected an integer or "infinite", found the string "forever")");
    EXPECT_EQ(error_of(sine_with(R"("iterations": 0, )")),
              R"(bad.json: sensation "hum": iterations = 0 is out of range (allowed 1..255 or "infinite"))");
    EXPECT_EQ(error_of(sine_with(R"("iterations": -1, )")),
              R"(bad.json: sensation "hum": iterations = -1 is out of range (allowed 1..255 or "infinite"))");
    EXPECT_EQ(error_of(sine_with(R"("iterations": 2.5, )")),
              R"(bad.json: sensation "hum": iterations: expected an integer or "infinite", found 2.5)");
    EXPECT_EQ(error_of(file_with(R"({"type": "ramp", "duration_us": "infinite", "axes": ["x"], "ramp": {"start": 0, "end": 1}})")),
              R"(bad.json: sensation "hum": duration_us: ramp, smart_pop and the sweep waves need a finite duration: they are shaped over it)");
}

TEST(SensationFileErrors, Axes) {
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": [], "periodic": {}})")),
              R"(bad.json: sensation "hum": axes: 0 axes is out of range (allowed 1..6))");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": ["x","y","z","rx","ry","rz","x"], "periodic": {}})")),
              R"(bad.json: sensation "hum": axes: 7 axes is out of range (allowed 1..6))");
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": ["x", "w"], "periodic": {}})")),
              R"(bad.json: sensation "hum": axes[1]: expected one of "x", "y", "z", "rx", "ry", "rz", found the string "w")");
    const std::string twice = R"({"type": "sweep_sine", "duration_us": 1, "axes": ["x", "x"], "periodic": {
        "magnitude": 1, "period_us": 1, "sweep_start_angle": 0, "sweep_end_angle": 0, "sweep_sense": "clockwise"}})";
    EXPECT_EQ(error_of(file_with(twice)),
              R"(bad.json: sensation "hum": axes[1]: an axis may appear only once in an effect's axes)");
}

TEST(SensationFileErrors, Direction) {
    auto two_axis_sine = [](std::string_view direction) {
        return file_with(R"({"type": "sine", "duration_us": 1, "axes": ["x", "y"], "direction": )" + std::string(direction) +
                         R"(, "periodic": {"magnitude": 1, "period_us": 1}})");
    };
    EXPECT_EQ(error_of(two_axis_sine(R"({"polar": 0, "cartesian": [1, 0]})")),
              R"(bad.json: sensation "hum": direction: expected an object with exactly one of "polar", "cartesian", "spherical" or "moments", found 2 members)");
    EXPECT_EQ(error_of(two_axis_sine("9000")),
              R"(bad.json: sensation "hum": direction: expected an object with exactly one of "polar", "cartesian", "spherical" or "moments", found 9000)");
    EXPECT_EQ(error_of(two_axis_sine(R"({"compass": 0})")),
              R"(bad.json: sensation "hum": direction: unknown direction form "compass" (allowed: polar, cartesian, spherical, moments))");
    EXPECT_EQ(error_of(two_axis_sine(R"({"cartesian": [1, 0, 0]})")),
              R"(bad.json: sensation "hum": direction.cartesian: found 3 components for 2 axes (one component per axis))");
    EXPECT_EQ(error_of(two_axis_sine(R"({"cartesian": [1, 0, 0, 0]})")),
              R"(bad.json: sensation "hum": direction.cartesian: 4 components is out of range (allowed 1..3, one per axis))");
    EXPECT_EQ(error_of(two_axis_sine(R"({"cartesian": [0, 0]})")),
              R"(bad.json: sensation "hum": direction.cartesian: the zero vector names no direction)");
    EXPECT_EQ(error_of(two_axis_sine(R"({"spherical": [0]})")),
              R"(bad.json: sensation "hum": direction.spherical: expected [azimuth, elevation], found 1 values)");
    EXPECT_EQ(error_of(two_axis_sine(R"({"polar": 36000})")),
              R"(bad.json: sensation "hum": direction.polar = 36000 is out of range (allowed 0..35999))");
    EXPECT_EQ(error_of(two_axis_sine(R"({"polar": "north"})")),
              R"(bad.json: sensation "hum": direction.polar: expected an integer, found the string "north")");
    // §6.5: a wave on several axes must say which way it pushes.
    EXPECT_EQ(error_of(file_with(R"({"type": "sine", "duration_us": 1, "axes": ["x", "y"], "periodic": {"magnitude": 1, "period_us": 1}})")),
              R"(bad.json: sensation "hum": direction: a wave on several axes needs a direction (polar, cartesian, spherical or moments))");
}

TEST(SensationFileErrors, Trigger) {
    EXPECT_EQ(error_of(sine_with(R"("trigger_button": 33, )")),
              R"(bad.json: sensation "hum": trigger_button = 33 is out of range (allowed 1..32))");
    EXPECT_EQ(error_of(sine_with(R"("trigger_button": "hat5", )")),
              R"(bad.json: sensation "hum": trigger_button: expected a button number 1..32 or "hat1".."hat4", found the string "hat5")");
    EXPECT_EQ(error_of(sine_with(R"("trigger_button": [1], )")),
              R"(bad.json: sensation "hum": trigger_button: expected a button number 1..32 or "hat1".."hat4", found an array)");
    EXPECT_EQ(error_of(sine_with(R"("trigger_repeat_interval_us": 100000, )")),
              R"(bad.json: sensation "hum": trigger_repeat_interval_us: a repeat interval needs a trigger button to repeat on)");
    EXPECT_EQ(error_of(sine_with(R"("trigger_button": 1, "trigger_repeat_interval_us": 65000001, )")),
              R"(bad.json: sensation "hum": trigger_repeat_interval_us = 65000001 is out of range (allowed 0..65000000))");
}

TEST(SensationFileErrors, EnvelopeOnlyWhereTheTypeSupportsIt) {
    const std::string text = R"({"type": "smart_pop", "duration_us": 20000, "axes": ["x"],
        "envelope": {"impulse_level": 1, "settle_time_us": 1}, "constant": {"magnitude": 1}})";
    EXPECT_EQ(error_of(file_with(text)),
              R"(bad.json: sensation "hum": envelope: only vector_force, constant, the periodic and sweep waves, force_profile and ramp take an envelope (§6.4))");
}

TEST(SensationFileErrors, BlockArrays) {
    const std::string one_for_two = R"({"type": "damper", "duration_us": 1, "axes": ["x", "y"], "conditions": [
        {"pos_coefficient": 1, "neg_coefficient": 1}]})";
    EXPECT_EQ(error_of(file_with(one_for_two)),
              R"(bad.json: sensation "hum": conditions: found 1 blocks, expected 2 (one per axis))");
    const std::string angle_spring = R"({"type": "angle_spring", "duration_us": 1, "axes": ["x", "y"], "direction": {"polar": 0},
        "conditions": [{"pos_coefficient": 1, "neg_coefficient": 1}, {"pos_coefficient": 1, "neg_coefficient": 1}]})";
    EXPECT_EQ(error_of(file_with(angle_spring)),
              R"(bad.json: sensation "hum": conditions: found 2 blocks, expected 1 (one for the whole plane))");
    const std::string not_array = R"({"type": "spring", "duration_us": 1, "axes": ["x"], "conditions": {"pos_coefficient": 1}})";
    EXPECT_EQ(error_of(file_with(not_array)),
              R"(bad.json: sensation "hum": conditions: expected an array of 1 blocks (one per axis), found an object)");
    const std::string law = R"({"type": "dynamic_control_law", "duration_us": 1, "axes": ["x", "y"], "dynamic": {
        "control_law": [{"mass": 1, "k_pos": 1, "k_neg": 1}]}})";
    EXPECT_EQ(error_of(file_with(law)),
              R"(bad.json: sensation "hum": dynamic.control_law: found 1 blocks, expected 2 (one per axis))");
    const std::string no_law = R"({"type": "dynamic_control_law", "duration_us": 1, "axes": ["x"], "dynamic": {}})";
    EXPECT_EQ(error_of(file_with(no_law)),
              R"(bad.json: sensation "hum": dynamic.control_law: required field is missing (one block per axis))");
    const std::string law_field = R"({"type": "dynamic_control_law", "duration_us": 1, "axes": ["x"], "dynamic": {
        "control_law": [{"mass": 1, "k_pos": 1, "k_neg": 1, "spring": 3}]}})";
    EXPECT_THAT(error_of(file_with(law_field)),
                HasSubstr(R"(dynamic.control_law[0]: unknown field "spring" (allowed here: mass, k_pos, k_neg, b, vel_init)"));
    const std::string recoil = R"({"type": "dynamic_recoil", "duration_us": 1, "axes": ["x", "y"], "dynamic": {
        "blast_direction": 0, "blast_intensity": 1, "dynamic_mass": 1, "blast_resonance": 1, "blast_decay": 0, "play": 3}})";
    EXPECT_EQ(error_of(file_with(recoil)),
              R"(bad.json: sensation "hum": dynamic: unknown field "play" (dynamic_inertia has it; allowed here: blast_direction, blast_intensity, dynamic_mass, blast_resonance, blast_decay, interim_reporting))");
}

TEST(SensationFileErrors, AFieldOfASiblingTypeNamesTheTypesThatHaveIt) {
    // §3.7 gives walls a clipping option that §3.8's barriers do not have: the error says
    // which types have the field, so the author sees they picked the wrong sibling.
    const std::string barrier = R"({"type": "axis_barrier", "duration_us": 1, "axes": ["x"], "barrier": {
        "pos_hardness": 1, "neg_hardness": 1, "thickness": 10, "clipping": true}})";
    EXPECT_EQ(error_of(file_with(barrier)),
              R"(bad.json: sensation "hum": barrier: unknown field "clipping" (axis_wall and angle_wall have it; allowed here: pos_hardness, neg_hardness, thickness, offset, offset_mode, surface_friction, surface_texture))");
    // The wall's sense is the wall's alone; its offset_mode is the barrier's too (§3.8).
    EXPECT_THAT(error_of(file_with(R"({"type": "angle_barrier", "duration_us": 1, "axes": ["x", "y"], "barrier": {
        "pos_hardness": 1, "neg_hardness": 1, "thickness": 10, "angle": 0, "sense": "positive"}})")),
                HasSubstr(R"(barrier: unknown field "sense" (axis_wall and angle_wall have it; allowed here: )"));
    EXPECT_EQ(params_of(file_with(R"({"type": "axis_barrier", "duration_us": 1, "axes": ["x"], "barrier": {
        "pos_hardness": 1, "neg_hardness": 1, "thickness": 10, "offset_mode": "relative"}})")).barrier.offset_mode,
              OffsetMode::relative);
    // A sweep's sense in a plain sine: the five sweeps (§4.2.d) have it.
    EXPECT_THAT(error_of(sine_with("", R"("magnitude": 2000, "period_us": 10000, "sweep_sense": "clockwise")")),
                HasSubstr(R"(periodic: unknown field "sweep_sense" (sweep_sine, sweep_square, sweep_triangle, sweep_saw_up and sweep_saw_down have it; allowed here: )"));
    // A field no type has gets no such note.
    EXPECT_THAT(error_of(file_with(R"({"type": "axis_barrier", "duration_us": 1, "axes": ["x"], "barrier": {
        "pos_hardness": 1, "neg_hardness": 1, "thickness": 10, "softness": 1}})")),
                HasSubstr(R"(barrier: unknown field "softness" (allowed here: )"));
}

TEST(SensationFileErrors, AConditionWithADirectionTakesOneBlock) {
    // §3.1: with a direction, one block applied along it; a block per axis takes no direction.
    EXPECT_EQ(error_of(file_with(R"({"type": "spring", "duration_us": 1, "axes": ["x", "y"], "direction": {"polar": 0},
        "conditions": [{"pos_coefficient": 1, "neg_coefficient": 1}, {"pos_coefficient": 1, "neg_coefficient": 1}]})")),
              R"(bad.json: sensation "hum": conditions: found 2 blocks, expected 1 (with a direction, one block applied along it; per-axis blocks take no direction))");
    EXPECT_EQ(error_of(file_with(R"({"type": "friction", "duration_us": 1, "axes": ["x"], "direction": {"cartesian": [1]},
        "conditions": [{"pos_coefficient": 1, "neg_coefficient": 1}]})")),
              R"(bad.json: sensation "hum": direction: a condition on one axis acts along that axis and takes no direction; a direction applies one condition block along it on 2 or more axes)");
    EXPECT_EQ(error_of(file_with(R"({"type": "inertia", "duration_us": 1, "axes": ["x", "y"], "direction": {"spherical": [0, 0]},
        "conditions": [{"pos_coefficient": 1, "neg_coefficient": 1}]})")),
              R"(bad.json: sensation "hum": direction.spherical: a spherical direction needs the axes x, y and z (§6.5.c))");
}

TEST(SensationFileErrors, AxisWallHasNoAngle) {
    const std::string text = R"({"type": "axis_wall", "duration_us": 1, "axes": ["x"], "wall": {"hardness": 1, "sense": "positive", "angle": 0}})";
    EXPECT_EQ(error_of(file_with(text)),
              R"(bad.json: sensation "hum": wall: unknown field "angle" (angle_barrier and angle_wall have it; allowed here: hardness, sense, offset, offset_mode, surface_friction, surface_texture, clipping))");
}

TEST(SensationFileErrors, ForceProfileSamples) {
    auto profile = [](std::string_view custom, std::string_view axes = R"(["x", "y"])") {
        return file_with(R"({"type": "force_profile", "duration_us": 1000, "axes": )" + std::string(axes) +
                         R"(, "custom": {)" + std::string(custom) + "}}");
    };
    EXPECT_EQ(error_of(profile(R"("channels": 2, "sample_period_us": 100, "samples": [1, 2, 3])")),
              R"(bad.json: sensation "hum": custom.samples: 3 samples is not a multiple of custom.channels = 2 (samples are interleaved by channel, §6.6.d))");
    EXPECT_EQ(error_of(profile(R"("channels": 2, "sample_period_us": 100, "samples": [])")),
              R"(bad.json: sensation "hum": custom.samples: 0 samples is out of range (allowed 1..65535))");
    EXPECT_EQ(error_of(profile(R"("channels": 2, "sample_period_us": 100)")),
              R"(bad.json: sensation "hum": custom.samples: required field is missing (the force values, interleaved by channel))");
    EXPECT_EQ(error_of(profile(R"("channels": 2, "sample_period_us": 100, "samples": [1, "2"])")),
              R"(bad.json: sensation "hum": custom.samples[1]: expected an integer, found the string "2")");
    EXPECT_EQ(error_of(profile(R"("channels": 0, "sample_period_us": 100, "samples": [1])")),
              R"(bad.json: sensation "hum": custom.channels = 0 is out of range (allowed 1..6))");
    EXPECT_EQ(error_of(profile(R"("channels": 3, "sample_period_us": 100, "samples": [1, 2, 3])")),
              R"(bad.json: sensation "hum": custom.channels: a profile with several channels drives one axis per channel: custom.channels must equal the number of axes)");
    EXPECT_EQ(error_of(profile(R"("sample_period_us": 100, "sample_count": 2, "samples": [1, 2])", R"(["x"])")),
              R"(bad.json: sensation "hum": custom: unknown field "sample_count" (allowed here: channels, sample_period_us, samples))");
    std::string many = R"("sample_period_us": 100, "samples": [0)";
    for (int i = 0; i < 65535; ++i) many += ",0";
    EXPECT_EQ(error_of(profile(many + "]", R"(["x"])")),
              R"(bad.json: sensation "hum": custom.samples: more than 65535 samples (allowed 1..65535))");  // refused while read
}

TEST(SensationFileErrors, LoadNamesThePath) {
    const std::filesystem::path missing = std::filesystem::path(FEEL_BINARY_DIR) / "no-such-dir" / "missing.feel.json";
    try {
        (void)load_sensation_file(missing);
        ADD_FAILURE() << "loaded a missing file";
    } catch (const FormatError& e) {
        EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open: No such file or directory");
    }
    // A directory opens on Linux but cannot be read.
    try {
        (void)load_sensation_file(FEEL_SOURCE_DIR);
        ADD_FAILURE() << "loaded a directory";
    } catch (const FormatError& e) {
        EXPECT_THAT(std::string(e.what()), StartsWith(std::string(FEEL_SOURCE_DIR) + ": cannot "));
    }
}

TEST(SensationFileErrors, LoadReportsParseErrorsWithThePath) {
    const std::filesystem::path path = std::filesystem::path(FEEL_BINARY_DIR) / "format_test_bad.feel.json";
    {
        std::FILE* f = std::fopen(path.string().c_str(), "wb");
        ASSERT_NE(f, nullptr);
        const std::string text = file_with(R"({"type": "sine", "duration_us": 0, "axes": ["x"], "periodic": {"magnitude": 1, "period_us": 1}})");
        std::fwrite(text.data(), 1, text.size(), f);
        std::fclose(f);
    }
    try {
        (void)load_sensation_file(path);
        ADD_FAILURE() << "loaded an invalid file";
    } catch (const FormatError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path.string() + R"(: sensation "hum": duration_us = 0 is out of range (allowed 1..65000000 or "infinite"))");
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace feel::format::test
