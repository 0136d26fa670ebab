#pragma once
// A point light's cube shadow map: a six-layer depth image (cube-compatible), one depth view per
// face, and the six 90-degree depth passes that draw it. Recorded outside the engine's render
// graph: the graph's runtime renders into whole images, and a face is one layer of this one.
#include <array>
#include <functional>
#include <string>

#include <glm/mat4x4.hpp>

#include "gpu_image.h"

namespace host {

class CubeShadowMap {
  public:
    CubeShadowMap(const rg::Device& device, uint32_t size, const std::string& name);
    ~CubeShadowMap();
    CubeShadowMap(const CubeShadowMap&) = delete;
    CubeShadowMap& operator=(const CubeShadowMap&) = delete;

    const GpuImage& image() const { return image_; }

    // Clears and draws the six faces in Vulkan's layer order; `draw` binds its pipeline and draws
    // the scene with the face's world -> clip matrix inside each face's rendering. Leaves every
    // layer in DEPTH_ATTACHMENT_OPTIMAL after LATE_FRAGMENT_TESTS writes (what the plugin is told).
    void record(VkCommandBuffer cmd, const std::array<glm::mat4, 6>& faces,
                const std::function<void(VkCommandBuffer, const glm::mat4&)>& draw) const;

  private:
    void destroyViews();

    const rg::Device& device_;
    std::string name_;
    GpuImage image_;
    std::array<VkImageView, 6> faceViews_{};
};

}  // namespace host
