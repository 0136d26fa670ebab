#pragma once
// Engine-side images for plugin tests: created, filled from the host, handed to the plugin as
// ImageInputs, and read back.
#include <cstdint>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "rendergraph/device.h"
#include "rendergraph/owned_image.h"

namespace plugin_test {

class TestImage {
  public:
    TestImage(const rg::Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
              VkImageLayout restingLayout, const std::string& name);
    TestImage(const TestImage&) = delete;
    TestImage& operator=(const TestImage&) = delete;

    // Uploads tightly packed texels (float per depth texel, 4 floats per RGBA32F texel).
    void upload(const std::vector<float>& texels);
    // Texels as the format packs them, tightly (rg::texelBytes each), either way.
    void uploadBytes(const std::vector<uint8_t>& bytes);
    std::vector<uint8_t> downloadBytes();
    std::vector<float> download();  // RGBA32F, RGBA16F or R32/D32 as floats
    void clear(float value);        // color images
    lightscatter::ImageInput input() const;
    VkImage image() const { return image_.image(); }

  private:
    void transition(VkCommandBuffer cmd, VkImageLayout from, VkImageLayout to) const;
    const rg::Device& device_;
    VkFormat format_;
    VkExtent2D extent_;
    VkImageUsageFlags usage_;
    VkImageLayout resting_;
    rg::OwnedImage image_;
};

}  // namespace plugin_test
