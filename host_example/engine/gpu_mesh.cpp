#include "gpu_mesh.h"

#include <algorithm>
#include <cstring>

#include "rendergraph/device_memory.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/vk_error.h"

namespace host {

VkBuffer GpuMesh::makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name,
                             VkDeviceMemory& memory) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<VkDeviceSize>(size, 4);
    info.usage = usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    const rg::BoundBuffer b = rg::createBoundBuffer(
        device_, info, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name, "buffer '" + name + "'");
    memory = b.memory;
    return b.buffer;
}

GpuMesh::GpuMesh(const rg::Device& device, const MeshData& mesh) : device_(device) {
    // Every texture against the device's limits before anything is allocated.
    for (const Texture& t : mesh.textures)
        rg::checkImageLimits(device, {t.width, t.height}, 1, "texture '" + t.name + "'");
    try {
        upload(mesh);
    } catch (...) {
        release();  // a constructor that throws runs no destructor
        throw;
    }
}

void GpuMesh::upload(const MeshData& mesh) {
    const rg::Device& device = device_;
    const VkDeviceSize vBytes = mesh.vertices.size() * sizeof(Vertex);
    const VkDeviceSize iBytes = mesh.indices.size() * sizeof(uint32_t);
    vertexBuffer_ =
        makeBuffer(vBytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "scene vertices", vertexMemory_);
    indexBuffer_ =
        makeBuffer(iBytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "scene indices", indexMemory_);

    // Textures, plus a white one for materials without. By reference: the pixels are held by the
    // mesh and, for the upload, by the staging buffer, never copied a third time (a 16384^2
    // texture cost 1 GiB more here).
    const Texture whiteTexture{"white", 1, 1, {255, 255, 255, 255}};
    std::vector<const Texture*> textures;
    for (const Texture& t : mesh.textures) textures.push_back(&t);
    textures.push_back(&whiteTexture);
    VkDeviceSize staged = vBytes + iBytes;
    for (const Texture* t : textures) staged += t->rgba.size();
    rg::HostBuffer staging(device, std::max<VkDeviceSize>(staged, 4),
                           VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "scene upload");
    auto* bytes = static_cast<uint8_t*>(staging.data());
    if (vBytes) std::memcpy(bytes, mesh.vertices.data(), vBytes);
    if (iBytes) std::memcpy(bytes + vBytes, mesh.indices.data(), iBytes);
    VkDeviceSize offset = vBytes + iBytes;
    std::vector<VkDeviceSize> textureOffsets;
    for (const Texture* t : textures) {
        textureOffsets.push_back(offset);
        std::memcpy(bytes + offset, t->rgba.data(), t->rgba.size());
        offset += t->rgba.size();
        textures_.push_back(std::make_unique<GpuImage>(
            device, VK_FORMAT_R8G8B8A8_SRGB, VkExtent2D{t->width, t->height},
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "texture " + t->name));
    }

    device.submitAndWait([&](VkCommandBuffer cmd) {
        if (vBytes) {
            VkBufferCopy c{0, 0, vBytes};
            vkCmdCopyBuffer(cmd, staging.buffer(), vertexBuffer_, 1, &c);
        }
        if (iBytes) {
            VkBufferCopy c{vBytes, 0, iBytes};
            vkCmdCopyBuffer(cmd, staging.buffer(), indexBuffer_, 1, &c);
        }
        auto barrier = [&](VkImage img, VkImageLayout from, VkImageLayout to,
                           VkPipelineStageFlags2 src, VkAccessFlags2 srcAccess,
                           VkPipelineStageFlags2 dst, VkAccessFlags2 dstAccess) {
            VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
            b.srcStageMask = src;
            b.srcAccessMask = srcAccess;
            b.dstStageMask = dst;
            b.dstAccessMask = dstAccess;
            b.oldLayout = from;
            b.newLayout = to;
            b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.image = img;
            b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dep.imageMemoryBarrierCount = 1;
            dep.pImageMemoryBarriers = &b;
            vkCmdPipelineBarrier2(cmd, &dep);
        };
        for (size_t i = 0; i < textures.size(); ++i) {
            const VkImage img = textures_[i]->image();
            barrier(img, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT);
            VkBufferImageCopy region{};
            region.bufferOffset = textureOffsets[i];
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {textures[i]->width, textures[i]->height, 1};
            vkCmdCopyBufferToImage(cmd, staging.buffer(), img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   1, &region);
            barrier(img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        }
        // Geometry is read by every later frame's draws.
        VkMemoryBarrier2 m{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        m.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        m.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        m.dstStageMask =
            VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT;
        m.dstAccessMask = VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT;
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &m;
        vkCmdPipelineBarrier2(cmd, &dep);
    });

    for (size_t i = 0; i < textures_.size(); ++i) {
        VkImageViewCreateInfo v{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        v.image = textures_[i]->image();
        v.viewType = VK_IMAGE_VIEW_TYPE_2D;
        v.format = VK_FORMAT_R8G8B8A8_SRGB;
        v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view;
        RG_VK(vkCreateImageView(device.device(), &v, nullptr, &view));
        device.setName(view, VK_OBJECT_TYPE_IMAGE_VIEW, "texture " + textures[i]->name + " view");
        views_.push_back(view);
    }
    const VkImageView white = views_.back();
    for (const Primitive& p : mesh.primitives) {
        Draw d{p.firstIndex, p.indexCount, glm::vec4(1.0f), white};
        if (p.material >= 0 && static_cast<size_t>(p.material) < mesh.materials.size()) {
            const Material& m = mesh.materials[static_cast<size_t>(p.material)];
            d.baseColor = m.baseColorFactor;
            if (m.baseColorTexture >= 0 &&
                static_cast<size_t>(m.baseColorTexture) < mesh.textures.size())
                d.texture = views_[static_cast<size_t>(m.baseColorTexture)];
        }
        draws_.push_back(d);
    }
}

GpuMesh::~GpuMesh() {
    release();
}

void GpuMesh::release() {
    const VkDevice dev = device_.device();
    for (VkImageView v : views_) vkDestroyImageView(dev, v, nullptr);
    views_.clear();
    textures_.clear();
    vkDestroyBuffer(dev, vertexBuffer_, nullptr);
    vkDestroyBuffer(dev, indexBuffer_, nullptr);
    vkFreeMemory(dev, vertexMemory_, nullptr);
    vkFreeMemory(dev, indexMemory_, nullptr);
    vertexBuffer_ = indexBuffer_ = VK_NULL_HANDLE;
    vertexMemory_ = indexMemory_ = VK_NULL_HANDLE;
}

}  // namespace host
