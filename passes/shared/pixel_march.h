#pragma once
// The per-pixel march (shaders/shared/pixel_march.frag): each pixel marches its own ray through
// the shadow map, one step per texel it crosses. Brute force draws it over every pixel; the
// epipolar fix-up over the pixels its unwarp left unmarked in a stencil, with an optional step cap.
// The caller adds the pass, its target and any stencil it tests; these add the march's reads and
// draw.
#include "chain_context.h"
#include "rendergraph/binding_table.h"
#include "rendergraph/pass_context.h"
#include "rendergraph/render_graph.h"
#include "shared_nodes.h"

namespace ls {

// The march's reads: the frame constants, the engine's depth and the light's images. The caller
// adds any rows of its own (the composite target) to the table before drawing with it.
// frameStages: the stages that read the frame constants (0: the fragment shader's).
rg::BindingTable declarePixelMarch(rg::PassBuilder& pass, const ChainContext& chain,
                                   const LightImages& light, VkPipelineStageFlags2 frameStages = 0);

struct PixelMarchDraw {
    const char* pipeline = "";        // names the pipeline
    uint32_t maxSteps = 0;            // steps per ray at most; 0: one per texel crossed
    bool whereStencilIsZero = false;  // draw only where the pass's stencil attachment holds 0
    // Composite into these (rows of the pass's table, addCompositeTarget) instead of writing
    // Lin to the pass's color attachment: the epipolar fix-up.
    const CompositeOutputs* composite = nullptr;
    bool addOnly = false;  // with composite: a frame's later light
    // What the draw covers: `vertices` vertices of this vertex shader (none: the viewport's one
    // triangle), whose bindings the caller added to the table.
    rg::ShaderCode vertex{};
    uint32_t vertices = 3;
};

// Records the march as one draw of the pass (full-screen unless PixelMarchDraw::vertex says), with
// the light's shader options.
void drawPixelMarch(rg::PassContext& ctx, const Shared& shared, const ScatterSpec& spec,
                    const rg::BindingTable& table, const PixelMarchDraw& draw);

}  // namespace ls
