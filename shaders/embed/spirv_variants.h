#pragma once
// The builds of one GLSL source, as cmake/EmbedShaders.cmake generates them
// (<name>_<stage>_variants.h): C++ asks for a build by its defines, so the list of builds is
// written once, in shaders/CMakeLists.txt, and a build asked for but not made is one clear error.
#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ls_spirv {

struct Define {
    const char* name;
    int value;
};

struct Variant {
    const char* name;                 // the build's name in shaders/CMakeLists.txt ("" for none)
    std::span<const Define> defines;  // as given to glslang; an absent one is 0
    std::span<const uint32_t> words;
};

class ShaderVariants {
  public:
    template <size_t N>
    constexpr ShaderVariants(const char* source, const Variant (&variants)[N])
        : source_(source), variants_(variants) {}

    const char* source() const { return source_; }
    std::span<const Variant> variants() const { return variants_; }

    // The build with exactly these defines. Each define any build of the source has must be given
    // (so a request cannot forget one), and none other (so a misspelt one is caught).
    const Variant& pick(std::span<const Define> asked) const {
        for (const Define& d : asked)
            if (!known(d.name)) fail(asked, std::string("no build of it has the define ") + d.name);
        for (const Variant& v : variants_)
            for (const Define& d : v.defines)
                if (!given(asked, d.name))
                    fail(asked, std::string("the define ") + d.name + " is not given");
        for (const Variant& v : variants_) {
            bool same = true;
            for (const Define& d : asked) same = same && valueIn(v.defines, d.name) == d.value;
            if (same) return v;
        }
        fail(asked, "no build has these defines (add it to shaders/CMakeLists.txt)");
    }
    const Variant& pick(std::initializer_list<Define> asked) const {
        return pick(std::span<const Define>(asked.begin(), asked.size()));
    }

  private:
    static int valueIn(std::span<const Define> defines, std::string_view name) {
        for (const Define& d : defines)
            if (name == d.name) return d.value;
        return 0;
    }
    static bool given(std::span<const Define> asked, std::string_view name) {
        for (const Define& d : asked)
            if (name == d.name) return true;
        return false;
    }
    bool known(std::string_view name) const {
        for (const Variant& v : variants_)
            if (given(v.defines, name)) return true;
        return false;
    }
    [[noreturn]] void fail(std::span<const Define> asked, const std::string& why) const {
        std::string defines;
        for (const Define& d : asked)
            defines +=
                (defines.empty() ? "" : ",") + std::string(d.name) + "=" + std::to_string(d.value);
        throw std::logic_error(std::string("shader ") + source_ + " with [" + defines +
                               "]: " + why);
    }

    const char* source_;
    std::span<const Variant> variants_;
};

}  // namespace ls_spirv
