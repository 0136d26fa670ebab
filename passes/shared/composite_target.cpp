#include "composite_target.h"

#include "pass_helpers.h"

namespace ls {
namespace {

bool wideColor(const rg::PassContext& ctx, const CompositeOutputs& written) {
    return ctx.format(written.color) == VK_FORMAT_R32G32B32A32_SFLOAT;
}

}  // namespace

CompositeOutputs declareCompositeTarget(rg::PassBuilder& pass, const CompositeTarget& target) {
    CompositeOutputs written;
    written.color = pass.storageReadWrite(target.color);
    // Read-modify-written: a later light adds to it, and a pixel the pass leaves to another keeps
    // what it holds.
    if (target.inscatterOut.valid())
        written.inscatterOut = pass.storageReadWrite(target.inscatterOut);
    return written;
}

void appendCompositeBindings(std::vector<rg::Binding>& bindings, const CompositeOutputs& written) {
    bindings.push_back(storageBinding(10));
    if (written.inscatterOut.valid()) bindings.push_back(storageBinding(11));
}

void pushCompositeTarget(rg::DescriptorPush& set, const rg::PassContext& ctx,
                         const CompositeOutputs& written) {
    set.storage(10, ctx.view(written.color));
    if (written.inscatterOut.valid()) set.storage(11, ctx.view(written.inscatterOut));
}

rg::ShaderCode CompositeVariants::pick(const rg::PassContext& ctx,
                                       const CompositeOutputs& written) const {
    const bool out = written.inscatterOut.valid();
    if (wideColor(ctx, written)) return out ? rgba32fOut : rgba32f;
    return out ? rgba16fOut : rgba16f;
}

std::string compositeKey(const rg::PassContext& ctx, const CompositeOutputs& written) {
    return std::string(wideColor(ctx, written) ? "rgba32f" : "rgba16f") +
           (written.inscatterOut.valid() ? "+out" : "");
}

}  // namespace ls
