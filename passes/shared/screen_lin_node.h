#pragma once
// The skeleton of the full-screen Lin nodes (analytic, unshadowed, cone march): one graphics pass
// that reads the frame constants and the engine's depth, plus the node's own rows, and draws a
// full-screen triangle into a new screen-sized R16G16B16A16_SFLOAT Lin image.
#include <functional>
#include <string>

#include "light_frame.h"
#include "pass_helpers.h"
#include "shared_state.h"

namespace ls {

struct ScreenLinNode {
    std::string name;  // the pass's and its pipeline's
    rg::BufferRef constants;
    rg::ImageRef depth;
    // The light's values: the node draws only within their screenRect (the rest cleared to 0).
    rg::HostDataRef<LightFrame> values;
    // The node's rows after the frame constants and the depth (the light's images).
    std::function<void(rg::BindingTable&)> rows;
    // The shader variant, chosen when the pass is recorded from the light's spec.
    std::function<rg::ShaderCode(const ScatterSpec&)> shader;
    // The node's own specialisation data, after the light's (ScatterSpec::constants()).
    std::function<void(rg::Specialization&)> specialize;
};

rg::ImageRef addScreenLinNode(rg::RenderGraph& graph, const Shared& shared, const ScatterSpec& spec,
                              ScreenLinNode node);

}  // namespace ls
