#pragma once
// Helpers for graph tests that need no GPU.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "rendergraph/compile.h"

namespace graph_test {

inline const rg::OfflineDeviceCaps& caps() {
    static const rg::OfflineDeviceCaps c;
    return c;
}

// Compiles and expects rejection by `rule` with a message containing every fragment.
inline void expectRejected(const rg::RenderGraph& graph, rg::Rule rule,
                           std::initializer_list<std::string> fragments,
                           const rg::DeviceCaps& c = caps()) {
    try {
        (void)rg::compile(graph, c);
        ADD_FAILURE() << "graph compiled, expected rule '" << rg::ruleName(rule) << "'";
    } catch (const rg::GraphError& e) {
        EXPECT_EQ(e.rule(), rule) << e.what();
        const std::string msg = e.what();
        for (const auto& f : fragments)
            EXPECT_NE(msg.find(f), std::string::npos) << "message lacks '" << f << "': " << msg;
    }
}

inline uint32_t positionOf(const rg::CompiledGraph& c, const rg::RenderGraph& g,
                           const std::string& pass) {
    for (uint32_t i = 0; i < c.passes.size(); ++i)
        if (g.passes()[c.passes[i].pass].name == pass) return i;
    return rg::kInvalidIndex;
}

inline rg::ImportedImage importedColor(VkExtent2D e, VkImageUsageFlags usage) {
    rg::ImportedImage i;
    i.format = VK_FORMAT_R8G8B8A8_UNORM;
    i.extent = e;
    i.usage = usage;
    i.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    i.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    i.finalStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    i.finalAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    return i;
}

}  // namespace graph_test
