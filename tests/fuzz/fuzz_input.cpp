#include "fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

namespace fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path& folder() {
    static const fs::path dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        fs::path d =
            fs::path(tmp && *tmp ? tmp : "/tmp") / ("ls-fuzz-" + std::to_string(::getpid()));
        fs::remove_all(d);
        fs::create_directories(d);
        for (const char* sub : {"scenes", "scenes/hard"}) {
            std::error_code ec;
            for (const auto& entry : fs::directory_iterator(fs::path(LS_SOURCE_DIR) / sub, ec)) {
                if (entry.is_regular_file())
                    fs::create_symlink(entry.path(), d / entry.path().filename(), ec);
            }
        }
        return d;
    }();
    return dir;
}

}  // namespace

const std::string& inputFolder() {
    static const std::string path = folder().string();
    return path;
}

const std::string& writeInput(const uint8_t* data, size_t size, const std::string& name) {
    static std::map<std::string, std::string> paths;
    auto [it, fresh] = paths.try_emplace(name);
    if (fresh) it->second = (folder() / name).string();
    std::ofstream out(it->second, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    out.close();
    if (!out) {
        std::fprintf(stderr, "fuzz: cannot write %s\n", it->second.c_str());
        std::abort();
    }
    return it->second;
}

void checkRefusal(const std::string& message, const std::string& path, size_t limit) {
    const char* broken = nullptr;
    if (message.rfind(path + ": ", 0) != 0)
        broken = "does not start with the file's path";
    else if (message.find('\n') != std::string::npos)
        broken = "is more than one line";
    else if (message.size() > path.size() + limit)
        broken = "is too long";
    if (!broken) return;
    std::fprintf(stderr, "fuzz: the refusal %s (%zu characters): %.2000s\n", broken, message.size(),
                 message.c_str());
    std::abort();
}

}  // namespace fuzz
