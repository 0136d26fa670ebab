#include "cli_args.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace host {

Args::Args(std::vector<std::string> words) {
    const auto end = std::find(words.begin(), words.end(), "--");
    words_.assign(words.begin(), end);
    if (end != words.end()) rest_.assign(end + 1, words.end());
}

void Args::refuseRepeats(const std::string& name) const {
    if (std::count(words_.begin(), words_.end(), name) > 1)
        throw std::runtime_error("option " + name + " is given more than once");
}

std::string Args::take(const std::string& name, const std::string& fallback) {
    refuseRepeats(name);
    for (size_t i = 0; i < words_.size(); ++i) {
        if (words_[i] != name) continue;
        if (i + 1 >= words_.size()) throw std::runtime_error("option " + name + " needs a value");
        std::string v = words_[i + 1];
        if (v.rfind("--", 0) == 0)
            throw std::runtime_error(
                "option " + name + " needs a value, but the word after it is the option '" + v +
                "' (a value never starts with \"--\"; give a file starting with it "
                "as ./" +
                v + ")");
        words_.erase(words_.begin() + static_cast<long>(i),
                     words_.begin() + static_cast<long>(i) + 2);
        return v;
    }
    return fallback;
}

bool Args::flag(const std::string& name) {
    refuseRepeats(name);
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
    if (!rest_.empty()) {
        std::string v = rest_.front();
        rest_.erase(rest_.begin());
        return v;
    }
    throw std::runtime_error("missing " + what);
}

void Args::finish() const {
    if (!words_.empty()) throw std::runtime_error("unknown option or argument '" + words_[0] + "'");
    if (!rest_.empty())
        throw std::runtime_error("unexpected argument '" + rest_[0] + "' after \"--\"");
}

namespace {

// Digits only, within [lo, hi]; std::from_chars alone would accept a leading '-' and stop quietly
// at the first non-digit.
bool wholeNumber(std::string_view text, uint32_t lo, uint32_t hi, uint32_t& out) {
    if (text.empty() ||
        !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return false;
    uint64_t v = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (error != std::errc() || end != text.data() + text.size() || v < lo || v > hi) return false;
    out = static_cast<uint32_t>(v);
    return true;
}

}  // namespace

uint32_t parseWhole(const std::string& text, const std::string& option, uint32_t lo, uint32_t hi) {
    uint32_t v = 0;
    if (!wholeNumber(text, lo, hi, v))
        throw std::runtime_error(option + " '" + text + "' is not a whole number from " +
                                 std::to_string(lo) + " to " + std::to_string(hi));
    return v;
}

VkExtent2D parseSize(const std::string& text, const std::string& option) {
    const size_t x = text.find('x');
    uint32_t w = 0, h = 0;
    if (x == std::string::npos || !wholeNumber(std::string_view(text).substr(0, x), 1, 16384, w) ||
        !wholeNumber(std::string_view(text).substr(x + 1), 1, 16384, h))
        throw std::runtime_error(option + " '" + text +
                                 "' is not WIDTHxHEIGHT with both whole numbers from 1 to 16384");
    return {w, h};
}

int parseCount(const std::string& text, const std::string& option) {
    return static_cast<int>(parseWhole(text, option, 1, 100000));
}

}  // namespace host
