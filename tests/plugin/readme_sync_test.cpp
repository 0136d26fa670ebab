// README.md quotes the integration example; this keeps the quote and the compiled code identical.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string read(const std::string& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

}  // namespace

TEST(Readme, QuotesTheCompiledIntegrationExample) {
    const std::string code = read(LS_SOURCE_DIR "/tests/plugin/readme_example.cpp");
    const std::string readme = read(LS_SOURCE_DIR "/README.md");
    const std::string marker = "    // [readme-example]\n";
    const size_t a = code.find(marker);
    ASSERT_NE(a, std::string::npos);
    const size_t b = code.find(marker, a + marker.size());
    ASSERT_NE(b, std::string::npos);
    // The README indents the block by 4 spaces less (it is outside the function).
    std::stringstream in(code.substr(a + marker.size(), b - a - marker.size()));
    std::string line, block;
    while (std::getline(in, line)) block += (line.size() >= 4 ? line.substr(4) : line) + "\n";
    EXPECT_NE(readme.find(block), std::string::npos) << "README.md does not quote:\n" << block;
}
