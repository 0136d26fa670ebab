#pragma once
// Compositing where Lin is made (shaders/shared/composite_into.glsl): the pass that makes Lin
// read-modify-writes the engine's color, and the Lin output when the frame has one, so no
// screen-sized Lin texture and no pass of its own are needed. The epipolar unwarp and fix-up do
// it; the composite node does it for the methods that leave Lin in a screen texture.
#include <string>
#include <vector>

#include "composite_variant.h"
#include "rendergraph/binding_table.h"
#include "rendergraph/pass_context.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/render_graph.h"
#include "shared_nodes.h"

namespace ls {

// Split: the engine's color is no storage image the passes can read-modify-write, or the frame
// asks for its transmittance (FrameDescription::transmittanceOut). The passes then composite into
// two images of the plugin's, `color` holding k Lin and `transmittance` T, and a last pass blends
// them into the engine's color (addSplitComposite).
struct CompositeTarget {
    rg::ImageRef color;         // the engine's color (RGBA16F or RGBA32F, storage) or the split Lin
    rg::ImageRef inscatterOut;  // RGBA32F; invalid: none
    bool addOnly = false;       // a frame's later light: add Lin, the first applied the extinction
    rg::ImageRef transmittance;  // the split's transmittance; invalid: not split
    // The engine's color (not split) also takes dual-source blending as a color attachment: a
    // fragment pass may blend into it (addBlendedCompositeTarget) rather than read-modify-write
    // it, the same sum without a load and a store per pixel (composite_into.glsl's LS_BLEND).
    bool blend = false;
};

// The pass's rows for the target's read-modify-written images (LS_BINDING_ENGINE_COLOR and, when
// there are, LS_BINDING_LIN_OUT and LS_BINDING_COMPOSITE_T); returns their new versions.
CompositeOutputs addCompositeTarget(rg::BindingTable& table, const CompositeTarget& target);

// A fragment pass's rows, blending into the color as its attachment where target.blend allows
// (`blended` says whether it does: the pass then draws with BlendMode::DualSourceMultiplyAdd and
// the shader's LS_BLEND build), else addCompositeTarget's.
CompositeOutputs addBlendedCompositeTarget(rg::PassBuilder& pass, rg::BindingTable& table,
                                           const CompositeTarget& target, bool& blended);

// The target of a later pass that composites into what an earlier one `written` (epipolar's
// fix-up after its unwarp), as the same light.
inline CompositeTarget targetAfter(const CompositeOutputs& written, bool addOnly) {
    return {written.color, written.inscatterOut, addOnly, written.transmittance};
}

// The shader variant that writes what the pass declared.
CompositeVariant compositeVariant(const rg::PassContext& ctx, const CompositeOutputs& written);

}  // namespace ls
