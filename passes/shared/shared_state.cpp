#include "shared_state.h"

namespace ls {

rg::Specialization ScatterSpec::constants() const {
    rg::Specialization s;
    s.set(0, static_cast<int32_t>(light));
    s.set(1, static_cast<int32_t>(isotropicMie ? 1 : hazyMie ? 2 : 0));
    s.set(3, lightColor);
    s.set(4, bilinearShadow);
    s.set(5, simplifiedModel);
    return s;
}

std::string ScatterSpec::key() const {
    return "L" + std::to_string(static_cast<int>(light)) +
           (isotropicMie ? "i"
            : hazyMie    ? "h"
                         : "c") +
           (minMaxTrees ? "T" : "t") + (lightColor ? "C" : "c") + (bilinearShadow ? "B" : "b") +
           (simplifiedModel ? "+simplified" : "") + (cubeShadow ? "+cube" : "");
}

const rg::Pipeline& PipelineLibrary::compute(const std::string& key, rg::ShaderCode code,
                                             const std::vector<rg::Binding>& bindings,
                                             uint32_t pushBytes, const rg::Specialization& spec) {
    auto it = pipelines_.find(key);
    if (it == pipelines_.end())
        it = pipelines_.emplace(key, rg::Pipeline::compute(device_, key, code, bindings, pushBytes, spec))
                 .first;
    return it->second;
}

const rg::Pipeline& PipelineLibrary::graphics(const std::string& key,
                                              const rg::GraphicsPipelineDesc& desc) {
    auto it = pipelines_.find(key);
    if (it == pipelines_.end())
        it = pipelines_.emplace(key, rg::Pipeline::graphics(device_, key, desc)).first;
    return it->second;
}

}  // namespace ls
