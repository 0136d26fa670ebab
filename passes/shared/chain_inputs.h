#pragma once
// A light's chain inputs as the nodes take them: the frame's part, and the light's images (its
// shadow map where it is shadowed, its light color wherever it is given).
#include "chain_context.h"
#include "method_unit.h"

namespace ls {

inline ChainContext chainContext(const ChainInputs& in, const ChainConfig& c) {
    return {in.shared, c.spec,    in.values,       in.constants,
            in.depth,  in.screen, in.depthStencil, in.coordinateFormat};
}

inline LightImages lightImages(const ChainInputs& in, const ChainConfig& c) {
    LightImages l;
    l.table = in.table;
    if (c.shadowed) l.shadowMap = in.shadowMap;
    // Without a shadow map too: an unshadowed light with a color is marched (addUnshadowed).
    l.lightColor = in.lightColor;
    l.shadowMapSize = c.shadowMapSize;
    return l;
}

// An unshadowed light's Lin for the methods that march a shadow map (epipolar, brute force): the
// point-light table, or the directional closed form, per pixel.
inline std::string unshadowedSummary(const ChainConfig& c) {
    if (c.spec.lightColor)
        return "unshadowed light with a light color: marched per pixel, a piece per row or column "
               "of the color's texels crossed";
    return c.light == LightType::Directional
               ? "unshadowed directional light: closed form per pixel"
               : "unshadowed light: the point-light table in closed form per pixel";
}

}  // namespace ls
