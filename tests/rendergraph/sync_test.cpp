// Barriers derived from declared uses: stages, access and layouts between passes.
#include "graph_test_util.h"

using namespace rg;

namespace {

const BarrierPlan* barrierFor(const PassPlan& p, uint32_t resource) {
    for (const auto& b : p.barriers)
        if (b.resource == resource) return &b;
    return nullptr;
}

}  // namespace

TEST(Sync, ComputeWriteThenFragmentSample) {
    RenderGraph g;
    ImageRef x = g.createImage("x", ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 8, 8));
    ImageRef out = g.createImage("out", ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 8, 8));
    auto w = g.addPass("write", PassType::Compute);
    x = w.storageWrite(x);
    auto r = g.addPass("sample", PassType::Graphics);
    r.sampled(x);
    g.markOutput(r.colorAttachment(out, LoadOp::Clear));
    const CompiledGraph c = compile(g, graph_test::caps());
    const BarrierPlan* b = barrierFor(c.passes[1], x.id);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->srcStages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(b->srcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(b->dstStages, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(b->dstAccess, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    EXPECT_EQ(b->oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(b->newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    ASSERT_EQ(c.passes[1].colors.size(), 1u);
    EXPECT_EQ(c.passes[1].colors[0].load, VK_ATTACHMENT_LOAD_OP_CLEAR);
}

TEST(Sync, StencilWriteThenStencilTest) {
    RenderGraph g;
    ImageRef ds = g.createImage("ds", ImageDesc::absolute(VK_FORMAT_D32_SFLOAT_S8_UINT, 8, 8));
    ImageRef out = g.createImage("out", ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 8, 8));
    auto m = g.addPass("mark", PassType::Graphics);
    ds = m.stencilWrite(ds, LoadOp::Clear);
    auto t = g.addPass("tested", PassType::Graphics);
    t.stencilTest(ds);
    g.markOutput(t.colorAttachment(out, LoadOp::Clear));
    const CompiledGraph c = compile(g, graph_test::caps());
    const BarrierPlan* b = barrierFor(c.passes[1], ds.id);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->srcAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(b->dstAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    EXPECT_EQ(b->oldLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(b->newLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    ASSERT_TRUE(c.passes[1].stencil.has_value());
    EXPECT_FALSE(c.passes[1].depth.has_value());
    EXPECT_EQ(c.passes[1].stencil->load, VK_ATTACHMENT_LOAD_OP_LOAD);
    EXPECT_EQ(c.passes[1].stencil->store, VK_ATTACHMENT_STORE_OP_NONE);  // test only
}

TEST(Sync, TwoReadersInOneLayoutNeedOneBarrier) {
    RenderGraph g;
    ImageRef x = g.createImage("x", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    ImageRef a = g.createImage("a", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    ImageRef b = g.createImage("b", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    auto w = g.addPass("write", PassType::Compute);
    x = w.storageWrite(x);
    auto r1 = g.addPass("read 1", PassType::Compute);
    r1.sampled(x);
    g.markOutput(r1.storageWrite(a));
    auto r2 = g.addPass("read 2", PassType::Compute);
    r2.sampled(x);
    g.markOutput(r2.storageWrite(b));
    const CompiledGraph c = compile(g, graph_test::caps());
    EXPECT_NE(barrierFor(c.passes[1], x.id), nullptr);
    EXPECT_EQ(barrierFor(c.passes[2], x.id), nullptr);
}

TEST(Sync, WriteAfterReadWaitsForTheReader) {
    RenderGraph g;
    ImageRef x = g.createImage("x", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    ImageRef y = g.createImage("y", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    auto w = g.addPass("write", PassType::Compute);
    x = w.storageWrite(x);
    auto r = g.addPass("read", PassType::Compute);
    r.sampled(x);
    g.markOutput(r.storageWrite(y));
    auto w2 = g.addPass("rewrite", PassType::Compute);
    g.markOutput(w2.storageWrite(x));
    const CompiledGraph c = compile(g, graph_test::caps());
    const BarrierPlan* b = barrierFor(c.passes[2], x.id);
    ASSERT_NE(b, nullptr);
    EXPECT_NE(b->srcStages & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0u);
    EXPECT_EQ(b->newLayout, VK_IMAGE_LAYOUT_GENERAL);
}

TEST(Sync, ImportIsHandedBackInItsFinalLayout) {
    RenderGraph g;
    auto desc =
        graph_test::importedColor({8, 8}, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
    desc.initialLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    desc.initialStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    desc.initialAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    ImageRef engine = g.importImage("engine", desc);
    auto p = g.addPass("composite", PassType::Compute);
    (void)p.storageReadWrite(engine);
    const CompiledGraph c = compile(g, graph_test::caps());
    const BarrierPlan* first = barrierFor(c.passes[0], engine.id);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->oldLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(first->newLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(first->srcStages, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    ASSERT_EQ(c.finalBarriers.size(), 1u);
    EXPECT_EQ(c.finalBarriers[0].oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(c.finalBarriers[0].newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(c.finalBarriers[0].srcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(Sync, ReadAfterReadWriteNeedsABarrier) {
    RenderGraph g;
    ImageRef x = g.createImage("x", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    ImageRef y = g.createImage("y", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    auto w = g.addPass("write", PassType::Compute);
    x = w.storageWrite(x);
    auto rw = g.addPass("read-modify-write", PassType::Compute);
    x = rw.storageReadWrite(x);
    auto r = g.addPass("read", PassType::Compute);
    r.storageRead(x);
    g.markOutput(r.storageWrite(y));
    const CompiledGraph c = compile(g, graph_test::caps());
    // The read-modify-write's own read access does not make its write visible to the next read.
    const BarrierPlan* b = barrierFor(c.passes[2], x.id);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->srcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(b->dstAccess, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    ASSERT_NE(barrierFor(c.passes[1], x.id), nullptr);
}

TEST(Sync, SampledDepthUsesTheShaderReadLayout) {
    RenderGraph g;
    ImportedImage d;
    d.format = VK_FORMAT_D32_SFLOAT;
    d.extent = {8, 8};
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT;  // not a depth attachment of ours
    d.initialLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    d.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    ImageRef depth = g.importImage("engine depth", d);
    ImageRef out = g.createImage("out", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    auto p = g.addPass("sample depth", PassType::Compute);
    p.sampled(depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    g.markOutput(p.storageWrite(out));
    const CompiledGraph c = compile(g, graph_test::caps());
    for (const auto& s : c.passes[0].states)
        if (s.resource == depth.id) {
            EXPECT_EQ(s.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        }
}

namespace {

ImportedImage engineDepth(VkImageUsageFlags usage) {
    ImportedImage d;
    d.format = VK_FORMAT_D32_SFLOAT;
    d.extent = {8, 8};
    d.usage = usage;
    d.initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    d.initialStages = VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    d.initialAccess = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    d.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    return d;
}

}  // namespace

// The engine's depth buffer sampled by one pass and then a read-only depth attachment of the next
// (the planes method's planes): one read-only layout after the engine's writes, loaded and never
// stored, and handed back to the engine in its own layout.
TEST(Sync, ImportedDepthSampledThenTestedReadOnly) {
    RenderGraph g;
    ImageRef depth = g.importImage(
        "engine depth",
        engineDepth(VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT));
    ImageRef z = g.createImage("z", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    ImageRef out = g.createImage("out", ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 8, 8));
    auto s = g.addPass("sample depth", PassType::Compute);
    s.sampled(depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    z = s.storageWrite(z);
    auto t = g.addPass("planes", PassType::Graphics);
    t.sampled(z);
    t.depthTest(depth);
    g.markOutput(t.colorAttachment(out, LoadOp::Clear));
    const CompiledGraph c = compile(g, graph_test::caps());
    ASSERT_EQ(c.passes.size(), 2u);
    const BarrierPlan* first = barrierFor(c.passes[0], depth.id);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->srcStages, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT);
    EXPECT_EQ(first->srcAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(first->oldLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(first->newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    const BarrierPlan* second = barrierFor(c.passes[1], depth.id);
    ASSERT_NE(second, nullptr) << "a layout change from sampled to depth attachment";
    EXPECT_EQ(second->oldLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(second->newLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    EXPECT_NE(second->srcStages & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0u);
    EXPECT_NE(second->dstStages & VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT, 0u);
    EXPECT_EQ(second->dstAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    ASSERT_TRUE(c.passes[1].depth.has_value());
    EXPECT_EQ(c.passes[1].depth->layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    EXPECT_EQ(c.passes[1].depth->load, VK_ATTACHMENT_LOAD_OP_LOAD);
    EXPECT_EQ(c.passes[1].depth->store, VK_ATTACHMENT_STORE_OP_NONE);
    bool handedBack = false;
    for (const auto& b : c.finalBarriers)
        if (b.resource == depth.id) {
            handedBack = true;
            EXPECT_EQ(b.oldLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
            EXPECT_EQ(b.newLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
        }
    EXPECT_TRUE(handedBack);
}

// An engine depth created without DEPTH_STENCIL_ATTACHMENT cannot be a depth attachment.
TEST(Sync, ImportedDepthWithoutAttachmentUsageIsRejected) {
    RenderGraph g;
    ImageRef depth = g.importImage("engine depth", engineDepth(VK_IMAGE_USAGE_SAMPLED_BIT));
    ImageRef out = g.createImage("out", ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 8, 8));
    auto t = g.addPass("planes", PassType::Graphics);
    t.depthTest(depth);
    g.markOutput(t.colorAttachment(out, LoadOp::Clear));
    graph_test::expectRejected(g, Rule::UsageNotDeclared, {"planes", "engine depth", "depth test"});
}
