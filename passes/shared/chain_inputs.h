#pragma once
// The node inputs of a light's chain for the nodes that take the whole set (epipolar's, brute
// force's, the unshadowed closed form's): the light's images where it is shadowed.
#include "method_unit.h"
#include "node_inputs.h"

namespace ls {

inline NodeInputs nodeInputs(const ChainInputs& in, const ChainConfig& c) {
    NodeInputs n;
    n.shared = in.shared;
    n.constants = in.constants;
    n.depth = in.depth;
    n.table = in.table;
    if (c.shadowed) {
        n.shadowMap = in.shadowMap;
        n.lightColor = in.lightColor;
    }
    n.screen = in.screen;
    n.depthStencil = in.depthStencil;
    n.coordinateFormat = in.coordinateFormat;
    n.shadowMapSize = c.shadowMapSize;
    return n;
}

// An unshadowed light's Lin for the methods that march a shadow map (epipolar, brute force): the
// point-light table, or the directional closed form, per pixel.
inline std::string unshadowedSummary(const ChainConfig& c) {
    return c.light == LightKind::Directional
               ? "unshadowed directional light: closed form per pixel"
               : "unshadowed light: the point-light table in closed form per pixel";
}

}  // namespace ls
