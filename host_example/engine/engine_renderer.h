#pragma once
// The host example's engine: a shadow-map pass and forward shading of a glTF scene (its own render
// graph), then the plugin's light scattering composited into the HDR color, in one command buffer.
// What an engine of any size does to integrate the plugin, at a small scale.
#include <memory>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "cube_shadow_map.h"
#include "gpu_image.h"
#include "gpu_mesh.h"
#include "rendergraph/compile.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "scene/scene.h"

namespace host {

struct RenderOptions {
    lightscatter::Method method = lightscatter::Method::Epipolar;
    lightscatter::Profile profile = lightscatter::Profile::Balanced;
    lightscatter::Settings custom;
    double timeSeconds = 0.0;  // FrameDescription::timeSeconds: scrolls the planes method's noise
    bool countSteps = false;   // DebugOptions::countSteps: epipolar's ray-march steps in the report
    bool resetHistory = false;  // FrameDescription::resetHistory: a camera cut
    // With froxels: the frame's grid in an engine image (FrameDescription::volumeOut), read back
    // by render() into FrameOutput::volume.
    bool exportVolume = false;
    // FrameDescription::inscatterOut: Lin alone, read back into FrameOutput::inscatter. An engine
    // that composites into its color leaves it out, and so do `render` without --inscatter and
    // `view`: the plugin then writes no screen-sized RGBA32F image (what that costs:
    // docs/epipolar.md, "Where the unwarp's time goes").
    bool linOut = true;
};

struct FrameOutput {
    std::vector<float> color;      // RGBA, linear HDR radiance after compositing
    std::vector<float> inscatter;  // RGBA, Lin alone (empty without RenderOptions::linOut)
    // RenderOptions::exportVolume: the froxel grid, RGBA per texel (x fastest, then y, then the
    // slice), laid out as `volumeLayout` says.
    std::vector<float> volume;
    lightscatter::FroxelVolume volumeLayout;
    lightscatter::FrameReport plugin;
    rg::FrameTimings engine;
};

class EngineRenderer {
  public:
    // `sizeOrigin` names where `size` came from in messages about what the device cannot hold at
    // it ("--size", a benchmark's "size").
    EngineRenderer(const rg::Device& device, SceneDesc scene, const MeshData& mesh, VkExtent2D size,
                   std::string sizeOrigin = "--size");
    ~EngineRenderer();
    EngineRenderer(const EngineRenderer&) = delete;
    EngineRenderer& operator=(const EngineRenderer&) = delete;

    // Renders one frame on the renderer's own command buffer, waits, and reads the images back.
    FrameOutput render(const RenderOptions& options);

    // For a window: records the engine passes and the plugin into `cmd`; the HDR color is left in
    // GENERAL layout, readable by a later pass (finalStages/Access below).
    void record(VkCommandBuffer cmd, const RenderOptions& options,
                VkPipelineStageFlags2 finalStages, VkAccessFlags2 finalAccess,
                VkImageLayout finalLayout = VK_IMAGE_LAYOUT_GENERAL);
    FrameOutput timings();  // after the engine waited for a recorded frame
    // Throws SceneError, in the scene's terms, when the plugin would refuse the frame `options`
    // make; renders nothing.
    void check(const RenderOptions& options) const;

    void resize(VkExtent2D size);
    VkExtent2D size() const { return size_; }
    SceneDesc& scene() { return scene_; }
    const GpuImage& color() const { return *color_; }
    lightscatter::Plugin& plugin() { return *plugin_; }
    const Bounds& bounds() const { return bounds_; }
    size_t occluderCount() const { return occluders_.size(); }  // seed 004's boxes, one a primitive

  private:
    std::vector<lightscatter::Occluder> occluders_;
    struct Pipelines;
    // One light of the scene ("light", or each of "lights"), the first one included: its shadow
    // map, if it has one. A sun or spot with shadowMapSize > 0 gets a 2D map drawn in the engine's
    // graph; a point light with one gets a cube map drawn before it. Each light's direct light is
    // shaded by a pass of its own: the first clears and writes depth, the others add onto it.
    struct LightTargets {
        std::unique_ptr<GpuImage> shadowMap;
        std::unique_ptr<CubeShadowMap> cubeShadow;
        std::unique_ptr<GpuImage> cookie;  // the light's color image (R8G8B8A8_SRGB), if it has one
    };
    void uploadCookie(const Texture& texture, GpuImage& image) const;
    void createTargets();
    void createScreenTargets();  // depth, color, Lin and their readbacks, at size_
    void layOutTargets();        // the first layouts of the targets just made
    void buildGraph();
    void recordCubeShadows(VkCommandBuffer cmd);
    // Light i as the plugin takes it: the light with its shadow map's matrices, and the map.
    lightscatter::LightInput pluginLight(size_t i, float aspect) const;
    lightscatter::FrameDescription describe(const RenderOptions& options,
                                            VkPipelineStageFlags2 finalStages,
                                            VkAccessFlags2 finalAccess) const;

    const rg::Device& device_;
    SceneDesc scene_;
    Bounds bounds_;
    std::vector<Bounds> partBounds_;  // one per draw: what the sun's shadow box is fitted to
    VkExtent2D size_;
    std::string sizeOrigin_;
    std::unique_ptr<GpuMesh> mesh_;
    std::unique_ptr<GpuImage> depth_, color_, inscatter_;
    std::vector<LightTargets> lights_;  // one per scene light, in the scene's order
    std::unique_ptr<rg::HostBuffer> colorReadback_, linReadback_;  // sized with the targets
    // RenderOptions::exportVolume's image (GENERAL between frames) and its read-back, made at the
    // grid's size on first use and again when the size changes.
    void prepareVolume(const RenderOptions& options);
    std::unique_ptr<GpuImage> volume_;
    std::unique_ptr<rg::HostBuffer> volumeReadback_;
    std::unique_ptr<lightscatter::Plugin> plugin_;
    std::shared_ptr<Pipelines> pipelines_;
    std::unique_ptr<rg::RenderGraph> graph_;
    std::unique_ptr<rg::GraphExecutor> executor_;
    rg::ImageRef colorRef_, depthRef_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace host
