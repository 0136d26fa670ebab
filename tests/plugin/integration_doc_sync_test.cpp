// docs/integration.md quotes compiled code; this keeps each quote and the code identical.
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

// The block between two `    // [marker]` lines of `file`, less the 4 spaces of indentation the
// function body adds (the page quotes it outside any function).
std::string block(const std::string& file, const std::string& name) {
    const std::string code = read(LS_SOURCE_DIR "/" + file);
    const std::string marker = "    // [" + name + "]\n";
    const size_t a = code.find(marker);
    const size_t b = a == std::string::npos ? a : code.find(marker, a + marker.size());
    if (b == std::string::npos) {
        ADD_FAILURE() << file << " has no block marked [" << name << "]";
        return {};
    }
    std::stringstream in(code.substr(a + marker.size(), b - a - marker.size()));
    std::string line, out;
    while (std::getline(in, line)) out += (line.size() >= 4 ? line.substr(4) : line) + "\n";
    return out;
}

}  // namespace

TEST(IntegrationDoc, QuotesTheCompiledIntegrationExample) {
    const std::string quoted = block("tests/plugin/readme_example.cpp", "integration-example");
    const std::string page = read(LS_SOURCE_DIR "/docs/integration.md");
    EXPECT_NE(page.find(quoted), std::string::npos) << "docs/integration.md does not quote:\n"
                                                    << quoted;
}

TEST(IntegrationDoc, QuotesTheCompiledDeviceCreation) {
    const std::string quoted =
        block("tests/consumer/engine/headless_engine.cpp", "integration-device");
    const std::string page = read(LS_SOURCE_DIR "/docs/integration.md");
    EXPECT_NE(page.find(quoted), std::string::npos) << "docs/integration.md does not quote:\n"
                                                    << quoted;
}

// The quick start quotes hello_shafts, the example CI builds and runs.
TEST(IntegrationDoc, QuotesHelloShafts) {
    const std::string page = read(LS_SOURCE_DIR "/docs/integration.md");
    for (const char* name : {"device", "frame"}) {
        const std::string quoted = block("examples/hello_shafts/hello_shafts.cpp", name);
        EXPECT_NE(page.find(quoted), std::string::npos)
            << "docs/integration.md does not quote " << name << ":\n"
            << quoted;
    }
}
