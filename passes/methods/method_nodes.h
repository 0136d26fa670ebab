#pragma once
// Nodes shared by every method, and the per-pixel methods. Each function adds one pass to the
// graph and returns the handles it produced.
#include "common/node_inputs.h"

namespace ls {

// Copies this frame's constants into a graph buffer (vkCmdUpdateBuffer, recorded per frame).
rg::BufferRef addUploadConstants(rg::RenderGraph& graph, const Shared& shared);

// Camera-space z of every pixel's ray end (R32_SFLOAT, screen).
rg::ImageRef addCameraZ(rg::RenderGraph& graph, const NodeInputs& in);

// Brute-force per-pixel ray marching through the shadow map: Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addBruteForce(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef cameraZ);

// Closed-form Lin for a light without a shadow map.
rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef cameraZ);

// color = color * exp(-betaT S) + Lin, and Lin alone into `inscatterOut` when it is valid.
// Without Lin (the light's volume misses the view) only the extinction is applied.
rg::ImageRef addComposite(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef color,
                          rg::ImageRef cameraZ, rg::ImageRef lin, rg::ImageRef inscatterOut);

// Fills the point-light table (R32G32B32A32_SFLOAT) for the current medium and light radius.
rg::ImageRef addPointTable(rg::RenderGraph& graph, const Shared& shared, rg::BufferRef constants,
                           rg::ImageRef table);

}  // namespace ls
