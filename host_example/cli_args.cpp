#include "cli_args.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace host {

std::string Args::take(const std::string& name, const std::string& fallback) {
    for (size_t i = 0; i < words_.size(); ++i) {
        if (words_[i] != name) continue;
        if (i + 1 >= words_.size()) throw std::runtime_error("option " + name + " needs a value");
        std::string v = words_[i + 1];
        words_.erase(words_.begin() + static_cast<long>(i), words_.begin() + static_cast<long>(i) + 2);
        return v;
    }
    return fallback;
}

bool Args::flag(const std::string& name) {
    for (size_t i = 0; i < words_.size(); ++i)
        if (words_[i] == name) {
            words_.erase(words_.begin() + static_cast<long>(i));
            return true;
        }
    return false;
}

std::string Args::positional(const std::string& what) {
    for (size_t i = 0; i < words_.size(); ++i)
        if (words_[i].rfind("--", 0) != 0) {
            std::string v = words_[i];
            words_.erase(words_.begin() + static_cast<long>(i));
            return v;
        }
    throw std::runtime_error("missing " + what);
}

void Args::finish() const {
    if (!words_.empty()) throw std::runtime_error("unknown option or argument '" + words_[0] + "'");
}

VkExtent2D parseSize(const std::string& text, const std::string& option) {
    unsigned w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &tail) != 2 || w == 0 || h == 0 ||
        w > 16384 || h > 16384)
        throw std::runtime_error(option + " '" + text +
                                 "' is not WIDTHxHEIGHT with both between 1 and 16384");
    return {w, h};
}

int parseCount(const std::string& text, const std::string& option) {
    unsigned n = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%u%c", &n, &tail) != 1 || n < 1 || n > 100000)
        throw std::runtime_error(option + " '" + text + "' is not a whole number from 1 to 100000");
    return static_cast<int>(n);
}

void writeTextFile(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".partial";
    {
        std::ofstream f(tmp, std::ios::binary);
        if (!f) throw std::runtime_error(path + ": cannot open for writing");
        f << text;
        if (!f) throw std::runtime_error(path + ": write failed");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot move into place: " + ec.message());
    }
}

}  // namespace host
