// Ordering, culling and lifetimes on graphs whose answer is known.
#include "graph_test_util.h"

using namespace rg;
using graph_test::positionOf;

namespace {

ImageRef img(RenderGraph& g, const char* name) {
    return g.createImage(name, ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 16, 16));
}

std::vector<std::string> orderNames(const RenderGraph& g, const CompiledGraph& c) {
    std::vector<std::string> names;
    for (const auto& p : c.passes) names.push_back(g.passes()[p.pass].name);
    return names;
}

}  // namespace

TEST(Schedule, FollowsDataNotDeclarationOrder) {
    RenderGraph g;
    ImageRef x = img(g, "x");
    // The consumer is declared first and names the version the producer will make.
    auto consumer = g.addPass("consumer", PassType::Compute);
    consumer.sampled(ImageRef{x.graph, x.id, 1});
    consumer.sideEffect();
    auto producer = g.addPass("producer", PassType::Compute);
    EXPECT_EQ(producer.storageWrite(x).version, 1u);
    const CompiledGraph c = compile(g, graph_test::caps());
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"producer", "consumer"}));
}

TEST(Schedule, ReaderRunsBeforeTheNextWriter) {
    RenderGraph g;
    ImageRef x = img(g, "x");
    ImageRef out1 = img(g, "out1");
    auto w1 = g.addPass("w1", PassType::Compute);
    const ImageRef x1 = w1.storageWrite(x);
    // w2 overwrites x1 and is declared before the reader of x1.
    auto w2 = g.addPass("w2", PassType::Compute);
    const ImageRef x2 = w2.storageReadWrite(x1);
    g.markOutput(x2);
    auto r = g.addPass("reader of x1", PassType::Compute);
    r.sampled(x1);
    g.markOutput(r.storageWrite(out1));
    const CompiledGraph c = compile(g, graph_test::caps());
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"w1", "reader of x1", "w2"}));
}

TEST(Schedule, CullsPassesNobodyNeeds) {
    RenderGraph g;
    ImageRef a = img(g, "a");
    ImageRef b = img(g, "b");
    ImageRef unused = img(g, "unused");
    ImageRef kept = img(g, "kept");
    auto pa = g.addPass("make a", PassType::Compute);
    a = pa.storageWrite(a);
    auto pb = g.addPass("a to b (only feeds a dead pass)", PassType::Compute);
    pb.sampled(a);
    b = pb.storageWrite(b);
    auto dead = g.addPass("b to unused", PassType::Compute);
    dead.sampled(b);
    (void)dead.storageWrite(unused);
    auto live = g.addPass("a to kept", PassType::Compute);
    live.sampled(a);
    kept = live.storageWrite(kept);
    g.markOutput(kept);
    const CompiledGraph c = compile(g, graph_test::caps());
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"make a", "a to kept"}));
    ASSERT_EQ(c.culled.size(), 2u);
    EXPECT_FALSE(c.resources[b.id].used);
    EXPECT_FALSE(c.resources[unused.id].used);
    EXPECT_TRUE(c.resources[kept.id].used);
}

TEST(Schedule, WritesToImportsAndSideEffectsAreKept) {
    RenderGraph g;
    ImageRef engine =
        g.importImage("engine", graph_test::importedColor({16, 16}, VK_IMAGE_USAGE_STORAGE_BIT));
    auto p = g.addPass("write engine image", PassType::Compute);
    (void)p.storageWrite(engine);
    auto s = g.addPass("side effect", PassType::Compute);
    s.sideEffect();
    auto n = g.addPass("nothing", PassType::Compute);
    (void)n;
    const CompiledGraph c = compile(g, graph_test::caps());
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"write engine image", "side effect"}));
    EXPECT_EQ(c.culled.size(), 1u);
}

TEST(Schedule, CulledWriterDoesNotUnorderAReaderAndALaterWriter) {
    RenderGraph g;
    ImageRef x = img(g, "x");
    ImageRef y = img(g, "y");
    auto w1 = g.addPass("w1", PassType::Compute);
    const ImageRef x1 = w1.storageWrite(x);
    auto w2 = g.addPass("w2 (culled)", PassType::Compute);
    const ImageRef x2 = w2.storageWrite(x1);
    auto w3 = g.addPass("w3 overwrites", PassType::Compute);
    g.markOutput(w3.storageWrite(x2));
    auto r = g.addPass("reader of x1", PassType::Compute);
    r.sampled(x1);
    g.markOutput(r.storageWrite(y));
    const CompiledGraph c = compile(g, graph_test::caps());
    const auto names = orderNames(g, c);
    EXPECT_EQ(names, (std::vector<std::string>{"w1", "reader of x1", "w3 overwrites"}));
}

TEST(Schedule, Lifetimes) {
    RenderGraph g;
    ImageRef t[4] = {img(g, "t0"), img(g, "t1"), img(g, "t2"), img(g, "t3")};
    ImageRef prev = t[0];
    {
        auto p = g.addPass("p0", PassType::Compute);
        prev = p.storageWrite(prev);
    }
    for (int i = 1; i < 4; ++i) {
        auto p = g.addPass("p" + std::to_string(i), PassType::Compute);
        p.sampled(prev);
        prev = p.storageWrite(t[i]);
    }
    g.markOutput(prev);
    const CompiledGraph c = compile(g, graph_test::caps());
    for (uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(c.resources[t[i].id].firstPass, i);
        EXPECT_EQ(c.resources[t[i].id].lastPass, i == 3 ? 3u : i + 1);
    }
    EXPECT_EQ(positionOf(c, g, "p2"), 2u);
}

TEST(Schedule, StencilTestOrdersAfterStencilWrite) {
    RenderGraph g;
    ImageRef ds =
        g.createImage("stencil", ImageDesc::absolute(VK_FORMAT_D32_SFLOAT_S8_UINT, 16, 16));
    ImageRef color =
        g.createImage("color", ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 16, 16));
    ImageRef marked{ds.graph, ds.id, 1};
    // Declared first: the test of the marks the next pass makes.
    auto use = g.addPass("stencil-tested draw", PassType::Graphics);
    use.stencilTest(marked);
    g.markOutput(use.colorAttachment(color, LoadOp::Clear));
    auto mark = g.addPass("mark stencil", PassType::Graphics);
    EXPECT_EQ(mark.stencilWrite(ds, LoadOp::Clear, 0).version, 1u);
    const CompiledGraph c = compile(g, graph_test::caps());
    EXPECT_EQ(orderNames(g, c), (std::vector<std::string>{"mark stencil", "stencil-tested draw"}));
}
