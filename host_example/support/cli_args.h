#pragma once
// Command-line options: "--name value" pairs and flags, each taken once; whatever is left over is
// an error naming it.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace host {

// A word "--" ends the options: every word after it is positional, so that a file named
// "--ddash.json" can be given.
class Args {
  public:
    explicit Args(std::vector<std::string> words);
    // The value after `name`, or `fallback` when absent; throws when `name` is given twice or has
    // no value. A value never starts with "--": `--timings --out a.png` is --timings without its
    // value, not a file named "--out".
    std::string take(const std::string& name, const std::string& fallback);
    bool flag(const std::string& name);  // throws when given twice
    // Positional argument (the first word not starting with "--", else the first after "--"), or
    // throws naming `what`.
    std::string positional(const std::string& what);
    void finish() const;  // throws if anything was not understood

  private:
    void refuseRepeats(const std::string& name) const;
    std::vector<std::string> words_;  // before "--"
    std::vector<std::string> rest_;   // after "--": positional only
};

// A whole number in [lo, hi], written as decimal digits alone: no sign, no spaces, nothing after
// it. Throws naming `option` and the range, so that "-1" or "4294967297" never wraps around.
uint32_t parseWhole(const std::string& text, const std::string& option, uint32_t lo, uint32_t hi);
VkExtent2D parseSize(const std::string& text, const std::string& option);  // WxH, 1..16384 each
int parseCount(const std::string& text, const std::string& option);        // 1..100000

}  // namespace host
