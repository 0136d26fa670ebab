#pragma once
// Command-line options: "--name value" pairs and flags, each taken once; whatever is left over is
// an error naming it.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace host {

class Args {
public:
    explicit Args(std::vector<std::string> words) : words_(std::move(words)) {}
    std::string take(const std::string& name, const std::string& fallback);
    bool flag(const std::string& name);
    // Positional argument (first word not starting with "--"), or throws naming `what`.
    std::string positional(const std::string& what);
    void finish() const;  // throws if anything was not understood

private:
    std::vector<std::string> words_;
};

VkExtent2D parseSize(const std::string& text, const std::string& option);
int parseCount(const std::string& text, const std::string& option);  // 1..100000
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace host
