#pragma once
// The JSON files a user names (scenes, --settings files, benchmark configurations) are all parsed
// one way: nesting is capped while parsing, a key given twice in one object is refused, and what an
// error message quotes of the file is cut to a stated length. A hostile or broken file is then one
// short error line, never a stack overflow in a recursive walk of the parsed value (nlohmann's
// dump(), copies and comparisons recurse once per level) nor a message the size of the file.
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace host {

// Arrays and objects within one another. No scene, settings or benchmark file of this project
// nests more than 4 deep, no glTF file of it or of Debian's assimp-testmodels more than 8; 64 is
// far below what a recursive walk of the value can take on any thread's stack (100,000 levels
// overflowed the main thread's 8 MiB).
constexpr size_t kMaxJsonDepth = 64;
// The most characters an error message quotes of one value, key or string from a file, the "..."
// that marks a cut included.
constexpr size_t kMaxEchoChars = 80;
// A path longer than this is refused before it is looked up (Linux's PATH_MAX); shorter ones are
// quoted whole, as they name the file.
constexpr size_t kMaxPathChars = 4096;

// The shortest text that reads back as the same value: "0.1" for 0.1f, not "0.100000001490116"
// (how an error message quotes a number from a file).
template <class T>
std::string shortestText(T v) {
    char text[64];
    const auto result = std::to_chars(text, text + sizeof text, v);
    return std::string(text, result.ptr);
}

// "PATH: <what>", one line.
class JsonInputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct JsonRules {
    // nlohmann keeps the last of two equal keys; in a file a person writes, a repeated key is as
    // likely a mistake as a misspelt one. glTF files are written by tools and keep their own rules.
    bool refuseDuplicateKeys = true;
    // Malformed JSON gives a discarded value instead of an error (the glTF loader leaves the
    // message to tinygltf); the nesting cap and the rule above still throw.
    bool malformedIsDiscarded = false;
};

// Parses [begin, end), the contents of `path`. Throws JsonInputError for malformed JSON (where, and
// nlohmann's reason), for arrays and objects nested more than kMaxJsonDepth deep (naming the field
// where it happens) and for a key given twice in one object (naming the key and the object).
nlohmann::json parseJson(const std::string& path, const char* begin, const char* end,
                         JsonRules rules = {});

// readInputFile(path, what, cap), then parseJson. A file that cannot be read throws JsonInputError.
nlohmann::json readJsonFile(const std::string& path, const std::string& what, uint64_t cap);

// A value as compact JSON text, at most kMaxEchoChars characters (a cut one ends in "..."), built
// without writing out more of a long array, object or string than that.
std::string echo(const nlohmann::json& value);

// A key or a string from a file as it reads, control characters escaped as JSON writes them (so the
// message stays one line), at most `limit` characters (a cut one ends in "...").
std::string echoText(const std::string& text, size_t limit = kMaxEchoChars);

}  // namespace host
