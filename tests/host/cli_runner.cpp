#include "cli_runner.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace cli_test {

const std::string& scratch() {
    static const std::string dir = [] {
        auto p = std::filesystem::temp_directory_path() /
                 ("lightscatter-cli-" + std::to_string(::getpid()));
        std::filesystem::create_directories(p);
        return p.string();
    }();
    return dir;
}

Result run(const std::string& arguments, const std::string& prefix) {
    const std::string command =
        "cd '" + scratch() + "' && " + prefix + " '" + LS_CLI + "' " + arguments + " 2>&1";
    Result r;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
    const int status = ::pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string xvfb(const std::string& screen) {
    return "xvfb-run -a -f .xvfb-authority -s '-screen 0 " + screen + "'";
}

std::string scene(const std::string& name) {
    return std::string(LS_SOURCE_DIR) + "/scenes/" + name + ".json";
}

bool exists(const std::string& path) {
    return std::filesystem::exists(std::filesystem::path(scratch()) / path);
}

std::string path(const std::string& name) {
    return (std::filesystem::path(scratch()) / name).string();
}

void writeFile(const std::string& name, const std::string& text) {
    std::ofstream(path(name)) << text;
}

void expectFailure(const Result& r, const std::string& fragment) {
    EXPECT_NE(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find(fragment), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_EQ(r.out.find("lightscatter: lightscatter:"), std::string::npos) << r.out;
}

void expectNoTemporaries() {
    for (const auto& e : std::filesystem::recursive_directory_iterator(scratch()))
        EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
}

}  // namespace cli_test
