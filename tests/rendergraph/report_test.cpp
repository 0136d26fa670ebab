// Reports name every pass and resource with its placement; DOT marks culled passes.
#include "rendergraph/report.h"
#include "graph_test_util.h"

using namespace rg;

TEST(Report, JsonTextAndDotDescribeTheCompiledGraph) {
    RenderGraph g;
    ImageRef a = g.createImage("alpha", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    ImageRef b = g.createImage("beta", ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, 8, 8));
    auto p = g.addPass("make alpha", PassType::Compute);
    a = p.storageWrite(a);
    g.markOutput(a);
    auto dead = g.addPass("unused beta", PassType::Compute);
    (void)dead.storageWrite(b);
    const CompiledGraph c = compile(g, graph_test::caps());

    const auto j = reportJson(g, c);
    ASSERT_EQ(j["passes"].size(), 1u);
    EXPECT_EQ(j["passes"][0]["name"], "make alpha");
    EXPECT_EQ(j["culled"][0], "unused beta");
    EXPECT_EQ(j["resources"][0]["format"], "R32_SFLOAT");
    EXPECT_EQ(j["resources"][0]["offset"], 0);
    EXPECT_EQ(j["resources"][1]["used"], false);
    EXPECT_EQ(j["totals"]["aliasedBytes"], c.aliasedBytes);
    EXPECT_EQ(j["memorySizes"], "estimate");

    const std::string text = reportText(g, c);
    EXPECT_NE(text.find("unused beta (culled)"), std::string::npos);
    EXPECT_NE(text.find("estimated sizes"), std::string::npos);

    const std::string dot = reportDot(g, c);
    EXPECT_NE(dot.find("digraph"), std::string::npos);
    EXPECT_NE(dot.find("\"make alpha\\n#0 compute\""), std::string::npos);
    EXPECT_NE(dot.find("unused beta\\n(culled)"), std::string::npos);
}
