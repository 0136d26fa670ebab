#include "composite_target.h"

#include "pass_helpers.h"

namespace ls {
namespace {

bool wideColor(const rg::PassContext& ctx, const CompositeOutputs& written) {
    return ctx.format(written.color) == VK_FORMAT_R32G32B32A32_SFLOAT;
}

}  // namespace

CompositeOutputs addCompositeTarget(rg::BindingTable& table, const CompositeTarget& target) {
    CompositeOutputs written;
    written.color = table.storageReadWrite(LS_BINDING_ENGINE_COLOR, target.color);
    // Read-modify-written: a later light adds to it, and a pixel the pass leaves to another keeps
    // what it holds.
    written.inscatterOut = table.storageReadWriteIfValid(LS_BINDING_LIN_OUT, target.inscatterOut);
    return written;
}

rg::ShaderCode CompositeVariants::pick(const rg::PassContext& ctx,
                                       const CompositeOutputs& written) const {
    const bool out = written.inscatterOut.valid();
    if (wideColor(ctx, written)) return out ? rgba32fOut : rgba32f;
    return out ? rgba16fOut : rgba16f;
}

}  // namespace ls
