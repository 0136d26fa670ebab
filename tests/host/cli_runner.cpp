#include "cli_runner.h"

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>

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

std::string scene(const std::string& name) {
    return std::string(LS_SOURCE_DIR) + "/scenes/" + name + ".json";
}

bool exists(const std::string& path) {
    return std::filesystem::exists(std::filesystem::path(scratch()) / path);
}

}  // namespace cli_test
