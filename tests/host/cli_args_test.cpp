// Option parsing: numbers are range-checked words of digits (sscanf's %u and stoul wrapped
// 4294967297 to 1 and -1 to 4294967295), and an option given twice is called that, not unknown.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cli_args.h"
#include "error_line.h"
#include "terminal_text.h"

namespace {

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(HostCliArgs, WholeNumbersAreDigitsWithinTheirRange) {
    EXPECT_EQ(host::parseWhole("1", "--frames", 1, 100000), 1u);
    EXPECT_EQ(host::parseWhole("100000", "--frames", 1, 100000), 100000u);
    EXPECT_EQ(host::parseWhole("007", "--frames", 1, 100000), 7u);
    for (const char* bad : {"4294967297", "18446744073709551617", "-1", "+5", " 5", "5 ", "5x",
                            "0x10", "", "1e3", "5.0", "100001", "0"}) {
        EXPECT_EQ(errorOf([&] { host::parseWhole(bad, "--frames", 1, 100000); }),
                  std::string("--frames '") + bad + "' is not a whole number from 1 to 100000");
    }
    EXPECT_EQ(host::parseCount("42", "--frames"), 42);
}

TEST(HostCliArgs, SizesAreTwoWholeNumbers) {
    const VkExtent2D s = host::parseSize("640x360", "--size");
    EXPECT_EQ(s.width, 640u);
    EXPECT_EQ(s.height, 360u);
    for (const char* bad : {"4294967328x4294967314", "-32x18", "32x-18", "32x18x2", "32x", "x18",
                            "32", "32X18", "0x5", "16385x1", "32x18 ", "+32x18"}) {
        EXPECT_EQ(errorOf([&] { host::parseSize(bad, "--size"); }),
                  std::string("--size '") + bad +
                      "' is not WIDTHxHEIGHT with both whole numbers from 1 to 16384");
    }
}

TEST(HostCliArgs, RepeatedOptionsAreCalledRepeated) {
    host::Args size({"--size", "8x8", "--size", "9x9"});
    EXPECT_EQ(errorOf([&] { size.take("--size", ""); }), "option --size is given more than once");
    host::Args flag({"--json", "--json"});
    EXPECT_EQ(errorOf([&] { flag.flag("--json"); }), "option --json is given more than once");
    host::Args once({"--size", "8x8", "scene.json"});
    EXPECT_EQ(once.take("--size", ""), "8x8");
    EXPECT_EQ(once.positional("SCENE.json"), "scene.json");
    EXPECT_NO_THROW(once.finish());
    host::Args unknown({"--frobnicate"});
    EXPECT_EQ(errorOf([&] { unknown.finish(); }), "unknown option or argument '--frobnicate'");
}

// `render s.json --timings --out a.png` took "--out" as the timings' file and then called "a.png"
// unknown; a scene named "--ddash.json" could not be given at all (issue #22).
TEST(HostCliArgs, AValueNeverStartsWithTwoDashesAndTwoDashesEndTheOptions) {
    host::Args swallowed({"s.json", "--timings", "--out", "a.png"});
    const std::string e = errorOf([&] { swallowed.take("--timings", ""); });
    EXPECT_NE(e.find("option --timings needs a value, but the word after it is the option '--out'"),
              std::string::npos)
        << e;
    host::Args dashed({"--size", "8x8", "--", "--ddash.json"});
    EXPECT_EQ(dashed.take("--size", ""), "8x8");
    EXPECT_EQ(dashed.take("--out", "none"), "none");
    EXPECT_EQ(dashed.positional("SCENE.json"), "--ddash.json");
    EXPECT_NO_THROW(dashed.finish());
    host::Args notAnOption({"--", "--out", "x.png"});
    EXPECT_EQ(notAnOption.take("--out", "none"), "none");  // after "--", "--out" is a file name
    EXPECT_EQ(notAnOption.positional("SCENE.json"), "--out");
    EXPECT_EQ(errorOf([&] { notAnOption.finish(); }), "unexpected argument 'x.png' after \"--\"");
    host::Args negative({"--frames", "-1"});  // one dash is a value, refused by the number's rule
    EXPECT_EQ(negative.take("--frames", ""), "-1");
}

// The plugin's messages carry their own "lightscatter: ", to which main() added another.
TEST(HostErrorLine, OnePrefixAndOneLine) {
    EXPECT_EQ(host::errorLine("lightscatter: budget shadow-map size 1: must be in [2, 16384]"),
              "budget shadow-map size 1: must be in [2, 16384]");
    EXPECT_EQ(host::errorLine("lightscatter: lightscatter: x"), "x");
    EXPECT_EQ(host::errorLine("a.gltf: first\nsecond \n\n"), "a.gltf: first; second");
    EXPECT_EQ(host::errorLine("plain"), "plain");
}

// Whatever reaches the error line of a user's input (a path, a value) is one line of at most
// kMaxLineChars, its control characters escaped: a file named "t\e]0;PWNED\a.json" must not set the
// terminal's title, nor a megabyte of value make a megabyte of line.
TEST(HostErrorLine, ControlCharactersAreEscapedAndTheLineIsCut) {
    EXPECT_EQ(host::errorLine("t\x1b]0;PWNED\x07.json: does not exist"),
              "t\\u001b]0;PWNED\\u0007.json: does not exist");
    EXPECT_EQ(host::errorLine("a\tb\rc\x7f"), "a\\tb\\rc\\u007f");
    EXPECT_EQ(host::errorLine("C1 \xc2\x9b"
                              "2J, and \xc3\xa9 kept"),
              "C1 \\u009b2J, and \xc3\xa9 kept");
    const std::string line = host::errorLine("x.json: " + std::string(1000000, 'v'));
    EXPECT_EQ(line.size(), host::kMaxLineChars);
    EXPECT_EQ(line.substr(line.size() - 3), "...");
}
