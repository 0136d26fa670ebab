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
struct CompositeOutputs {
    rg::ImageRef color;
    rg::ImageRef inscatterOut;  // invalid when none was given
};
struct CompositeInputs {
    ChainContext chain;         // its constants and depth
    rg::ImageRef color;         // the engine's color
    rg::ImageRef lin;           // invalid: extinction only
    rg::ImageRef inscatterOut;  // invalid: none
};
CompositeOutputs addComposite(rg::RenderGraph& graph, const CompositeInputs& in);

// Several lights: adds one more light's Lin into the color, after the first light's composite
// (which applied the extinction), and into `inscatterOut` when it is valid (which then holds the
// sum). Each light's Lin is dead after it, so the next light's chain may reuse its memory.
CompositeOutputs addInscatter(rg::RenderGraph& graph, const CompositeInputs& in);

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
