#pragma once
// A small graph that exercises the runtime end to end: a compute pass writes a test pattern, a
// stencil-only graphics pass marks a circle, two graphics passes copy the pattern and invert it
// where the stencil test passes, a compute pass blurs into 8-bit, a transfer pass reads it back. A
// debug pass nobody reads is declared too, and culled. The pattern image dies before the blur
// output is born, so the two share memory.
#include <cstdint>
#include <memory>
#include <vector>

#include "rendergraph/compile.h"
#include "rendergraph/device.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/render_graph.h"

namespace rg::demo {

struct TestPatternHandles {
    ImageRef pattern, mask, composed, display, luma;
    BufferRef readback;
};

struct TestPatternPipelines;  // built on first execution

// Declares the graph. `depthStencil` is the stencil format the device offers; `pipelines` may be
// null when the graph is only compiled.
TestPatternHandles declareTestPattern(RenderGraph& graph, VkExtent2D size, VkFormat depthStencil,
                                      const ImportedBuffer& readback,
                                      std::shared_ptr<TestPatternPipelines> pipelines);

// Renders the pattern on a device and returns RGBA8 pixels, row-major, top row first.
class TestPatternRenderer {
  public:
    TestPatternRenderer(const Device& device, VkExtent2D size);
    ~TestPatternRenderer();
    std::vector<uint8_t> render(FrameTimings* timings = nullptr);
    const RenderGraph& graph() const { return graph_; }
    const CompiledGraph& compiled() const { return executor_->compiled(); }
    VkFormat depthStencilFormat() const { return depthStencil_; }

  private:
    VkFormat depthStencil_;
    HostBuffer readback_;
    RenderGraph graph_;
    std::shared_ptr<TestPatternPipelines> pipelines_;
    std::unique_ptr<GraphExecutor> executor_;
};

}  // namespace rg::demo
