#pragma once
// A shader's build asked for by its defines (shaders/embed/spirv_variants.h): the builds are listed
// once, in shaders/CMakeLists.txt, and one that is not built is a clear error naming the shader and
// the defines.
#include <vulkan/vulkan.h>

#include <initializer_list>
#include <vector>

#include "composite_variant.h"
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

// A shader that composites: its own defines, then its target's.
inline rg::ShaderCode pickCompositeShader(const ls_spirv::ShaderVariants& shader,
                                          std::initializer_list<ls_spirv::Define> own,
                                          const CompositeVariant& target) {
    std::vector<ls_spirv::Define> defines(own);
    defines.push_back({"LS_COLOR_RGBA32F", target.color == VK_FORMAT_R32G32B32A32_SFLOAT});
    defines.push_back({"LS_WITH_OUTPUT", target.output});
    defines.push_back({"LS_SPLIT", target.split});
    return spirvOf(shader.pick(defines));
}

}  // namespace ls
