// Every rejection rule of the compiler: build the bad graph, check the rule and that the message
// names the pass, the resource and what is wrong.
#include "graph_test_util.h"

using namespace rg;
using graph_test::expectRejected;

namespace {

constexpr VkExtent2D kSize{64, 32};

ImageRef color(RenderGraph& g, const char* name, VkFormat f = VK_FORMAT_R16G16B16A16_SFLOAT) {
    return g.createImage(name, ImageDesc::absolute(f, kSize.width, kSize.height));
}

}  // namespace

TEST(CompileRules, UnknownResourceFromAnotherGraph) {
    RenderGraph other;
    const ImageRef foreign =
        other.createImage("foreign", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 4, 4));
    RenderGraph g;
    auto p = g.addPass("consumer", PassType::Compute);
    p.sampled(foreign);
    p.sideEffect();
    expectRejected(g, Rule::UnknownResource, {"'consumer'", "did not declare"});
}

TEST(CompileRules, UnknownVersion) {
    RenderGraph g;
    ImageRef x = color(g, "x");
    auto p = g.addPass("reader", PassType::Compute);
    p.sampled(ImageRef{x.graph, x.id, 5});
    p.sideEffect();
    expectRejected(g, Rule::UnknownResource, {"'reader'", "version 5", "'x'"});
}

TEST(CompileRules, ReadOfNeverWrittenResource) {
    RenderGraph g;
    ImageRef x = color(g, "never written");
    auto p = g.addPass("early reader", PassType::Compute);
    p.sampled(x);
    p.sideEffect();
    expectRejected(g, Rule::NeverWritten, {"'early reader'", "'never written'", "no pass writes"});
}

TEST(CompileRules, LoadingAnUnwrittenAttachmentIsANeverWrittenRead) {
    RenderGraph g;
    ImageRef x = color(g, "target");
    auto p = g.addPass("blend onto nothing", PassType::Graphics);
    (void)p.colorAttachment(x, LoadOp::Load);
    p.sideEffect();
    expectRejected(g, Rule::NeverWritten, {"'blend onto nothing'", "'target'"});
}

TEST(CompileRules, FormatNotValidForUsageOnDevice) {
    OfflineDeviceCaps noStorage;
    noStorage.removeFeatures(VK_FORMAT_R16G16_UINT, VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT);
    RenderGraph g;
    ImageRef x = color(g, "interpolation source", VK_FORMAT_R16G16_UINT);
    auto p = g.addPass("refine samples", PassType::Compute);
    (void)p.storageWrite(x);
    p.sideEffect();
    expectRejected(g, Rule::FormatUnsupported,
                   {"'refine samples'", "'interpolation source'", "R16G16_UINT", "storage"},
                   noStorage);
}

TEST(CompileRules, MissingD24S8IsReportedAndAlternativeChosen) {
    OfflineDeviceCaps noD24(false);
    RenderGraph g;
    ImageRef ds = g.createImage("stencil", ImageDesc::absolute(VK_FORMAT_D24_UNORM_S8_UINT, 8, 8));
    auto p = g.addPass("mark", PassType::Graphics);
    (void)p.stencilWrite(ds, LoadOp::Clear);
    p.sideEffect();
    expectRejected(g, Rule::FormatUnsupported, {"'mark'", "D24_UNORM_S8_UINT"}, noD24);
    EXPECT_EQ(firstSupported(noD24, {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT},
                             VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT),
              VK_FORMAT_D32_SFLOAT_S8_UINT);
}

TEST(CompileRules, ImportedImageWithoutTheUsage) {
    RenderGraph g;
    ImageRef engine =
        g.importImage("engine color", graph_test::importedColor(kSize, VK_IMAGE_USAGE_SAMPLED_BIT));
    auto p = g.addPass("composite", PassType::Compute);
    (void)p.storageWrite(engine);
    expectRejected(g, Rule::UsageNotDeclared, {"'composite'", "'engine color'", "storage"});
}

TEST(CompileRules, AttachmentExtentsDiffer) {
    RenderGraph g;
    ImageRef c = color(g, "color");
    ImageRef ds =
        g.createImage("small stencil", ImageDesc::absolute(VK_FORMAT_D32_SFLOAT_S8_UINT, 32, 32));
    auto p = g.addPass("draw", PassType::Graphics);
    (void)p.colorAttachment(c, LoadOp::Clear);
    (void)p.stencilWrite(ds, LoadOp::Clear);
    p.sideEffect();
    expectRejected(g, Rule::ExtentMismatch,
                   {"'draw'", "'color'", "64x32", "'small stencil'", "32x32"});
}

TEST(CompileRules, CycleIsNamed) {
    RenderGraph g;
    ImageRef x = color(g, "x");
    ImageRef y = color(g, "y");
    // "a" reads y@1, written by "b"; "b" reads x@1, written by "a".
    auto a = g.addPass("a", PassType::Compute);
    a.sampled(ImageRef{y.graph, y.id, 1});
    (void)a.storageWrite(x);
    a.sideEffect();
    auto b = g.addPass("b", PassType::Compute);
    b.sampled(ImageRef{x.graph, x.id, 1});
    (void)b.storageWrite(y);
    expectRejected(g, Rule::Cycle, {"'a'", "'b'", "->"});
}

TEST(CompileRules, TwoWritersOfTheSameVersionAreUnordered) {
    RenderGraph g;
    ImageRef x = color(g, "shared target");
    auto a = g.addPass("first writer", PassType::Compute);
    (void)a.storageWrite(x);
    a.sideEffect();
    auto b = g.addPass("second writer", PassType::Compute);
    (void)b.storageWrite(x);  // should have used the version "first writer" returned
    b.sideEffect();
    expectRejected(g, Rule::UnorderedWriters,
                   {"'first writer'", "'second writer'", "'shared target'", "version 0"});
}

TEST(CompileRules, StencilTestOnFormatWithoutStencil) {
    RenderGraph g;
    ImageRef c = color(g, "color");
    ImageRef d = g.createImage(
        "depth only", ImageDesc::absolute(VK_FORMAT_D32_SFLOAT, kSize.width, kSize.height));
    auto w = g.addPass("write depth", PassType::Graphics);
    d = w.depthWrite(d, LoadOp::Clear);
    auto p = g.addPass("stencil tested draw", PassType::Graphics);
    p.stencilTest(d);
    (void)p.colorAttachment(c, LoadOp::Clear);
    p.sideEffect();
    expectRejected(g, Rule::StencilWithoutStencilFormat,
                   {"'stencil tested draw'", "'depth only'", "D32_SFLOAT", "no stencil"});
}

TEST(CompileRules, DepthUseOnColorFormat) {
    RenderGraph g;
    ImageRef c = color(g, "not depth");
    auto p = g.addPass("depth pass", PassType::Graphics);
    (void)p.depthWrite(c, LoadOp::Clear);
    p.sideEffect();
    expectRejected(g, Rule::DepthWithoutDepthFormat, {"'depth pass'", "'not depth'"});
}

TEST(CompileRules, ImportWithoutFinalLayout) {
    RenderGraph g;
    auto desc = graph_test::importedColor(kSize, VK_IMAGE_USAGE_SAMPLED_BIT);
    desc.finalLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    g.importImage("engine depth", desc);
    expectRejected(g, Rule::ImportWithoutFinalLayout, {"'engine depth'", "final"});
}

TEST(CompileRules, SampledAndColorAttachmentInOnePassConflict) {
    RenderGraph g;
    ImageRef c = color(g, "feedback");
    auto w = g.addPass("init", PassType::Compute);
    c = w.storageWrite(c);
    auto p = g.addPass("loop", PassType::Graphics);
    p.sampled(c);
    (void)p.colorAttachment(c, LoadOp::Load);
    p.sideEffect();
    expectRejected(g, Rule::ConflictingUses,
                   {"'loop'", "'feedback'", "sampled", "color attachment"});
}

TEST(CompileRules, DepthSampledWhileStencilWrittenIsAllowed) {
    RenderGraph g;
    ImageRef ds = g.createImage("ds", ImageDesc::absolute(VK_FORMAT_D32_SFLOAT_S8_UINT, 8, 8));
    auto w = g.addPass("depth", PassType::Graphics);
    const ImageRef fresh = ds;
    ds = w.depthWrite(fresh, LoadOp::Clear);
    EXPECT_EQ(w.stencilWrite(fresh, LoadOp::Clear).version, ds.version);  // one new version
    auto p = g.addPass("mark", PassType::Graphics);
    p.sampled(ds, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    (void)p.stencilWrite(ds, LoadOp::Load);
    p.sideEffect();
    const CompiledGraph c = compile(g, graph_test::caps());
    const auto& states = c.passes[1].states;
    ASSERT_EQ(states.size(), 1u);
    EXPECT_EQ(states[0].layout, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL);
}

TEST(CompileRules, AttachmentInComputePass) {
    RenderGraph g;
    ImageRef c = color(g, "color");
    auto p = g.addPass("compute with attachment", PassType::Compute);
    (void)p.colorAttachment(c, LoadOp::Clear);
    p.sideEffect();
    expectRejected(g, Rule::WrongPassType, {"'compute with attachment'", "'color'"});
}

TEST(CompileRules, GraphicsPassWithoutAttachments) {
    RenderGraph g;
    ImageRef c = color(g, "color");
    auto w = g.addPass("init", PassType::Compute);
    c = w.storageWrite(c);
    auto p = g.addPass("no targets", PassType::Graphics);
    p.sampled(c);
    p.sideEffect();
    expectRejected(g, Rule::WrongPassType, {"'no targets'", "without attachments"});
}

// A graphics pass whose fragments only write storage images declares the area it renders over;
// with attachments it renders over theirs, so it may not declare one too.
TEST(CompileRules, RenderAreaOnlyWithoutAttachments) {
    {
        RenderGraph g;
        ImageRef c = color(g, "color");
        auto p = g.addPass("storage only", PassType::Graphics);
        c = p.storageWrite(c);
        p.renderArea({16, 16});
        p.sideEffect();
        const rg::OfflineDeviceCaps caps;
        const rg::CompiledGraph compiled = rg::compile(g, caps);
        ASSERT_EQ(compiled.passes.size(), 1u);
        EXPECT_EQ(compiled.passes[0].renderExtent.width, 16u);
        EXPECT_EQ(compiled.passes[0].renderExtent.height, 16u);
    }
    {
        RenderGraph g;
        ImageRef c = color(g, "color");
        auto p = g.addPass("both", PassType::Graphics);
        c = p.colorAttachment(c, LoadOp::Clear);
        p.renderArea({16, 16});
        p.sideEffect();
        expectRejected(g, Rule::ExtentMismatch, {"'both'", "render area and has attachments"});
    }
    {
        RenderGraph g;
        ImageRef c = color(g, "color");
        auto p = g.addPass("compute area", PassType::Compute);
        c = p.storageWrite(c);
        p.renderArea({16, 16});
        p.sideEffect();
        expectRejected(g, Rule::WrongPassType, {"'compute area'", "not a graphics pass"});
    }
}

TEST(CompileRules, BadDescriptions) {
    {
        RenderGraph g;
        g.createImage("dup", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 4, 4));
        g.createImage("dup", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 4, 4));
        expectRejected(g, Rule::BadDescription, {"'dup'", "twice"});
    }
    {
        RenderGraph g;
        g.createImage("empty", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 0, 4));
        expectRejected(g, Rule::BadDescription, {"'empty'", "0x4"});
    }
    {
        RenderGraph g;
        g.createImage("relative", ImageDesc::screen(VK_FORMAT_R32_SFLOAT));
        expectRejected(g, Rule::BadDescription, {"'relative'", "screen extent"});
    }
    {
        RenderGraph g;
        g.createBuffer("nothing", BufferDesc{0});
        expectRejected(g, Rule::BadDescription, {"'nothing'", "size 0"});
    }
}

TEST(CompileRules, BufferUsedAsImage) {
    RenderGraph g;
    BufferRef b = g.createBuffer("params", BufferDesc{256});
    auto p = g.addPass("confused", PassType::Compute);
    p.sampled(ImageRef{b.graph, b.id, 0});
    p.sideEffect();
    expectRejected(g, Rule::UnknownResource, {"'confused'", "'params'", "buffer"});
}

TEST(CompileRules, UpdateImportRefusesIncompatibleChange) {
    RenderGraph g;
    auto desc = graph_test::importedColor(kSize, VK_IMAGE_USAGE_SAMPLED_BIT);
    ImageRef engine = g.importImage("engine color", desc);
    desc.extent = {128, 128};
    try {
        g.updateImport(engine, desc);
        ADD_FAILURE() << "extent change accepted";
    } catch (const GraphError& e) {
        EXPECT_EQ(e.rule(), Rule::ImportChanged);
        EXPECT_NE(std::string(e.what()).find("'engine color'"), std::string::npos);
    }
    EXPECT_EQ(g.resource(engine.id).importedImage.extent.width, kSize.width);  // unchanged
}
