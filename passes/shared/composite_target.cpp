#include "composite_target.h"

#include "pass_helpers.h"

namespace ls {

CompositeOutputs addCompositeTarget(rg::BindingTable& table, const CompositeTarget& target) {
    CompositeOutputs written;
    // The split's images start with the frame's first light, whose composite writes every pixel
    // of the frame without reading (its passes together: epipolar's unwarp, then its fix-up, each
    // keeps what the other wrote). The engine's color is read-modify-written: a later light adds
    // to it, and a pixel the pass leaves to another keeps what it holds.
    const bool split = target.transmittance.valid();
    const bool starts = split && !target.addOnly;
    written.color = starts ? table.storageWrite(LS_BINDING_ENGINE_COLOR, target.color)
                           : table.storageReadWrite(LS_BINDING_ENGINE_COLOR, target.color);
    written.inscatterOut = table.storageReadWriteIfValid(LS_BINDING_LIN_OUT, target.inscatterOut);
    // Written by the first light only; a later light's pass keeps it (the same image, in order).
    if (split)
        written.transmittance =
            starts ? table.storageWrite(LS_BINDING_COMPOSITE_T, target.transmittance)
                   : table.storageReadWrite(LS_BINDING_COMPOSITE_T, target.transmittance);
    return written;
}

CompositeOutputs addBlendedCompositeTarget(rg::PassBuilder& pass, rg::BindingTable& table,
                                           const CompositeTarget& target, bool& blended) {
    blended = target.blend && !target.transmittance.valid();
    if (!blended) return addCompositeTarget(table, target);
    CompositeOutputs written;
    written.color = pass.colorAttachment(target.color, rg::LoadOp::Load);
    written.inscatterOut = table.storageReadWriteIfValid(LS_BINDING_LIN_OUT, target.inscatterOut);
    return written;
}

CompositeVariant compositeVariant(const rg::PassContext& ctx, const CompositeOutputs& written) {
    return {ctx.format(written.color), written.inscatterOut.valid(), written.transmittance.valid()};
}

}  // namespace ls
