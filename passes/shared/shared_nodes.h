#pragma once
// Nodes every method shares: the frame constants, the point-light table, the
// closed form for lights without a shadow map (whatever the method), and the composite. Each
// function adds one pass to the graph, takes the handles it reads and returns those it writes.
#include "chain_context.h"

namespace ls {

// Copies this frame's constants into a graph buffer (vkCmdUpdateBuffer, recorded per frame).
struct UploadConstantsInputs {
    rg::HostDataRef<LightFrame> values;  // whose constants
};
rg::BufferRef addUploadConstants(rg::RenderGraph& graph, const UploadConstantsInputs& in);

// Closed-form Lin for a light without a shadow map (R16G16B16A16_SFLOAT, screen); reads
// light.table. With light.lightColor, a per-pixel march through the color instead (the color
// varies along the ray, which the closed form cannot carry).
struct UnshadowedInputs {
    ChainContext chain;
    LightImages light;
};
rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const UnshadowedInputs& in);

// color = color * exp(-betaT S) + Lin, and Lin alone into `inscatterOut` when it is valid.
// Without Lin (the light's volume misses the view) only the extinction is applied.
// In a split composite (composite_target.h) `color` is the split's Lin and `transmittance` its
// transmittance, which the first light writes.
struct CompositeOutputs {
    rg::ImageRef color;
    rg::ImageRef inscatterOut;   // invalid when none was given
    rg::ImageRef transmittance;  // valid: the composite is split
};
struct CompositeInputs {
    ChainContext chain;          // its constants and depth
    rg::ImageRef color;          // the engine's color, or the split composite's Lin
    rg::ImageRef lin;            // invalid: extinction only
    rg::ImageRef inscatterOut;   // invalid: none
    rg::ImageRef transmittance;  // valid: the composite is split
};
CompositeOutputs addComposite(rg::RenderGraph& graph, const CompositeInputs& in);

// Several lights: adds one more light's Lin into the color, after the first light's composite
// (which applied the extinction), and into `inscatterOut` when it is valid (which then holds the
// sum). Each light's Lin is dead after it, so the next light's chain may reuse its memory.
CompositeOutputs addInscatter(rg::RenderGraph& graph, const CompositeInputs& in);

// The split composite (composite_target.h) into the engine's color, color * T + k Lin: a compute
// pass where the color is a storage image of R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT, else a
// graphics pass blending into it as a color attachment (any format the device blends into), in
// one draw with dual-source blending or, on a device without it, two (multiply by T, add k Lin).
// Returns the color's new version.
struct SplitCompositeInputs {
    ChainContext chain;               // the device's shared state
    rg::ImageRef lin, transmittance;  // the split's
    rg::ImageRef color;               // the engine's
    bool storage = false;             // the color is a storage image of those formats
    bool dualSource = false;          // the device was created with dualSrcBlend
};
rg::ImageRef addSplitComposite(rg::RenderGraph& graph, const SplitCompositeInputs& in);

// The split's transmittance into the engine's FrameDescription::transmittanceOut (storage,
// R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT); returns its new version.
struct TransmittanceExportInputs {
    ChainContext chain;
    rg::ImageRef transmittance;  // the split's
    rg::ImageRef out;            // the engine's
};
rg::ImageRef addTransmittanceExport(rg::RenderGraph& graph, const TransmittanceExportInputs& in);

// Fills the point-light table (R32G32B32A32_SFLOAT) for the current medium and light radius, in the
// frames that find it empty or made for another medium; the others record nothing and leave it as
// it was.
struct PointTableInputs {
    Shared shared;
    ScatterSpec spec;
    rg::HostDataRef<LightFrame> values;
    rg::BufferRef constants;
    rg::HostDataRef<rg::PersistentKey> key;  // the light's: the graph keeps its table under it
};
// The light's table (point_table.h), filled where the frames before left it empty or made for
// another medium; returns it as the chain's passes read it.
rg::ImageRef addPointTable(rg::RenderGraph& graph, const PointTableInputs& in);

}  // namespace ls
