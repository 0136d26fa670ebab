#pragma once
// A scene's triangles and textures on the device: one vertex and one index buffer, an sRGB image
// per texture (and a white one for untextured materials), uploaded once and left ready for drawing.
#include <memory>
#include <vector>

#include "gpu_image.h"
#include "rendergraph/device.h"
#include "scene/scene.h"

namespace host {

class GpuMesh {
  public:
    GpuMesh(const rg::Device& device, const MeshData& mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    struct Draw {
        uint32_t firstIndex, indexCount;
        glm::vec4 baseColor;
        VkImageView texture;
    };
    const std::vector<Draw>& draws() const { return draws_; }
    VkBuffer vertices() const { return vertexBuffer_; }
    VkBuffer indices() const { return indexBuffer_; }

  private:
    void upload(const MeshData& mesh);
    void release();  // destroys what was made, for the destructor and a failed constructor
    VkBuffer makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name,
                        VkDeviceMemory& memory);
    const rg::Device& device_;
    VkBuffer vertexBuffer_ = VK_NULL_HANDLE, indexBuffer_ = VK_NULL_HANDLE;
    VkDeviceMemory vertexMemory_ = VK_NULL_HANDLE, indexMemory_ = VK_NULL_HANDLE;
    std::vector<std::unique_ptr<GpuImage>> textures_;
    std::vector<VkImageView> views_;
    std::vector<Draw> draws_;
};

}  // namespace host
