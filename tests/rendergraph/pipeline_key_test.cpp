// Pipeline keys (rendergraph/pipeline_key.h): two descriptions that differ in any one field get
// different keys, so a cache keyed by them never hands out the wrong pipeline; equal descriptions
// get equal keys. The binding table (rendergraph/binding_table.h) gives the layout from its rows.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rendergraph/binding_table.h"
#include "rendergraph/pipeline_key.h"
#include "rendergraph/render_graph.h"

namespace {

const uint32_t kVertex[4] = {1, 2, 3, 4};
const uint32_t kFragment[4] = {1, 2, 3, 4};  // same words, another module
const uint32_t kOther[5] = {1, 2, 3, 4, 5};

rg::GraphicsPipelineDesc base() {
    rg::GraphicsPipelineDesc d;
    d.vertex = rg::spirv(kVertex);
    d.fragment = rg::spirv(kFragment);
    d.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_ALL},
                  {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_ALL}};
    d.specialization.set(0u, 1u).set(3u, true);
    d.formats.colors = {VK_FORMAT_R16G16B16A16_SFLOAT};
    return d;
}

TEST(PipelineKey, EveryGraphicsFieldChangesTheKey) {
    using Change = std::pair<std::string, std::function<void(rg::GraphicsPipelineDesc&)>>;
    const std::vector<Change> changes = {
        {"vertex", [](auto& d) { d.vertex = rg::spirv(kOther); }},
        {"fragment", [](auto& d) { d.fragment = rg::spirv(kVertex); }},
        {"binding number", [](auto& d) { d.bindings[1].binding = 2; }},
        {"binding type", [](auto& d) { d.bindings[1].type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE; }},
        {"binding stages", [](auto& d) { d.bindings[1].stages = VK_SHADER_STAGE_FRAGMENT_BIT; }},
        {"one binding more",
         [](auto& d) {
             d.bindings.push_back({8, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
         }},
        {"push bytes", [](auto& d) { d.pushConstantBytes = 8; }},
        {"specialisation value", [](auto& d) { d.specialization.values[0].second = 2; }},
        {"specialisation id", [](auto& d) { d.specialization.values[1].first = 4; }},
        {"one constant more", [](auto& d) { d.specialization.set(10u, 32u); }},
        {"color format", [](auto& d) { d.formats.colors[0] = VK_FORMAT_R32G32B32A32_SFLOAT; }},
        {"one color more", [](auto& d) { d.formats.colors.push_back(VK_FORMAT_R8_UNORM); }},
        {"depth format", [](auto& d) { d.formats.depth = VK_FORMAT_D32_SFLOAT; }},
        {"stencil format", [](auto& d) { d.formats.stencil = VK_FORMAT_S8_UINT; }},
        {"topology", [](auto& d) { d.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP; }},
        {"vertex binding",
         [](auto& d) {
             d.vertexBindings.push_back({0, 12});
         }},
        {"vertex attribute",
         [](auto& d) {
             d.vertexAttributes.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
         }},
        {"cull mode", [](auto& d) { d.cullMode = VK_CULL_MODE_BACK_BIT; }},
        {"front face", [](auto& d) { d.frontFace = VK_FRONT_FACE_CLOCKWISE; }},
        {"depth test", [](auto& d) { d.depthTest = true; }},
        {"depth write", [](auto& d) { d.depthWrite = true; }},
        {"depth compare", [](auto& d) { d.depthCompare = VK_COMPARE_OP_GREATER; }},
        {"stencil test", [](auto& d) { d.stencilTest = true; }},
        {"stencil fail op", [](auto& d) { d.stencil.failOp = VK_STENCIL_OP_ZERO; }},
        {"stencil pass op", [](auto& d) { d.stencil.passOp = VK_STENCIL_OP_REPLACE; }},
        {"stencil depth-fail op", [](auto& d) { d.stencil.depthFailOp = VK_STENCIL_OP_ZERO; }},
        {"stencil compare", [](auto& d) { d.stencil.compareOp = VK_COMPARE_OP_EQUAL; }},
        {"stencil compare mask", [](auto& d) { d.stencil.compareMask = 0xff; }},
        {"stencil write mask", [](auto& d) { d.stencil.writeMask = 0xff; }},
        {"stencil reference", [](auto& d) { d.stencil.reference = 2; }},
        {"blend", [](auto& d) { d.blend = rg::BlendMode::Additive; }},
        {"color write mask", [](auto& d) { d.colorWriteMask = VK_COLOR_COMPONENT_R_BIT; }},
        {"depth bias", [](auto& d) { d.depthBias = true; }},
    };
    const rg::PipelineKey reference = rg::pipelineKey(base());
    EXPECT_EQ(rg::pipelineKey(base()), reference);
    std::vector<rg::PipelineKey> seen{reference};
    for (const auto& [field, change] : changes) {
        rg::GraphicsPipelineDesc d = base();
        change(d);
        const rg::PipelineKey key = rg::pipelineKey(d);
        EXPECT_NE(key, reference) << field;
        for (size_t i = 1; i < seen.size(); ++i)
            EXPECT_NE(key, seen[i]) << field << " vs " << changes[i - 1].first;
        seen.push_back(key);
    }
}

TEST(PipelineKey, OrderOfBindingsAndConstantsIsNoPartOfIt) {
    rg::GraphicsPipelineDesc a = base(), b = base();
    std::swap(b.bindings[0], b.bindings[1]);
    std::swap(b.specialization.values[0], b.specialization.values[1]);
    EXPECT_EQ(rg::pipelineKey(a), rg::pipelineKey(b));
}

TEST(PipelineKey, EveryComputeFieldChangesTheKey) {
    const std::vector<rg::Binding> bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
    rg::Specialization spec;
    spec.set(0u, 1u);
    const rg::PipelineKey reference = rg::pipelineKey(rg::spirv(kVertex), bindings, 0, spec);
    rg::Specialization other;
    other.set(0u, 2u);
    EXPECT_NE(rg::pipelineKey(rg::spirv(kFragment), bindings, 0, spec), reference);
    EXPECT_NE(
        rg::pipelineKey(rg::spirv(kVertex), {{1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}}, 0, spec),
        reference);
    EXPECT_NE(rg::pipelineKey(rg::spirv(kVertex), bindings, 4, spec), reference);
    EXPECT_NE(rg::pipelineKey(rg::spirv(kVertex), bindings, 0, other), reference);
    EXPECT_NE(rg::pipelineKey(rg::spirv(kVertex), bindings, 0, {}), reference);
    // A compute and a graphics description never share a key.
    rg::GraphicsPipelineDesc g;
    EXPECT_NE(rg::pipelineKey(g), rg::pipelineKey({}, {}, 0, {}));
}

TEST(BindingTable, OneRowGivesTheUseAndTheLayout) {
    rg::RenderGraph graph;
    const rg::BufferRef constants = graph.createBuffer("constants", rg::BufferDesc{256});
    const rg::ImageRef image =
        graph.createImage("image", rg::ImageDesc::absolute(VK_FORMAT_R8G8B8A8_UNORM, 4, 4));
    const rg::ImageRef out =
        graph.createImage("out", rg::ImageDesc::absolute(VK_FORMAT_R8G8B8A8_UNORM, 4, 4));
    auto pass = graph.addPass("pass", rg::PassType::Compute);
    rg::BindingTable table(pass);
    table.uniform(0, constants)
        .sampled(3, image, VK_NULL_HANDLE)
        .sampledIfValid(6, rg::ImageRef{}, VK_NULL_HANDLE);
    const rg::ImageRef written = table.storageWrite(5, out);
    EXPECT_TRUE(written.valid());
    EXPECT_FALSE(table.storageReadWriteIfValid(7, rg::ImageRef{}).valid());
    const std::vector<rg::Binding> layout = table.layout();
    ASSERT_EQ(layout.size(), 3u);  // the rows of invalid handles add nothing
    EXPECT_EQ(layout[0].binding, 0u);
    EXPECT_EQ(layout[0].type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_EQ(layout[1].binding, 3u);
    EXPECT_EQ(layout[1].type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(layout[2].binding, 5u);
    EXPECT_EQ(layout[2].type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    EXPECT_TRUE(table.has(3));
    EXPECT_FALSE(table.has(6));
    EXPECT_FALSE(table.without(3).has(3));
    EXPECT_EQ(table.without(3).layout().size(), 2u);
}

}  // namespace
