// A pass reaches only what it declared: PassContext refuses a view or a layout of any other
// resource, naming the pass and the resource, so an undeclared read cannot slip past the barriers
// the runtime derives from the declarations.
#include <functional>
#include <string>

#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/vk_error.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

class PassContextGpu : public GpuTest {
  protected:
    // A graph whose "snoop" pass declares a sampled read of "declared" and runs `probe` on a
    // context for it; "undeclared" is written by the same pass that writes "declared", so it is
    // alive and allocated, just not this pass's to touch.
    void recordSnoop(const std::function<void(rg::PassContext&, rg::ImageRef declared,
                                              rg::ImageRef undeclared)>& probe) {
        rg::RenderGraph g;
        const rg::ImageDesc desc = rg::ImageDesc::absolute(VK_FORMAT_R8G8B8A8_UNORM, 4, 4);
        rg::ImageRef declared = g.createImage("declared", desc);
        rg::ImageRef undeclared = g.createImage("undeclared", desc);
        {
            auto p = g.addPass("clear", rg::PassType::Transfer);
            declared = p.transferDst(declared);
            undeclared = p.transferDst(undeclared);
            const rg::ImageRef a = declared, b = undeclared;
            p.execute([a, b](rg::PassContext& ctx) {
                const VkClearColorValue black{};
                const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
                for (rg::ImageRef r : {a, b})
                    vkCmdClearColorImage(ctx.cmd(), ctx.image(r), ctx.layout(r), &black, 1, &range);
            });
        }
        {
            auto p = g.addPass("snoop", rg::PassType::Compute);
            p.sampled(declared);
            p.sideEffect();
            const rg::ImageRef a = declared, b = undeclared;
            p.execute([a, b, probe](rg::PassContext& ctx) { probe(ctx, a, b); });
        }
        const rg::VulkanDeviceCaps caps(dev());
        rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));
        exec.rehearse();
    }
};

TEST_F(PassContextGpu, ADeclaredImageHasAViewAndALayout) {
    recordSnoop([](rg::PassContext& ctx, rg::ImageRef declared, rg::ImageRef) {
        EXPECT_NE(ctx.view(declared), VK_NULL_HANDLE);
        EXPECT_EQ(ctx.layout(declared), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    });
}

TEST_F(PassContextGpu, AViewOfAnUndeclaredImageIsRefused) {
    std::string message;
    try {
        recordSnoop([](rg::PassContext& ctx, rg::ImageRef, rg::ImageRef undeclared) {
            ctx.view(undeclared);
        });
    } catch (const rg::VulkanError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("'snoop'"), std::string::npos) << message;
    EXPECT_NE(message.find("'undeclared'"), std::string::npos) << message;
    EXPECT_NE(message.find("did not declare"), std::string::npos) << message;
}

TEST_F(PassContextGpu, ALayoutOfAnUndeclaredImageIsRefused) {
    std::string message;
    try {
        recordSnoop([](rg::PassContext& ctx, rg::ImageRef, rg::ImageRef undeclared) {
            ctx.layout(undeclared);
        });
    } catch (const rg::VulkanError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("'snoop'"), std::string::npos) << message;
    EXPECT_NE(message.find("'undeclared'"), std::string::npos) << message;
}
