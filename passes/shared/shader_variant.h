#pragma once
// A shader's build asked for by its defines (shaders/embed/spirv_variants.h): the builds are listed
// once, in shaders/CMakeLists.txt, and one that is not built is a clear error naming the shader and
// the defines.
#include <vulkan/vulkan.h>

#include <initializer_list>
#include <vector>

#include "rendergraph/pipeline.h"
#include "spirv_variants.h"

namespace ls {

inline rg::ShaderCode spirvOf(const ls_spirv::Variant& v) {
    return {v.words.data(), v.words.size_bytes()};
}

inline rg::ShaderCode pickShader(const ls_spirv::ShaderVariants& shader,
                                 std::initializer_list<ls_spirv::Define> defines) {
    return spirvOf(shader.pick(defines));
}

// A shader that composites into the engine's color (shaders/shared/composite_into.glsl): its own
// defines, then the color's format and whether the Lin output image is written.
inline rg::ShaderCode pickCompositeShader(const ls_spirv::ShaderVariants& shader,
                                          std::initializer_list<ls_spirv::Define> own,
                                          VkFormat color, bool withOutput) {
    std::vector<ls_spirv::Define> defines(own);
    defines.push_back({"LS_COLOR_RGBA32F", color == VK_FORMAT_R32G32B32A32_SFLOAT});
    defines.push_back({"LS_WITH_OUTPUT", withOutput});
    return spirvOf(shader.pick(defines));
}

}  // namespace ls
