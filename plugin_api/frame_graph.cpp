#include "frame_graph.h"

#include "brute_force/brute_force_node.h"
#include "epipolar/epipolar_nodes.h"
#include "shared/shared_nodes.h"

namespace lightscatter::detail {

bool GraphConfig::operator==(const GraphConfig& o) const {
    return method == o.method && light == o.light && shadowed == o.shadowed &&
           touchesView == o.touchesView && minMaxTrees == o.minMaxTrees && fixup == o.fixup &&
           slices == o.slices && samples == o.samples && shadowMapSize == o.shadowMapSize &&
           screen.width == o.screen.width && screen.height == o.screen.height &&
           depthStencil == o.depthStencil && depth == o.depth && color == o.color &&
           shadowMap == o.shadowMap && lightColor == o.lightColor &&
           inscatterOut == o.inscatterOut && table == o.table && poisonTransients == o.poisonTransients;
}

rg::ImportedImage importDescription(const ImageInput& in) {
    rg::ImportedImage d;
    d.image = in.image;
    d.format = in.format;
    d.extent = in.extent;
    d.usage = in.usage;
    d.initialLayout = in.layout;
    d.initialStages = in.stages;
    d.initialAccess = in.access;
    d.finalLayout = in.finalLayout;
    d.finalStages = in.finalStages;
    d.finalAccess = in.finalAccess;
    return d;
}

rg::ImportedImage importDescription(const ImportState& s) {
    rg::ImportedImage d;
    d.format = s.format;
    d.extent = s.extent;
    d.usage = s.usage;
    d.initialLayout = s.layout;
    d.finalLayout = s.finalLayout;
    return d;
}

FrameGraph buildFrameGraph(const GraphConfig& c, const ls::Shared& shared) {
    FrameGraph fg;
    fg.graph = std::make_unique<rg::RenderGraph>();
    rg::RenderGraph& g = *fg.graph;
    g.setScreenExtent(c.screen);

    ls::NodeInputs in;
    in.shared = shared;
    in.screen = c.screen;
    in.depthStencil = c.depthStencil;
    in.shadowMapSize = c.shadowMapSize;
    fg.depth = in.depth = g.importImage("engine depth", importDescription(c.depth));
    fg.color = g.importImage("engine color", importDescription(c.color));
    if (c.inscatterOut.format != VK_FORMAT_UNDEFINED)
        fg.inscatterOut = g.importImage("in-scattering output", importDescription(c.inscatterOut));
    in.constants = ls::addUploadConstants(g, shared);
    const rg::ImageRef cameraZ = ls::addCameraZ(g, in);

    rg::ImageRef lin;
    if (!c.touchesView) {
        fg.summary = "the light's volume misses the view: extinction only";
    } else {
        if (c.light != ls::LightKind::Directional)
            fg.table = in.table = g.importImage("point-light table", importDescription(c.table));
        if (c.shadowed) {
            fg.shadowMap = in.shadowMap = g.importImage("engine shadow map", importDescription(c.shadowMap));
            if (c.lightColor.format != VK_FORMAT_UNDEFINED)
                fg.lightColor = in.lightColor =
                    g.importImage("light color", importDescription(c.lightColor));
        }
        if (!c.shadowed) {
            lin = ls::addUnshadowed(g, in, cameraZ);
            fg.summary = "unshadowed light: closed form per pixel";
        } else if (c.method == Method::BruteForce) {
            lin = ls::addBruteForce(g, in, cameraZ);
            fg.summary = "brute-force ray marching";
        } else {
            ls::EpipolarSizes sizes{c.slices, c.samples, c.shadowMapSize};
            ls::EpipolarOptions options{c.minMaxTrees, c.fixup};
            lin = ls::addEpipolarNodes(g, in, sizes, options, cameraZ).screenInscatter;
            fg.summary = std::string("epipolar sampling") + (c.minMaxTrees ? " with min/max trees" : "") +
                         (c.fixup ? ", fix-up" : "");
        }
    }
    ls::addComposite(g, in, fg.color, cameraZ, lin, fg.inscatterOut);
    return fg;
}

}  // namespace lightscatter::detail
