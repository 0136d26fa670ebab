#include "shared_state.h"

#include "shaders/shared/bindings.h"

namespace ls {

rg::Specialization ScatterSpec::constants() const {
    rg::Specialization s;
    s.set(LS_SPEC_LIGHT_TYPE, static_cast<int32_t>(light));
    s.set(LS_SPEC_MIE_PHASE, static_cast<int32_t>(phase));
    s.set(LS_SPEC_LIGHT_COLOR, lightColor);
    s.set(LS_SPEC_BILINEAR_SHADOW, bilinearShadow);
    s.set(LS_SPEC_SIMPLIFIED_MODEL, simplifiedModel);
    // Only a non-uniform medium names the constant: a homogeneous frame's pipelines are keyed
    // and built exactly as before media existed.
    if (media != 0) s.set(LS_SPEC_MEDIA, static_cast<int32_t>(media));
    return s;
}

rg::Specialization ScatterSpec::mediaConstants() const {
    rg::Specialization s;
    if (media != 0) s.set(LS_SPEC_MEDIA, static_cast<int32_t>(media));
    return s;
}

const rg::Pipeline& PipelineLibrary::compute(const std::string& name, rg::ShaderCode code,
                                             const std::vector<rg::Binding>& bindings,
                                             uint32_t pushBytes, const rg::Specialization& spec) {
    rg::PipelineKey key = rg::pipelineKey(code, bindings, pushBytes, spec);
    std::lock_guard lock(mutex_);
    auto it = pipelines_.find(key);
    if (it == pipelines_.end())
        it = pipelines_
                 .emplace(std::move(key),
                          rg::Pipeline::compute(device_, name, code, bindings, pushBytes, spec))
                 .first;
    return it->second;
}

const rg::Pipeline& PipelineLibrary::graphics(const std::string& name,
                                              const rg::GraphicsPipelineDesc& desc) {
    rg::PipelineKey key = rg::pipelineKey(desc);
    std::lock_guard lock(mutex_);
    auto it = pipelines_.find(key);
    if (it == pipelines_.end())
        it = pipelines_.emplace(std::move(key), rg::Pipeline::graphics(device_, name, desc)).first;
    return it->second;
}

const rg::Samplers& samplersOf(const Shared& shared) {
    static const rg::Samplers none;
    return shared ? shared->samplers : none;
}

}  // namespace ls
