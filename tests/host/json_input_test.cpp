// The one way the scene, --settings and benchmark files are parsed (scene/json_input.h): nesting
// capped while parsing, repeated keys refused, echoed values cut. The readers' own tests check the
// same rules through each reader (scene_test, settings_file_test, bench_motion_test).
#include <gtest/gtest.h>

#include <string>

#include "scene/json_input.h"

namespace {

using nlohmann::json;

// `levels` arrays within one another as the value of "slices".
std::string nested(size_t levels) {
    return R"({"slices": )" + std::string(levels, '[') + std::string(levels, ']') + "}";
}

std::string parseError(const std::string& text, host::JsonRules rules = {}) {
    try {
        (void)host::parseJson("f.json", text.data(), text.data() + text.size(), rules);
    } catch (const host::JsonInputError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        return m;
    }
    return "(accepted)";
}

TEST(JsonInput, NestingIsCappedWhileParsing) {
    // 63 arrays inside the top-level object: 64 levels, the most accepted.
    EXPECT_EQ(parseError(nested(host::kMaxJsonDepth - 1)), "(accepted)");
    for (size_t levels : {size_t{64}, size_t{30000}, size_t{100000}}) {
        SCOPED_TRACE(levels);
        const std::string m = parseError(nested(levels));
        EXPECT_EQ(m.rfind("f.json: slices[0][0][0]", 0), 0u) << m;
        EXPECT_NE(m.find(": arrays and objects nest more than 64 deep here (the most this reader "
                         "takes)"),
                  std::string::npos)
            << m;
        EXPECT_LE(m.size(), 200u) << m;
    }
    // Objects count as levels too, and the field is named by its keys.
    std::string objects;
    for (int i = 0; i < 100000; ++i) objects += R"({"a":)";
    objects += "1" + std::string(100000, '}');
    const std::string m = parseError(objects);
    EXPECT_EQ(m.rfind("f.json: a.a.a.a", 0), 0u) << m;
    EXPECT_LE(m.size(), 200u) << m;
}

TEST(JsonInput, RepeatedKeysAreRefusedWhereTheyAre) {
    EXPECT_EQ(parseError(R"({"slices": 1, "slices": 2})"),
              "f.json: key 'slices' appears twice in one object");
    EXPECT_EQ(parseError(R"({"camera": {"near": 1}, "lights": [{}, {"type": 1, "type": 2}]})"),
              "f.json: lights[1]: key 'type' appears twice in one object");
    // The same key in two objects is no repeat.
    EXPECT_EQ(parseError(R"({"a": {"x": 1}, "b": {"x": 1}, "c": [{"x": 1}, {"x": 2}]})"),
              "(accepted)");
    EXPECT_EQ(parseError(R"({"x": 1, "x": 2})", {.refuseDuplicateKeys = false}), "(accepted)");
}

// Three million empty objects in one array, 9 MB: nlohmann's callback parser, which the depth cap
// used, scanned the array after each object (80,000 objects took 2.6 s of CPU, quadrupling with
// each doubling: a million about 400 s, three million an hour). Read in one pass they take about a
// second; nothing here is timed, but a quadratic reader runs past test_host_scene's timeout of 300
// s (tests/host/CMakeLists.txt).
TEST(JsonInput, MillionsOfObjectsAreReadInOnePass) {
    std::string many = R"({"lights": [)";
    for (int i = 0; i < 3000000; ++i) many += i ? ",{}" : "{}";
    many += "]}";
    const json v = host::parseJson("f.json", many.data(), many.data() + many.size());
    EXPECT_EQ(v["lights"].size(), 3000000u);
    // The same in one object's keys, where each key is also checked against the object's others.
    std::string keys = "{";
    for (int i = 0; i < 300000; ++i) keys += (i ? ",\"" : "\"") + std::to_string(i) + "\":{}";
    keys += R"(,"7": 1})";
    EXPECT_EQ(parseError(keys), "f.json: key '7' appears twice in one object");
}

// The value read is the value written, whatever nests in what (the reader builds it itself).
TEST(JsonInput, TheValueReadIsTheTextsValue) {
    const std::string text =
        R"({"a": [1, {"b": null}, "x", 2.5, -3, true, 18446744073709551615], "c": {},)"
        R"( "e": [[], [{}], [[{"f": [false]}]]], "g": {"h": {"i": "j"}}})";
    const json v = host::parseJson("f.json", text.data(), text.data() + text.size());
    EXPECT_EQ(v, json::parse(text));
    EXPECT_EQ(v.dump(), json::parse(text).dump());
    EXPECT_TRUE(v["a"][6].is_number_unsigned());
    EXPECT_TRUE(v["a"][4].is_number_integer());
    const std::string scalar = "42";
    EXPECT_EQ(host::parseJson("f.json", scalar.data(), scalar.data() + scalar.size()), 42);
    // Malformed JSON is a discarded value where the rules ask for one, and the cap still throws.
    const std::string broken = R"({"a": [1, 2)";
    EXPECT_TRUE(host::parseJson("f.json", broken.data(), broken.data() + broken.size(),
                                {.malformedIsDiscarded = true})
                    .is_discarded());
    EXPECT_NE(parseError(nested(100), {.malformedIsDiscarded = true}).find("nest more than 64"),
              std::string::npos);
}

TEST(JsonInput, EchoedValuesAreCut) {
    EXPECT_EQ(host::echo(json::parse(R"([1, 2, "three", {"four": null}])")),
              R"([1,2,"three",{"four":null}])");
    json many = json::array();
    for (int i = 0; i < 100000; ++i) many.push_back(i);
    const std::string cut = host::echo(many);
    EXPECT_EQ(cut.size(), host::kMaxEchoChars);
    EXPECT_EQ(cut.substr(0, 10), "[0,1,2,3,4");
    EXPECT_EQ(cut.substr(cut.size() - 3), "...");
    EXPECT_EQ(host::echo(std::string(1 << 20, 'x')).size(), host::kMaxEchoChars);
    // A key or string quoted in a message stays on one line, and a cut never splits a character.
    EXPECT_EQ(host::echoText("a\nb\tc\x01"), "a\\nb\\tc\\u0001");
    std::string accents;
    for (int i = 0; i < 100; ++i) accents += "\xc3\xa9";  // é, two bytes each
    const std::string e = host::echoText(accents);
    EXPECT_LE(e.size(), host::kMaxEchoChars);
    EXPECT_EQ(e.substr(e.size() - 5), "\xc3\xa9...");
}

TEST(JsonInput, MalformedJsonNamesThePlaceAndCutsTheToken) {
    EXPECT_EQ(parseError(R"({"camera": })"),
              "f.json: malformed JSON at byte 12: [json.exception.parse_error.101] parse error at "
              "line 1, column 12: syntax error while parsing value - unexpected '}'; expected "
              "'[', '{', or a literal");
    EXPECT_EQ(parseError(R"({"near": 1e400})"),
              "f.json: malformed JSON: [json.exception.out_of_range.406] number overflow parsing "
              "'1e400'");
    // An unterminated string: nlohmann quotes all it read of it.
    const std::string m = parseError(R"({"name": ")" + std::string(1 << 20, 'x'));
    EXPECT_LE(m.size(), 300u) << m;
    EXPECT_NE(m.find("last read: '\"xxxxxxxx"), std::string::npos) << m;
    const std::string digits = parseError(R"({"near": 1)" + std::string(100000, '0') + "}");
    EXPECT_LE(digits.size(), 300u) << digits;
}

}  // namespace
